// The outputs of simulate queries: their trajectories as CSV and as an SVG plot, one panel per
// expression and one line per run.
#pragma once

#include <string>

#include "smc/check/check.h"

namespace smcbip::tools {

/// `run,time,e1,e2,...` with a header row naming the expressions; time in milliseconds.
std::string trajectories_csv(const smc::Trajectories& trajectories);

/// One panel per expression, titled by `query` and the expression, with every run a line.
std::string trajectories_svg(const std::string& query, const smc::Trajectories& trajectories);

}  // namespace smcbip::tools
