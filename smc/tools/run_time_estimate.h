// How long `smcbip check` would take to make its runs interpreted: a short pilot times runs of
// one query, the methods tell how many runs each query needs. `--compile auto` weighs it
// against the time a build of the model's plugin takes.
#pragma once

#include <cstdint>
#include <string>

#include "bipc/ir/ir.h"
#include "monitors/monitors.h"
#include "smc/check/check.h"

namespace smcbip::tools {

/// The pilot makes runs for about this long (at least one run).
inline constexpr double kPilotSeconds = 0.05;

struct RunTimeEstimate {
  double seconds = 0;       // wall time of every query's runs on the check's threads
  std::uint64_t runs = 0;   // the runs of every query
  double run_seconds = 0;   // one run, timed by the pilot (0: no query makes runs)
  bool sequential = false;  // some query's count is an estimate for a sequential method
};

/// The runs a query needs, at the largest over its points: a fixed-size method's number
/// (PESTIM's Chernoff-Hoeffding bound, the single sampling plan, an expectation's N, a
/// simulate query's N); a sequential method's estimate (SPRT and the paired SPRT: Wald's
/// average sample number where it is largest, at the p whose log-ratio steps cancel; the
/// sequential intervals, ci and bayes: PESTIM's number). With `explore`, α (and β) split over
/// the points as explore splits them. Sets `sequential` for an estimate.
std::uint64_t expected_runs(const monitors::PropertyFile& file, const monitors::Query& q,
                            const smc::CheckOptions& options, bool explore, bool& sequential);

/// Times interpreted runs of the first query that makes them (one thread, run indices from
/// 0 as the check makes them, about kPilotSeconds) and counts the runs of every query. A
/// model or query the pilot cannot run gives an estimate of 0 (the check then reports it).
RunTimeEstimate estimate_run_time(const bipc::ir::System& system,
                                  const monitors::PropertyFile& file,
                                  const smc::CheckOptions& options, bool explore);

}  // namespace smcbip::tools
