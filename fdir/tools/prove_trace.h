// `smcbip prove --trace-out FILE`: a counterexample or witness written in the JSON-lines trace
// format, as the engines replay it, so that `smcbip simulate --replay FILE` follows it.
#pragma once

#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "fdir/search/counterexample_search.h"

namespace smcbip::tools {

/// Replays `trace` (the prover's, its interactions as the text trace lists them) in the
/// engines, writing the run as JSON lines with an `interaction` field per step, to `path`
/// all at once (a temporary renamed over it). Returns 0, or the exit code after an error on
/// stderr: 2 when `path` cannot be written, 3 when the trace does not replay (a bug).
int write_prove_trace(const std::string& path, const bipc::ir::System& system,
                      const std::vector<fdir::TraceState>& trace);

}  // namespace smcbip::tools
