// Command-line options of a simulation, declared once for `smcbip simulate` and for generated
// executables.
#pragma once

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "engines/engines.h"

namespace smcbip::engines {

/// Registers the options of `smcbip simulate` on a (sub)command.
inline void register_simulate_options(CLI::App& app, SimulateOptions& options) {
  app.add_option("--engine", options.engine, "scheduler")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, EngineKind>{{"reference", EngineKind::Reference},
                                            {"optimised", EngineKind::Optimised},
                                            {"optimized", EngineKind::Optimised},
                                            {"multithread", EngineKind::Multithread}},
          CLI::ignore_case));
  app.add_option("--threads", options.threads, "worker threads of the multithread engine")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--seed", options.seed, "seed of the run's random stream");
  app.add_option("--run-index", options.run_index,
                 "which run of the seed to replay (smcbip check numbers its runs from 0)");
  app.add_option("-l,--limit", options.limit, "stop after this many steps")
      ->check(CLI::PositiveNumber);
  app.add_flag("--real-time", options.real_time, "follow the platform clock");
  app.add_flag("-a,--asap", options.asap, "plan each item at its earliest date");
  app.add_flag("-f,--first-enabled", options.first_enabled,
               "choose among the items that can run first");
  app.add_flag("--relaxed", options.relaxed,
               "real time: report missed deadlines as warnings and go on");
  app.add_flag("--disable-maximal-progress", options.disable_maximal_progress,
               "do not restrict connectors to their maximal interactions");
  app.add_flag("--interactive", options.interactive, "pick each item at a prompt");
  app.add_flag("-s,--silent", options.silent, "print no engine trace (errors still)");
  app.add_flag(
      "--explore", options.explore,
      "enumerate the reachable states (untimed); with --limit, those within that many steps");
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
      ->check(CLI::PositiveNumber);
  app.add_option("--trace", options.trace, "trace format")
      ->transform(
          CLI::CheckedTransformer(std::map<std::string, TraceFormat>{{"text", TraceFormat::Text},
                                                                     {"jsonl", TraceFormat::Jsonl}},
                                  CLI::ignore_case));
}

/// The main program of a generated model: parses the options of `smcbip simulate` (no model
/// file: the model is compiled in) and runs `model` once as `smcbip simulate` does; returns the
/// exit code.
inline int simulate_main(int argc, char** argv, const Model& model, const Externs& externs,
                         const std::string& name) {
  try {
    CLI::App app{name + ": the BIP model " + name + ", compiled by bipc gen"};
    SimulateOptions options;
    register_simulate_options(app, options);
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      std::cerr << name << ": error: " << e.what() << "\n";
      return kUsageError;
    }
    return run_simulation(model, options, externs, name);
  } catch (const std::exception& e) {
    std::cerr << name << ": internal error: " << e.what() << "\n";
    return kInternalError;
  }
}

}  // namespace smcbip::engines
