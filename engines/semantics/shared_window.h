// The optimised engine's choice on an untimed state, where every item has the same window: the
// scheduler and the compiled step path (flat_steps.h) draw it alike.
#pragma once

#include <cmath>
#include <cstddef>

#include "engines/stochastic/random_stream.h"
#include "engines/time_value.h"

namespace smcbip::engines {

/// The item and date a race of n items over one shared window gives, in two draws instead of
/// one per item (SharedWindowChooser). The race is then symmetric: its winner is uniform among the
/// n items and independent of the winning date. On the window [now, +inf) (`open_ended`) the dates
/// are now + floor(E_i), the E_i i.i.d. exponential of mean 10 ns, so the earliest is now +
/// floor(min E_i) and min E_i is exponential of mean 10/n; `first_enabled` keeps the winner's own
/// date (mean 10). On the window {now}, and with `asap`, every date is now.
struct SharedWindowChoice {
  std::size_t chosen = 0;
  TimeValue date = 0;
};

/// choose_in_shared_window's draws, kept by the scheduler or step path that makes them: the
/// delay floor(-mean ln u) is 0 whenever u lies above exp(-c / mean) for a c just under 1, so
/// above that cut, kept for the last mean, the logarithm (a good part of a step) is skipped.
/// The margin 1 - c = 2^-20 dwarfs the rounding errors of exp, log and the product (a few
/// units of 2^-53), so the skipped logarithm would have given 0 too: the dates are those of
/// the formula, bit for bit.
class SharedWindowChooser {
 public:
  SharedWindowChoice choose(std::size_t n, TimeValue now, bool open_ended, bool asap,
                            bool first_enabled, RandomStream& random) {
    const auto chosen = static_cast<std::size_t>(random.below(n));
    if (asap || !open_ended) return {chosen, now};
    const double mean = first_enabled ? 10.0 : 10.0 / static_cast<double>(n);
    if (mean != mean_) [[unlikely]] {
      mean_ = mean;
      zero_delay_above_ = std::exp(-(1.0 - 0x1p-20) / mean);
    }
    const double u = random.uniform01_open();
    if (u > zero_delay_above_) return {chosen, now};
    // The conversion truncates, which is floor on the delay, positive as u < 1 (and a call to
    // floor where the target lacks SSE4.1's rounding instruction).
    return {chosen, now + static_cast<TimeValue>(-mean * std::log(u))};
  }

 private:
  double mean_ = 0;
  double zero_delay_above_ = 1;
};

}  // namespace smcbip::engines
