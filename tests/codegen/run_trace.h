// The trace of one run, for comparing generated and interpreted models.
#pragma once

#include <cstdint>
#include <memory>
#include <sstream>
#include <string>

#include "engines/engines.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/compiled_steps.h"
#include "engines/semantics/layout.h"

namespace smcbip::tests {

/// The whole output of run 0 of `model` on `engine` with `seed`, at most `limit` steps, then
/// its exit code and error (with its place in the model); then the same run's JSON-lines trace
/// (the optimised engine takes the compiled step path there, where a model has one) and exit
/// code. The multithread engine uses two
/// threads, firing atoms on them from `parallel_min_work` instructions of work.
inline std::string run_trace(const engines::Model& model, engines::EngineKind engine,
                             std::uint64_t seed, std::uint64_t limit,
                             std::size_t parallel_min_work = 1000) {
  engines::SimulateOptions options;
  options.engine = engine;
  options.threads = 2;
  options.parallel_min_work = parallel_min_work;
  options.seed = seed;
  options.limit = limit;
  std::ostringstream out;
  for (engines::TraceFormat format : {engines::TraceFormat::Text, engines::TraceFormat::Jsonl}) {
    options.trace = format;
    engines::Simulator simulator(model, options, engines::Externs::with_builtins());
    const engines::RunResult result = simulator.run(0, engines::RunStreams{out, out});
    out << "\nexit " << result.code << " after " << result.steps << " steps: " << result.message
        << " at " << result.where << "\n";
  }
  return out.str();
}

/// Calls `use(layout, code)` with the layout of `system` and the code `make_code` generated
/// for it; false when either cannot be made.
template <class Use>
bool with_generated_code(const bipc::ir::System& system,
                         const engines::CompiledModel::CodeFactory& make_code, Use use) {
  engines::Layout layout;
  if (!engines::build_layout(system, layout).empty()) return false;
  engines::StringPool strings;
  std::ostringstream out;
  engines::CallContext call{out, strings};
  engines::BoundFunctions functions;
  if (!engines::bind_functions(system, engines::Externs::with_builtins(), strings, functions)
           .empty()) {
    return false;
  }
  const std::unique_ptr<engines::ModelCode> code = make_code(system, functions, call, nullptr);
  use(layout, *code);
  return true;
}

/// Whether the code `make_code` generated for `system` has a compiled step path that covers it
/// (the optimised engine's runs above then take it).
inline bool has_compiled_steps(const bipc::ir::System& system,
                               const engines::CompiledModel::CodeFactory& make_code) {
  bool covered = false;
  with_generated_code(system, make_code,
                      [&](const engines::Layout& layout, engines::ModelCode& code) {
                        covered = code.make_steps(system, layout) != nullptr;
                      });
  return covered;
}

}  // namespace smcbip::tests
