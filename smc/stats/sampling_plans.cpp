#include "smc/stats/sampling_plans.h"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace smcbip::smc {
namespace {

double binomial_at_most(std::uint64_t c, double p, std::uint64_t n) {
  return gsl_cdf_binomial_P(static_cast<unsigned>(c), p, static_cast<unsigned>(n));
}

/// The largest c with P[X <= c | p, n] <= limit, or -1 when even c = 0 exceeds it.
std::int64_t largest_c_below(double p, std::uint64_t n, double limit) {
  std::int64_t low = -1, high = static_cast<std::int64_t>(n);  // answer in [low, high]
  while (low < high) {
    const std::int64_t middle = low + (high - low + 1) / 2;
    if (binomial_at_most(static_cast<std::uint64_t>(middle), p, n) <= limit) {
      low = middle;
    } else {
      high = middle - 1;
    }
  }
  return low;
}

}  // namespace

SamplingPlan single_sampling_plan(double theta, double delta, double alpha, double beta) {
  const double p0 = std::min(1.0, theta + delta), p1 = std::max(0.0, theta - delta);
  constexpr std::uint64_t kLargest = 100'000'000;
  for (std::uint64_t n = 1; n <= kLargest; ++n) {
    // c must keep the false rejection of p0 within alpha...
    const std::int64_t c = largest_c_below(p0, n, alpha);
    if (c < 0) continue;
    // ...and the false acceptance of p1, P[X > c | p1], within beta.
    if (1.0 - binomial_at_most(static_cast<std::uint64_t>(c), p1, n) <= beta) {
      return {n, static_cast<std::uint64_t>(c)};
    }
  }
  throw std::invalid_argument("no single sampling plan of at most 10^8 runs");
}

std::uint64_t chernoff_samples(double delta, double alpha) {
  return static_cast<std::uint64_t>(std::ceil(std::log(2.0 / alpha) / (2.0 * delta * delta)));
}

double dkw_half_width(std::uint64_t runs, double alpha) {
  return std::sqrt(std::log(2.0 / alpha) / (2.0 * static_cast<double>(runs)));
}

}  // namespace smcbip::smc
