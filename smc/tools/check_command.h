// `smcbip check MODEL PROP ...`: every query of a property file answered by statistical model
// checking over runs of the model; `smcbip explore` answers them with one guarantee for each
// query's whole parameter sweep, and plots the sweeps.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "smc/check/check.h"
#include "smc/check/remote_runs.h"

namespace smcbip::tools {

struct CheckCommand {
  bipc::FrontendOptions model;
  std::string properties;
  std::string method = "auto", undecided = "error";
  bool json = false;
  std::vector<std::string> parameters;  // --param NAME=values
  smc::CheckOptions options;
  /// Set on the ranks of an MPI job: runs come from (or go to) other processes, and a worker
  /// rank prints and writes nothing.
  smc::RemoteRuns* remote = nullptr;
  bool worker = false;
  std::string compiled;  // --compiled: a plugin, or the folder of a built `bipc gen` project
  std::string compile = "auto";  // --compile: auto, always or never (the cache of plugins)
  bool explore = false;
  std::string plot, csv;     // explore: files to write
  std::string trajectories;  // the folder simulate queries write their trajectories to
};

/// The options of `check`, and with `explore` set those of `explore` too.
void register_check_options(CLI::App& command, CheckCommand& check, bool explore);

/// 0 when every hypothesis holds, 1 when one does not, 2 on bad input or a query left without
/// an answer (reported on stderr).
int run_check(CheckCommand check);

}  // namespace smcbip::tools
