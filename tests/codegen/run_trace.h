// The trace of one run, for comparing generated and interpreted models.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>

#include "engines/engines.h"

namespace smcbip::tests {

/// The whole output of run 0 of `model` on `engine` with `seed`, at most `limit` steps, then
/// its exit code; then the same run's JSON-lines trace (the optimised engine takes the compiled
/// step path there, where a model has one) and exit code. The multithread engine uses two
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
        << "\n";
  }
  return out.str();
}

}  // namespace smcbip::tests
