// Pr[<=T](phi) >= Pr[<=T2](psi): which of two probabilities is the larger, by a sequential test
// on runs that judge both formulas at once.
#pragma once

#include "smc/check/check.h"
#include "smc/check/query_runs.h"

namespace smcbip::smc {

/// Answers a Compare query at each of its points. Each run is judged for both formulas (common
/// random numbers: the same run for phi and psi). Only the runs where exactly one formula holds
/// tell the probabilities apart: among them, the share q where phi holds is above 1/2 exactly
/// when P(phi) > P(psi), since P(phi) - P(psi) = P(phi only) - P(psi only). Wald's SPRT tests
/// q >= 1/2 + delta against q <= 1/2 - delta with strength (alpha, beta); the verdict is the
/// comparison's. The estimate is the difference of the two estimates over the runs made.
std::vector<QueryResult> compare_probabilities(const bipc::ir::System& system,
                                               const QueryPoints& query,
                                               const CheckOptions& options);

}  // namespace smcbip::smc
