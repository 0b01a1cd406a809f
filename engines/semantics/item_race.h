// The optimised engine's choice among items with windows of their own (timed states): the
// reference engine's race of random dates, and the stochastic race of planned dates. The
// scheduler and the compiled step path (flat_steps.h) draw them alike; items are given by
// position (0 to n-1) through accessors.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

#include "engines/api/time_value.h"
#include "engines/stochastic/date_planner.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

/// The first date of `interval` from `now` on.
inline TimeValue earliest(const Interval& interval, TimeValue now) {
  return std::max(interval.first(), now);
}

/// The date an item is planned at by the reference scheduler: uniform over the (integer
/// nanosecond) points of a bounded window; on an unbounded one the left end plus an
/// exponential delay of mean 10 ns, as the reference engine's Interval::random does.
inline TimeValue random_date(const Interval& interval, RandomStream& random) {
  if (interval.bounded()) return uniform_date(interval, random);
  return interval.first() +
         static_cast<TimeValue>(std::floor(-10.0 * std::log(random.uniform01_open())));
}

/// The delay floor(-10 ln u) of random_date's unbounded case, computed only when needed: the
/// race mostly has to know whether it is below, at or above a given whole number of
/// nanoseconds, which comparing u with exp(-d / 10) answers without a logarithm. Near those
/// bounds (within a relative 1e-9, far above the rounding errors of exp and log) the delay is
/// computed exactly as random_date does, so the choices are the same.
class ExponentialDelay {
 public:
  static TimeValue of(double u) { return static_cast<TimeValue>(std::floor(-10.0 * std::log(u))); }
  /// The sign of of(u) - d; the bounds of the last d are kept (items mostly share it).
  int compare(double u, TimeValue d) {
    if (d < 0) return 1;  // u < 1, so the delay is never negative
    if (d != d_) {
      d_ = d;
      below_d_ = std::exp(-static_cast<double>(d) / 10.0);  // u above it: delay < d
      below_next_ = std::exp(-static_cast<double>(d + 1) / 10.0);
    }
    constexpr double kMargin = 1e-9;
    if (u > below_d_ * (1 + kMargin)) return -1;
    if (u < below_next_ * (1 - kMargin)) return 1;
    if (u < below_d_ * (1 - kMargin) && u > below_next_ * (1 + kMargin)) return 0;
    const TimeValue exact = of(u);
    return exact < d ? -1 : exact > d ? 1 : 0;
  }

 private:
  TimeValue d_ = -1;
  double below_d_ = 0, below_next_ = 0;
};

/// The reference scheduler's race over n items (n > 0): every item draws a date in its window
/// (`window(i)`), the earliest wins, ties go to a uniform choice. `asap` plans each item at its
/// earliest date; `first_enabled` compares earliest dates but keeps the winner's drawn one.
template <class WindowOf>
std::pair<std::size_t, TimeValue> random_race(std::size_t n, WindowOf window, TimeValue now,
                                              bool asap, bool first_enabled, RandomStream& random) {
  std::size_t best = 0;
  std::uint64_t ties = 0;
  TimeValue best_criterion = kPlusInfinity, best_date = now;
  ExponentialDelay delay;
  for (std::size_t i = 0; i < n; ++i) {
    const Interval& interval = window(i);
    if (!asap && !first_enabled && !interval.bounded()) {
      // The planned date is the criterion: often decided without its logarithm.
      const TimeValue first = interval.first();
      const double u = random.uniform01_open();
      const int order = i == 0 ? -1 : delay.compare(u, best_criterion - first);
      if (order < 0) {
        best = i;
        ties = 1;
        best_criterion = best_date = first + ExponentialDelay::of(u);
      } else if (order == 0 && random.below(++ties) == 0) {
        best = i;
        best_date = best_criterion;
      }
      continue;
    }
    const TimeValue planned = asap ? earliest(interval, now) : random_date(interval, random);
    const TimeValue criterion = first_enabled ? earliest(interval, now) : planned;
    if (i == 0 || criterion < best_criterion) {
      best = i;
      ties = 1;
      best_criterion = criterion;
      best_date = planned;
    } else if (criterion == best_criterion && random.below(++ties) == 0) {
      best = i;
      best_date = planned;
    }
  }
  return {best, std::max(best_date, now)};
}

/// The stochastic race over n items: the earliest planned date (`date(i)`) that lies in its
/// item's window (`window(i)`) wins, ties go to a uniform choice; nullopt when no date lies in
/// its window. Always inline: over a few items, the call cost more than the loop in the
/// compiled step path.
template <class WindowOf, class DateOf>
[[gnu::always_inline]] inline std::optional<std::pair<std::size_t, TimeValue>> earliest_in_window(
    std::size_t n, WindowOf window, DateOf date, RandomStream& random) {
  std::optional<std::pair<std::size_t, TimeValue>> best;
  std::uint64_t ties = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const TimeValue d = date(i);
    if (!window(i).contains(d)) continue;
    if (!best || d < best->second) {
      best = std::pair{i, d};
      ties = 1;
    } else if (d == best->second && random.below(++ties) == 0) {
      best->first = i;
    }
  }
  return best;
}

}  // namespace smcbip::engines
