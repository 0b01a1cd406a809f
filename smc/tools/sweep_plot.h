// The plot of `smcbip explore --plot`: for each query over parameters, its estimates against
// one parameter with their band or intervals, and a hypothesis' threshold line, as SVG.
#pragma once

#include <string>

#include "smc/tools/report.h"

namespace smcbip::tools {

/// Whether `q` names a parameter of `file`, so that its results make a curve.
bool sweeps_parameter(const monitors::PropertyFile& file, const monitors::Query& q);

/// One panel per query that sweeps a parameter, stacked; the x axis is the parameter with the
/// most values, and each combination of the others' values is a curve of its own.
std::string sweep_svg(const Report& report);

}  // namespace smcbip::tools
