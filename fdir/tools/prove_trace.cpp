// The prover's trace, replayed by the engines and written as JSON lines.
#include "fdir/tools/prove_trace.h"

#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bipc/exit_codes.h"
#include "bipc/json_dump.h"
#include "bipc/output_file.h"
#include "engines/api/replay.h"
#include "engines/engines.h"

namespace smcbip::tools {

namespace {

/// The prover's trace as a script to follow: each step names its interaction exactly.
engines::ReplayScript script_of(const std::vector<fdir::TraceState>& trace) {
  engines::ReplayScript script;
  script.file = "the prover's trace";
  for (std::size_t k = 0; k < trace.size(); ++k) {
    engines::ReplayStep step;
    step.line = k + 1;
    if (k > 0) {
      step.interaction = trace[k].fired;
      step.fired = trace[k].fired.substr(0, trace[k].fired.find(": "));
    }
    script.steps.push_back(std::move(step));
  }
  return script;
}

/// The JSON lines of the run, each step line given the `interaction` it fired.
std::string with_interactions(const std::string& lines,
                              const std::vector<fdir::TraceState>& trace) {
  std::istringstream in(lines);
  std::string out, text;
  while (std::getline(in, text)) {
    nlohmann::ordered_json line = nlohmann::ordered_json::parse(text);
    if (line.contains("step")) {
      const std::size_t k = line["step"].get<std::size_t>();
      if (k > 0 && k < trace.size()) line["interaction"] = trace[k].fired;
    }
    out += bipc::dump_json(line) + "\n";
  }
  return out;
}

}  // namespace

int write_prove_trace(const std::string& path, const bipc::ir::System& system,
                      const std::vector<fdir::TraceState>& trace) {
  engines::SimulateOptions options;
  options.trace = engines::TraceFormat::Jsonl;
  options.seed = 0;  // nothing is drawn: the trace chooses every step
  engines::Simulator simulator(system, options, engines::Externs::with_builtins());
  std::ostringstream lines, model_output;
  const engines::RunResult run =
      simulator.replay(script_of(trace), engines::RunStreams{lines, model_output, nullptr});
  if (run.code != engines::kRunOk) {
    std::cerr << "smcbip: error: the prover's trace does not replay in the engines: "
              << engines::located_message(run.where, run.message) << "\n";
    return exit_codes::kInternalError;
  }
  std::string error;
  if (!bipc::write_file_atomically(path, with_interactions(lines.str(), trace), error)) {
    std::cerr << path << ": error: " << error << "\n";
    return exit_codes::kInputError;
  }
  return exit_codes::kSuccess;
}

}  // namespace smcbip::tools
