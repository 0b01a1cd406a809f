// `smcbip check MODEL PROP ...`: every query of a property file answered by statistical model
// checking over runs of the model.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "smc/check/check.h"

namespace smcbip::tools {

struct CheckCommand {
  bipc::FrontendOptions model;
  std::string properties;
  std::string method = "auto", undecided = "error";
  bool json = false;
  smc::CheckOptions options;
};

void register_check_options(CLI::App& command, CheckCommand& check);

/// 0 when every hypothesis holds, 1 when one does not, 2 on bad input or a query left without
/// an answer (reported on stderr).
int run_check(CheckCommand check);

}  // namespace smcbip::tools
