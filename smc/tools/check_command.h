// `smcbip check MODEL PROP ...`: every query of a property file answered by statistical model
// checking over runs of the model.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "smc/check/check.h"

namespace smcbip::tools {

struct CheckCommand {
  std::string model, properties, root;
  std::vector<std::string> include_dirs;
  std::string method = "auto", undecided = "error";
  bool json = false;
  smc::CheckOptions options;
};

void register_check_options(CLI::App& command, CheckCommand& check);

/// 0 when every hypothesis holds, 1 when one does not, 2 on bad input or a query left without
/// an answer (reported on stderr).
int run_check(CheckCommand check);

}  // namespace smcbip::tools
