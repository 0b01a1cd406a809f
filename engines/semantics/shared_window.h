// The optimised engine's choice on an untimed state, where every item has the same window: the
// scheduler and the compiled step path (flat_steps.h) draw it alike.
#pragma once

#include <cmath>
#include <cstddef>

#include "engines/stochastic/random_stream.h"
#include "engines/time_value.h"

namespace smcbip::engines {

/// The item and date a race of n items over one shared window gives, in two draws instead of
/// one per item. The race is then symmetric: its winner is uniform among the n items and
/// independent of the winning date. On the window [now, +inf) (`open_ended`) the dates are
/// now + floor(E_i), the E_i i.i.d. exponential of mean 10 ns, so the earliest is
/// now + floor(min E_i) and min E_i is exponential of mean 10/n; `first_enabled` keeps the
/// winner's own date (mean 10). On the window {now}, and with `asap`, every date is now.
struct SharedWindowChoice {
  std::size_t chosen = 0;
  TimeValue date = 0;
};

inline SharedWindowChoice choose_in_shared_window(std::size_t n, TimeValue now, bool open_ended,
                                                  bool asap, bool first_enabled,
                                                  RandomStream& random) {
  const auto chosen = static_cast<std::size_t>(random.below(n));
  if (asap || !open_ended) return {chosen, now};
  const double mean = first_enabled ? 10.0 : 10.0 / static_cast<double>(n);
  const double delay = std::floor(-mean * std::log(random.uniform01_open()));
  return {chosen, now + static_cast<TimeValue>(delay)};
}

}  // namespace smcbip::engines
