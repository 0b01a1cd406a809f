// `smcbip monitor PROP --trace RUN.jsonl... [--json]`: the verdict of each query of a property
// file on recorded runs.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "bipc/bipc.h"

namespace smcbip::tools {

struct MonitorOptions {
  std::string properties;
  std::vector<std::string> traces;
  bool json = false;
  bool pointwise = false;
  std::string time_unit = "ms";
  // A model whose names the properties must use (checked before the traces are read).
  bipc::FrontendOptions model;
};

/// Adds the options of `smcbip monitor` to its subcommand.
void register_monitor_options(CLI::App& command, MonitorOptions& options);

/// Runs the command: 0 when no verdict is false, 1 when one is, 2 on bad input (reported on
/// stderr, nothing on stdout).
int run_monitor(const MonitorOptions& options);

}  // namespace smcbip::tools
