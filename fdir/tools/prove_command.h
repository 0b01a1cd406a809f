// `smcbip prove MODEL PROP ...`: the `A[]` and `E<>` queries of a property file answered by
// invariants and Z3, with counterexamples confirmed by the engines' exploration.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "fdir/prove/prover.h"

namespace smcbip::tools {

struct ProveCommand {
  bipc::FrontendOptions model;
  std::string properties;
  bool json = false;
  fdir::ProveOptions options;
  std::vector<std::string> assumptions;  // --assume: SMT-LIB2 files
  std::string trace_out;                 // --trace-out: JSON-lines file of the first trace
};

/// The options of `prove`.
void register_prove_options(CLI::App& command, ProveCommand& prove);

/// Exit codes of `prove`: 0 every query holds, 1 one does not, 4 one is left open (and none
/// fails), 2 bad input or a construct the prover does not handle.
inline constexpr int kProveOpen = 4;

int run_prove(const ProveCommand& prove);

}  // namespace smcbip::tools
