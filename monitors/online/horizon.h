// How far a formula looks into a run: the nested sum of its upper bounds (PROPERTIES.md: the
// run length of a query without a run bound).
#pragma once

#include <cstdint>

#include "monitors/online/online_monitor.h"

namespace smcbip::monitors {

/// The time (ticks) and steps past the first position that a formula's verdict depends on at
/// most: along every path of nested operators the sum of time bounds and of step bounds (X
/// counts one step), the largest over the paths. Unbounded: some F, G, U or R has no bound.
struct Horizon {
  bool bounded = true;
  online::Tick time = 0;
  std::int64_t steps = 0;
};

/// Throws MonitorError as bound_ticks does.
Horizon horizon(const Formula& formula, const TimeScale& scale, const Bindings& bindings);

}  // namespace smcbip::monitors
