// The statistics of smc on Bernoulli sources of known p, with fixed seeds. Published vectors
// for the sampling plans; error rates, coverage and sample counts of the sequential methods
// against their guarantees, with the binomial slack stated where it is used. The `slow`
// variants repeat each case 1,000 times; the quick ones 200 times.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <tuple>
#include <vector>

#include "smc/smc.h"
#include "tests/smc/repetitions.h"

namespace smcbip::smc {
namespace {

using tests::repetitions;
using tests::slack_bound;

TEST(SamplingPlans, SingleSamplingPlanMatchesPublishedVectors) {
  const SamplingPlan strict = single_sampling_plan(0.5, 0.05, 0.01, 0.01);
  EXPECT_EQ(strict.n, 539u);
  EXPECT_EQ(strict.c, 269u);
  const SamplingPlan loose = single_sampling_plan(0.5, 0.05, 0.05, 0.05);
  EXPECT_EQ(loose.n, 269u);
  EXPECT_EQ(loose.c, 134u);
}

/// P[X <= c | p] for c = 0..n, X binomial(n, p), summed from the probability mass function
/// (by log-gamma): a computation of its own, not the library's.
std::vector<double> binomial_cdf(int n, double p) {
  std::vector<double> cdf(n + 1);
  double sum = 0;
  for (int k = 0; k <= n; ++k) {
    sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) +
                    k * std::log(p) + (n - k) * std::log1p(-p));
    cdf[k] = sum;
  }
  return cdf;
}

TEST(SamplingPlans, SingleSamplingPlanMatchesASearchOfItsOwn) {
  // The smallest n for which some c keeps both errors within bounds, found by trying every
  // n and c; the plan's c must be one of those that do.
  for (const auto& [theta, delta, alpha, beta] :
       {std::tuple{0.5, 0.05, 0.01, 0.01}, std::tuple{0.3, 0.05, 0.05, 0.1},
        std::tuple{0.9, 0.03, 0.05, 0.05}, std::tuple{0.1, 0.02, 0.01, 0.05}}) {
    const SamplingPlan plan = single_sampling_plan(theta, delta, alpha, beta);
    int smallest = -1;
    std::vector<int> valid;
    for (int n = 1; smallest < 0 && n <= 5000; ++n) {
      const std::vector<double> at_p0 = binomial_cdf(n, theta + delta);
      const std::vector<double> at_p1 = binomial_cdf(n, theta - delta);
      for (int c = 0; c < n; ++c) {
        // A margin of 1e-9 on each side absorbs rounding: the test must not hinge on it.
        if (at_p0[c] <= alpha + 1e-9 && 1 - at_p1[c] <= beta + 1e-9) valid.push_back(c);
      }
      if (!valid.empty()) smallest = n;
    }
    EXPECT_EQ(static_cast<int>(plan.n), smallest) << theta << " " << delta;
    EXPECT_NE(std::find(valid.begin(), valid.end(), static_cast<int>(plan.c)), valid.end())
        << "c = " << plan.c << " for theta " << theta;
  }
}

TEST(SamplingPlans, ChernoffSampleSizes) {
  EXPECT_EQ(chernoff_samples(0.05, 0.05), 738u);
  EXPECT_EQ(chernoff_samples(0.01, 0.05), 18445u);
  EXPECT_EQ(chernoff_samples(0.01, 0.01), 26492u);
}

TEST(ClopperPearson, KnownIntervals) {
  // No success in 10 runs: the upper end solves (1 - p)^10 = alpha / 2.
  const Interval none = clopper_pearson(0, 10, 0.05);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 1 - std::pow(0.025, 0.1), 1e-9);
  const Interval all = clopper_pearson(10, 10, 0.05);
  EXPECT_NEAR(all.low, std::pow(0.025, 0.1), 1e-9);
  EXPECT_EQ(all.high, 1.0);
}

struct SprtCase {
  double theta, delta, alpha, beta;
};

