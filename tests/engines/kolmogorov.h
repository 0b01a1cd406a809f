// The one-sample Kolmogorov-Smirnov statistic and its critical value, shared by the tests of
// the date distributions and of the stochastic engine.
//
// Under H0 (the samples follow F, F continuous), sqrt(n)·D_n tends in law to the Kolmogorov
// distribution, P(K > x) = 2·sum_{k>=1} (-1)^(k-1) exp(-2k²x²). At the critical point the first
// term alone is exact to 2·exp(-8x²) ~ 1e-13, so K_alpha = sqrt(-ln(alpha/2) / 2) = 1.9495 for
// alpha = 0.001. The finite-n error is of order 1/sqrt(n): Stephens' (1970) correction
// multiplies sqrt(n) by 1 + 0.12/n^(1/2) + ..., i.e. changes the statistic by 0.12% at
// n = 10,000, well inside any margin that matters here.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace smcbip::tests {

inline constexpr double kKsAlpha = 0.001;

/// sqrt(-ln(alpha/2) / 2): the asymptotic Kolmogorov critical value (see the file comment).
inline double kolmogorov_critical(double alpha = kKsAlpha) {
  return std::sqrt(-0.5 * std::log(alpha / 2.0));
}

/// sqrt(n)·D_n with D_n = sup_x |F_n(x) - F(x)|, attained at a sample point from the left or
/// the right: max over sorted x_(i) of i/n - F(x_(i)) and F(x_(i)) - (i-1)/n.
inline double kolmogorov_statistic(std::vector<double> samples,
                                   const std::function<double(double)>& f) {
  std::sort(samples.begin(), samples.end());
  const double n = static_cast<double>(samples.size());
  double d = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double fx = f(samples[i]);
    d = std::max({d, static_cast<double>(i + 1) / n - fx, fx - static_cast<double>(i) / n});
  }
  return std::sqrt(n) * d;
}

}  // namespace smcbip::tests
