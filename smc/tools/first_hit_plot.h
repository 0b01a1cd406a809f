// The plot of `smcbip check --plot` (UPPAAL's for Pr[<=T](<> phi)): for each estimate of when
// a formula F phi first holds, the cumulative probability over time with its simultaneous
// confidence band, and the density of the first times as a histogram.
#pragma once

#include <string>

#include "smc/tools/report.h"

namespace smcbip::tools {

/// Whether `r` holds the first times of its runs (an estimate of F phi), so that it plots.
bool has_first_hits(const smc::QueryResult& r);

/// Two panels per such result: the cumulative probability P(phi holds by t) for t over the
/// run's bound, the empirical distribution of the runs' first times within the DKW band at the
/// result's 1 - alpha (simultaneous over every t), and below it their histogram as a density.
std::string first_hit_svg(const Report& report);

}  // namespace smcbip::tools