/// Wald's approximation of the expected number of runs when p is `p`.
double wald_asn(const SprtCase& c, double p) {
  const double p0 = c.theta + c.delta, p1 = c.theta - c.delta;
  const double a = std::log(c.beta / (1 - c.alpha)), b = std::log((1 - c.beta) / c.alpha);
  const double step = p * std::log(p1 / p0) + (1 - p) * std::log((1 - p1) / (1 - p0));
  const double accept = p == p0 ? 1 - c.alpha : c.beta;  // the chance to end at a
  return (accept * a + (1 - accept) * b) / step;
}

TEST(Sprt, ErrorRatesStayWithinAlphaAndBeta) {
  for (const SprtCase c : {SprtCase{0.5, 0.05, 0.05, 0.05}, SprtCase{0.8, 0.02, 0.01, 0.05},
                           SprtCase{0.1, 0.05, 0.05, 0.01}}) {
    const int n = repetitions();
    std::mt19937_64 random(42);
    for (const bool at_least : {true, false}) {
      const double p = at_least ? c.theta + c.delta : c.theta - c.delta;
      std::bernoulli_distribution run(p);
      int errors = 0;
      double samples = 0;
      for (int r = 0; r < n; ++r) {
        Sprt test(c.theta, c.delta, c.alpha, c.beta);
        Decision d = Decision::Undecided;
        while (d == Decision::Undecided) d = test.add(run(random));
        errors += d != (at_least ? Decision::AtLeast : Decision::Below);
        samples += static_cast<double>(test.samples());
      }
      const double rate = at_least ? c.alpha : c.beta;
      EXPECT_LE(errors, slack_bound(n, rate)) << "theta " << c.theta << ", p " << p;
      // Wald's approximation neglects the overshoot of the last step: within 10% on average.
      EXPECT_NEAR(samples / n, wald_asn(c, p), 0.1 * wald_asn(c, p) + 2)
          << "theta " << c.theta << ", p " << p;
    }
  }
}

TEST(Sprt, DecidesAtOnceOnCertainBounds) {
  Sprt everything(1.0, 0.05, 0.05, 0.05);  // p0 clipped to 1: one failure refutes p >= 1
  EXPECT_EQ(everything.add(false), Decision::Below);
  EXPECT_EQ(everything.samples(), 1u);
}

TEST(SequentialInterval, CoversPWhereverItStops) {
  const int n = repetitions();
  for (const double p : {0.02, 0.3, 0.5, 0.97}) {
    std::mt19937_64 random(7);
    std::bernoulli_distribution run(p);
    int misses = 0;
    for (int r = 0; r < n; ++r) {
      SequentialInterval estimate(0.05, 0.05);
      while (!estimate.add(run(random))) {
      }
      const Interval i = estimate.interval();
      EXPECT_LE(i.high - i.low, 0.1 + 1e-12);
      misses += p < i.low || p > i.high;
    }
    EXPECT_LE(misses, slack_bound(n, 0.05)) << "p " << p;
  }
}

TEST(SequentialInterval, NeedsFewerRunsNearZeroOrOne) {
  std::mt19937_64 random(9);
  std::bernoulli_distribution rare(0.01);
  SequentialInterval estimate(0.01, 0.05);
  while (!estimate.add(rare(random))) {
  }
  EXPECT_LT(estimate.samples(), chernoff_samples(0.01, 0.05) / 2);
}

TEST(BayesianInterval, PosteriorIntervalsCoverP) {
  const int n = repetitions();
  for (const double p : {0.1, 0.5, 0.9}) {
    std::mt19937_64 random(3);
    std::bernoulli_distribution run(p);
    int misses = 0;
    for (int r = 0; r < n; ++r) {
      BayesianInterval estimate(0.05, 0.95);
      while (!estimate.add(run(random))) {
      }
      EXPECT_GE(estimate.posterior(), 0.95);
      misses += p < estimate.interval().low || p > estimate.interval().high;
    }
    // Under the uniform prior the coverage is Bayesian; the frequentist misses stay near 5%.
    EXPECT_LE(misses, slack_bound(n, 0.08)) << "p " << p;
  }
}

}  // namespace
}  // namespace smcbip::smc
