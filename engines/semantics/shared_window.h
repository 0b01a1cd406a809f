// The optimised engine's choice on an untimed state, where every item has the same window: the
// scheduler and the compiled step path (flat_steps.h) draw it alike.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "engines/api/time_value.h"
#include "engines/stochastic/random_stream.h"

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

/// The draws of SharedWindowChoice, kept by the scheduler or step path that makes them. The
/// delay floor(-mean ln u) is k exactly when u lies between exp(-(k + 1)/mean) and
/// exp(-k/mean): cuts just inside those bounds, kept for the last mean, tell the delay without
/// the logarithm (a good part of a step) unless it is large or u lies next to a bound. The
/// margin 2^-20 on the delay dwarfs the rounding errors of exp, log and the product (a few
/// units of 2^-53 of a delay below kCuts times a mean of at most 10), so the skipped logarithm
/// would have given the same delay: the dates are those of the formula, bit for bit.
class SharedWindowChooser {
 public:
  SharedWindowChoice choose(std::size_t n, TimeValue now, bool open_ended, bool asap,
                            bool first_enabled, RandomStream& random) {
    const auto chosen = static_cast<std::size_t>(random.below(n));
    if (asap || !open_ended) return {chosen, now};
    const double mean = first_enabled ? 10.0 : 10.0 / static_cast<double>(n);
    if (mean != mean_) [[unlikely]]
      set_mean(mean);
    return {chosen, now + delay(random.uniform01_open())};
  }

  /// floor(-mean ln u) for the last mean, u in (0, 1).
  TimeValue delay(double u) const {
    // k: the cuts at or above u, counted two at a time without branches (as random as u).
    const Pair both = {u, u};
    Count at_or_above = {0, 0};
    for (const Pair& cuts : at_most_) at_or_above -= (both <= cuts);  // true is -1
    const auto k = static_cast<int>(at_or_above[0] + at_or_above[1]);
    if (k < kCuts && u < at_least_[k]) return k;
    // The conversion truncates, which is floor on the delay, positive as u < 1 (and a call to
    // floor where the target lacks SSE4.1's rounding instruction).
    return static_cast<TimeValue>(-mean_ * std::log(u));
  }

 private:
  static constexpr int kCuts = 16;
  static constexpr double kMargin = 0x1p-20;
  // Two lanes of a vector register (GCC's and Clang's vector extensions: SSE2 on x86-64,
  // NEON on AArch64); comparing them gives -1 where true.
  using Pair = double __attribute__((vector_size(16)));
  using Count = std::int64_t __attribute__((vector_size(16)));

  void set_mean(double mean) {
    mean_ = mean;
    for (int k = 0; k < kCuts; ++k) {
      // u above cut k: the delay is at most k; u below at_least_[k]: it is at least k.
      at_most_[k / 2][k % 2] = std::exp(-(k + 1 - kMargin) / mean);
      at_least_[k] = std::exp(-(k + kMargin) / mean);
    }
  }

  double mean_ = 0;
  Pair at_most_[kCuts / 2] = {};  // cut k in lane k % 2 of pair k / 2
  double at_least_[kCuts] = {};
};

}  // namespace smcbip::engines
