// The model-time date at which a clock reaches a value: shared by Runtime::clock_reaches and
// the date planner, which computes it inline from the run's state on every stochastic draw.
#pragma once

#include <cmath>
#include <cstdint>

#include "engines/api/compiled_model.h"

namespace smcbip::engines {

/// clock_value (compiled_model.h), to the bit, without its division where it is not needed: at
/// the date the clock was last set (a clock reset by the step that offers the port) the
/// elapsed term is rate·0/unit, a zero of the rate's sign.
inline double clock_value_at(const ClockState& clock, TimeValue unit, TimeValue at) {
  if (at == clock.since) return clock.value_at + clock.rate * 0.0;
  return clock_value(clock, unit, at);
}

/// std::ceil(x), to the bit, without the library call the baseline x86-64 target makes of it
/// (it has no rounding instruction): below 2^63 a double's whole part converts to an integer
/// and back exactly, and one more is exact below 2^52, the only doubles with a fraction.
inline double ceil_of(double x) {
  if (!(x > 0.0 && x < 9.2e18)) return std::ceil(x);  // zeros keep their sign there
  const double whole = static_cast<double>(static_cast<std::int64_t>(x));
  return whole < x ? whole + 1.0 : whole;
}

/// The first date from `now` at which `clock` (of unit `unit` ns) shows `value` or more:
/// `now` when it already does, +infinity when it never will (a stopped clock or a date past
/// the end of time).
inline TimeValue clock_reaches(const ClockState& clock, TimeValue unit, TimeValue now,
                               double value) {
  const double now_value = clock_value_at(clock, unit, now);
  if (value <= now_value) return now;
  if (clock.rate <= 0.0) return kPlusInfinity;
  // Clocks are linear in the delay: value = now_value + rate * delay / unit.
  // Dividing by a rate of 1 is exact: skipped, as it costs as much as the rest.
  const double scaled = (value - now_value) * static_cast<double>(unit);
  const double delay = ceil_of(clock.rate == 1.0 ? scaled : scaled / clock.rate);
  if (delay >= static_cast<double>(kPlusInfinity - now)) return kPlusInfinity;
  return now + static_cast<TimeValue>(delay);
}

}  // namespace smcbip::engines
