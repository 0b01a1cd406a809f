// simulate [<=T; N] { e1, e2 } (UPPAAL): the trajectories of expressions along N runs.
#pragma once

#include "smc/check/check.h"
#include "smc/check/query_runs.h"

namespace smcbip::smc {

/// Makes runs 0..N-1 of the model for each point of a Simulate query and records its
/// expressions along each, up to the run bound: at every step, and where an expression grows
/// with the clocks, just before the next step and at the bound. A run that deadlocks before
/// the bound is followed to it; one cut short (a limit, an error) ends where it stopped.
std::vector<QueryResult> simulate_trajectories(const bipc::ir::System& system,
                                               const QueryPoints& query,
                                               const CheckOptions& options);

}  // namespace smcbip::smc
