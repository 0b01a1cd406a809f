// Command-line options of a simulation, declared once for `smcbip simulate` and for generated
// executables.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <string>

#include "bipc/exit_codes.h"
#include "bipc/options.h"
#include "bipc/tool_main.h"
#include "engines/api/replay.h"
#include "engines/api/simulate.h"

namespace smcbip::engines {

namespace detail {

// The steps of register_simulate_options, in the order `--help` lists the options.

/// Which engine runs, with which seed and run, and for how long.
inline void add_engine_options(CLI::App& app, SimulateOptions& options) {
  constexpr std::uint64_t kLargest = std::numeric_limits<std::uint64_t>::max();
  app.add_option("--engine", options.engine, "the scheduler (default: reference)")
      ->transform(cli::named_choice(
          std::map<std::string, EngineKind>{{"reference", EngineKind::Reference},
                                            {"optimised", EngineKind::Optimised},
                                            {"optimized", EngineKind::Optimised},
                                            {"multithread", EngineKind::Multithread}}))
      ->option_text(cli::choices_text({"reference", "optimised", "multithread"}));
  cli::add_threads_option(app, options.threads,
                          "worker threads of the multithread engine, 0 for all cores", 0);
  cli::add_seed_option(app, options.seed, "the seed of the run's random stream (default: drawn)");
  app.add_option("--run-index", options.run_index,
                 "which run of the seed to replay (smcbip check numbers its runs from 0)")
      ->check(cli::integer_in(0, kLargest))
      ->type_name("I");
  app.add_option("-l,--limit", options.limit, "stop after this many steps")
      ->check(cli::integer_in(1, kLargest))
      ->type_name("N");
}

/// How the engine chooses the next item, and when.
inline void add_choice_flags(CLI::App& app, SimulateOptions& options) {
  app.add_flag("--real-time", options.real_time, "follow the platform clock");
  app.add_flag("-a,--asap", options.asap, "plan each item at its earliest date");
  app.add_flag("-f,--first-enabled", options.first_enabled,
               "choose among the items that can run first");
  app.add_flag("--relaxed", options.relaxed,
               "real time: report missed deadlines as warnings and go on");
  app.add_flag("--disable-maximal-progress", options.disable_maximal_progress,
               "do not restrict connectors to their maximal interactions");
}

/// What the run is: one driven by a prompt or a trace, a silent one, or an exploration.
inline void add_run_mode_options(CLI::App& app, SimulateOptions& options) {
  CLI::Option* interactive =
      app.add_flag("--interactive", options.interactive, "pick each item at a prompt");
  app.add_option("--replay", options.replay,
                 "follow a JSON-lines trace (--trace jsonl, smcbip prove --trace-out): fire the "
                 "interaction of each step, which must be enabled, and check each state")
      ->type_name("FILE")
      ->excludes(interactive);
  app.add_flag("-s,--silent", options.silent, "print no engine trace (errors still)");
  app.add_flag(
         "--explore", options.explore,
         "enumerate the reachable states (untimed); with --limit, those within that many steps")
      ->excludes("--replay");
  app.add_option("--max-states", options.max_explored_states,
                 "--explore: keep at most this many states (default: " +
                     std::to_string(options.max_explored_states) + "), then stop")
      ->check(cli::integer_in(1, std::uint64_t{1} << 40))
      ->type_name("N");
}

/// Whether planned dates race, and the mean delay of the items without a deadline.
inline void add_stochastic_options(CLI::App& app, SimulateOptions& options) {
  app.add_flag_callback(
      "--stochastic", [&options] { options.stochastic = true; },
      "race planned dates (the default when the model has @stochastic ports)");
  app.add_flag_callback(
      "--no-stochastic", [&options] { options.stochastic = false; },
      "use the reference engine's random choice even with @stochastic ports");
  app.add_option_function<double>(
         "--unbounded-mean",
         [&options](double ms) { options.unbounded_mean = static_cast<TimeValue>(ms * 1e6); },
         "stochastic mode: mean delay (ms) of items with no deadline (default 1)")
      ->check(cli::finite_in(1e-6, 1e9))
      ->type_name("MS");
}

}  // namespace detail

/// Registers the options of `smcbip simulate` on a (sub)command.
inline void register_simulate_options(CLI::App& app, SimulateOptions& options) {
  detail::add_engine_options(app, options);
  detail::add_choice_flags(app, options);
  detail::add_run_mode_options(app, options);
  detail::add_stochastic_options(app, options);
  app.add_option("--trace", options.trace, "the trace's format (default: text)")
      ->transform(cli::named_choice(std::map<std::string, TraceFormat>{
          {"text", TraceFormat::Text}, {"jsonl", TraceFormat::Jsonl}}))
      ->option_text(cli::choices_text({"text", "jsonl"}));
}

/// `smcbip simulate`'s run of a model once loaded: the trace on stdout, the model's output on
/// stdout (stderr with a JSON-lines trace), input errors on stderr prefixed by their place in
/// the model when known, else by `where` (the model file), else by `tool`; returns the exit code
/// (the RunCode).
inline int run_simulation(const Model& model, const SimulateOptions& options,
                          const Externs& externs, const std::string& tool,
                          const std::string& where = "") {
  std::ios::sync_with_stdio(false);
  // A JSON-lines trace keeps stdout for the trace: the model's own output goes to stderr.
  std::ostream& model_output = options.trace == TraceFormat::Jsonl ? std::cerr : std::cout;
  Simulator simulator(model, options, externs);
  const RunStreams streams{std::cout, model_output, &std::cin};
  std::optional<ReplayScript> script;
  if (!options.replay.empty()) {
    std::ifstream in(options.replay);
    if (!in) {
      std::cerr << options.replay << ": error: cannot read the trace\n";
      return kInputError;
    }
    try {
      script = read_replay_script(in, options.replay);
    } catch (const ReplayError& e) {
      std::cerr << e.where << ": error: " << e.what() << "\n";
      return kInputError;
    }
  }
  const RunResult run =
      script ? simulator.replay(*script, streams) : simulator.run(options.run_index, streams);
  std::cout.flush();
  if (run.code == kInputError || run.code == kInternalError || run.code == kUsageError) {
    const std::string& at = !run.where.empty() ? run.where : where.empty() ? tool : where;
    std::cerr << at << ": error: " << run.message << "\n";
  }
  return run.code;
}

/// The main program of a generated model: parses the options of `smcbip simulate` (no model
/// file: the model is compiled in) and runs `model` once as `smcbip simulate` does; returns the
/// exit code.
inline int simulate_main(int argc, char** argv, const Model& model, const Externs& externs,
                         const std::string& name) {
  return cli::guarded_main(name, exit_codes::kRunCodes, [&] {
    CLI::App app{name + ": the BIP model " + name + ", compiled by bipc gen"};
    SimulateOptions options;
    register_simulate_options(app, options);
    cli::add_version_flags(app, name);
    if (const int code = cli::parse_command_line(app, argc, argv); code >= 0) return code;
    return run_simulation(model, options, externs, name);
  });
}

}  // namespace smcbip::engines
