// smcbip: simulate BIP models (statistical checking arrives with the smc stage).
//
// `smcbip simulate` exits with the reference engine's run codes (0 normal end, 1..7 model
// errors), 64 for usage errors, 65 for bad input, 70 for internal errors.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "bipc/bipc.h"
#include "bipc/options.h"
#include "engines/engines.h"
#include "engines/options.h"

namespace {

using namespace smcbip;

int run_simulate(const bipc::FrontendOptions& frontend, const engines::SimulateOptions& options) {
  bipc::FrontendResult result = bipc::run_frontend(frontend, /*need_system=*/true);
  bipc::Diagnostics sorted = result.diags;
  sorted.sort_by_location();
  std::cerr << sorted.format(result.model.files);
  if (result.diags.has_errors()) return engines::kInputError;
  if (!result.system) {
    std::cerr << "smcbip: error: no root given and the model has no single top compound; use "
                 "--root\n";
    return engines::kUsageError;
  }
  const engines::Externs externs = engines::Externs::with_builtins();
  std::ios::sync_with_stdio(false);
  // A JSON-lines trace keeps stdout for the trace: the model's own output goes to stderr.
  std::ostream& model_output = options.trace == engines::TraceFormat::Jsonl ? std::cerr : std::cout;
  engines::Simulator simulator(*result.system, options, externs);
  const engines::RunResult run =
      simulator.run(options.run_index, engines::RunStreams{std::cout, model_output, &std::cin});
  std::cout.flush();
  if (run.code == engines::kInputError || run.code == engines::kInternalError ||
      run.code == engines::kUsageError) {
    std::cerr << "smcbip: error: " << run.message << "\n";
  }
  return run.code;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    CLI::App app{"smcbip: simulation and statistical model checking of BIP models"};
    app.require_subcommand(1);
    bipc::FrontendOptions frontend;
    engines::SimulateOptions options;
    CLI::App* simulate = app.add_subcommand("simulate", "run a model once and print its trace");
    bipc::register_frontend_options(*simulate, frontend);
    engines::register_simulate_options(*simulate, options);
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      std::cerr << "smcbip: error: " << e.what() << "\n";
      return engines::kUsageError;
    }
    return run_simulate(frontend, options);
  } catch (const std::exception& e) {
    std::cerr << "smcbip: internal error: " << e.what() << "\n";
    return engines::kInternalError;
  }
}
