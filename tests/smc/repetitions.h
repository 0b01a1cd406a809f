// How often the statistical tests repeat a case, and how many failures a sound method may show.
#pragma once

#include <cmath>
#include <cstdlib>

namespace smcbip::smc::tests {

/// 1,000 repetitions in the `slow` run (SMCBIP_SLOW_STATS set), 200 otherwise.
inline int repetitions() { return std::getenv("SMCBIP_SLOW_STATS") != nullptr ? 1000 : 200; }

/// The most failures among `n` trials of probability at most `rate` that a sound method shows
/// but for a chance below 0.2%: the mean plus three standard deviations (plus one).
inline double slack_bound(int n, double rate) {
  const double mean = n * rate;
  return mean + 3 * std::sqrt(n * rate * (1 - rate)) + 1;
}

}  // namespace smcbip::smc::tests
