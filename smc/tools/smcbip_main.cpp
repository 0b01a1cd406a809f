// smcbip: simulate BIP models, judge recorded runs against properties, and check properties
// statistically.
//
// `smcbip simulate` exits with the reference engine's run codes (0 normal end, 1..7 model
// errors), 64 for usage errors, 65 for bad input, 70 for internal errors. `smcbip monitor` and
// `smcbip check` and `smcbip explore` exit with 0 (no property false), 1 (one is), 2 (bad input or
// usage), 3 (internal error); `smcbip prove` likewise, and 4 when a query is left open.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "bipc/exit_codes.h"
#include "bipc/ir/model_hash.h"
#include "bipc/options.h"
#include "bipc/tool_main.h"
#include "engines/api/options.h"
#include "engines/api/plugin.h"
#include "engines/engines.h"
#include "fdir/tools/prove_command.h"
#include "smc/tools/check_command.h"
#include "smc/tools/distributed.h"
#include "smc/tools/model_loading.h"
#include "smc/tools/monitor_command.h"

namespace {

using namespace smcbip;

/// The system of the model file, or nullopt (diagnostics printed, `code` set).
std::optional<bipc::ir::System> load_system(const bipc::FrontendOptions& frontend, int& code) {
  tools::LoadFailure failure{};
  std::optional<bipc::ir::System> system = tools::load_model_system(frontend, failure);
  code = failure == tools::LoadFailure::NoRoot ? engines::kUsageError : engines::kInputError;
  return system;
}

/// Runs the compiled model of `plugin_path`; with a model file, only when it is that model.
/// A plugin or extern source that cannot be read throws (an InputError for the firewall).
int run_compiled(const bipc::FrontendOptions& frontend, const std::string& plugin_path,
                 const engines::SimulateOptions& options) {
  const engines::Plugin plugin = engines::load_plugin(plugin_path);
  if (!frontend.file.empty()) {
    int code = 0;
    const std::optional<bipc::ir::System> system = load_system(frontend, code);
    if (!system) return code;
    const std::string hash =
        bipc::ir::model_hash(*system, bipc::ir::extern_sources_of(*system, frontend.include_dirs));
    if (hash != plugin.entry->model_hash) {
      std::cerr << "smcbip: error: " << plugin.path << " holds another model (hash "
                << plugin.entry->model_hash << ") than " << frontend.file << " (hash " << hash
                << "); generate and build it again\n";
      return engines::kInputError;
    }
  }
  engines::Externs externs = engines::Externs::with_builtins();
  plugin.entry->register_externs(externs);
  return engines::run_simulation(plugin.entry->model(), options, externs, "smcbip",
                                 frontend.file.empty() ? plugin.path : frontend.file);
}

int run_simulate(const bipc::FrontendOptions& frontend, const engines::SimulateOptions& options) {
  int code = 0;
  const std::optional<bipc::ir::System> system = load_system(frontend, code);
  if (!system) return code;
  const engines::InterpretedModel model(*system);
  return engines::run_simulation(model, options, engines::Externs::with_builtins(), "smcbip",
                                 frontend.file);
}

/// The exit codes of a command: those of checking for `monitor`, `check` and `explore`, those
/// of runs for `simulate` (and for a command line with no command).
const exit_codes::FailureCodes& failure_codes(int argc, char** argv) {
  const std::string command = argc > 1 ? argv[1] : "";
  const bool judging =
      command == "monitor" || command == "check" || command == "explore" || command == "prove";
  return judging ? exit_codes::kJudgingCodes : exit_codes::kRunCodes;
}

int run(int argc, char** argv) {
  CLI::App app{"smcbip: simulation and statistical model checking of BIP models"};
  app.require_subcommand(1);
  bipc::FrontendOptions frontend;
  engines::SimulateOptions options;
  std::string compiled;
  CLI::App* simulate = app.add_subcommand("simulate", "run a model once and print its trace");
  bipc::register_frontend_options(*simulate, frontend, /*file_required=*/false);
  engines::register_simulate_options(*simulate, options);
  simulate
      ->add_option("--compiled", compiled,
                   "run the model compiled by bipc gen: its plugin, or the folder of its "
                   "built project (with FILE, only if FILE is that model)")
      ->type_name("DIR");
  tools::MonitorOptions monitor_options;
  CLI::App* monitor =
      app.add_subcommand("monitor", "judge recorded runs against the queries of a property file");
  tools::register_monitor_options(*monitor, monitor_options);
  tools::CheckCommand check_command;
  CLI::App* check = app.add_subcommand(
      "check", "answer the queries of a property file by statistical model checking");
  tools::register_check_options(*check, check_command, false);
  tools::CheckCommand explore_command;
  CLI::App* explore = app.add_subcommand(
      "explore", "answer parametric queries over their whole sweep at once, and plot them");
  tools::register_check_options(*explore, explore_command, true);
  tools::ProveCommand prove_command;
  CLI::App* prove = app.add_subcommand(
      "prove", "answer the A[] and E<> queries of a property file by invariants (Z3)");
  tools::register_prove_options(*prove, prove_command);
  cli::add_version_flags(app, "smcbip");
  if (const int code = cli::parse_command_line(app, argc, argv); code >= 0) return code;
  if (simulate->parsed() && frontend.file.empty() && compiled.empty()) {
    throw UsageError("FILE (or --compiled) is required\nRun with --help for more information.");
  }
  if (monitor->parsed()) return tools::run_monitor(monitor_options);
  if (check->parsed()) return tools::run_check_distributed(check_command, argc, argv);
  if (explore->parsed()) return tools::run_check_distributed(explore_command, argc, argv);
  if (prove->parsed()) return tools::run_prove(prove_command);
  if (!compiled.empty()) return run_compiled(frontend, compiled, options);
  return run_simulate(frontend, options);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::guarded_main("smcbip", failure_codes(argc, argv), [&] { return run(argc, argv); });
}
