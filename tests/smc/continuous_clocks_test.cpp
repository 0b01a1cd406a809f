// smc::check_properties on clocks read continuously, against values derived by hand on
// tests/smc/models/clock_reset.bip (its header works them out): predicates over clocks change
// truth at their crossing times, between steps and after a deadlock, and expectations follow
// the clocks between steps. Probabilities are PESTIM's, within delta = 0.01 of the true value
// with probability 1 - alpha = 0.99; expectations' intervals hold their value with probability
// 0.99. The seeds are fixed, so a given build passes or fails for good; a sound monitor fails
// each check with probability at most 0.01.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "smc/smc.h"
#include "tests/smc/check_fixtures.h"

namespace smcbip::smc {
namespace {

constexpr double kDelta = 0.01;
constexpr double kAlpha = 0.01;

std::vector<QueryResult> answers(const std::string& queries, std::uint64_t seed) {
  const bipc::ir::System& system = tests::model_in("tests/smc/models", "clock_reset.bip");
  CheckOptions options;
  options.method = Method::Pestim;
  options.delta = kDelta;
  options.alpha = kAlpha;
  options.confidence = 1 - kAlpha;
  options.seed = seed;
  options.threads = 2;
  std::vector<QueryResult> results =
      check_properties(system, tests::properties(queries, system), options);
  for (const QueryResult& r : results) {
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.undecided, 0u);
  }
  return results;
}

/// The expectation of g(T) over T exponential of mean 1 ms, for g constant beyond 4 ms:
/// Simpson's rule on [0, 4] (exact to far below the intervals' widths) plus g(4) e^-4.
double expectation(const std::function<double(double)>& g) {
  constexpr int kIntervals = 20000;  // even
  constexpr double kEnd = 4, kStep = kEnd / kIntervals;
  double sum = g(0) + g(kEnd) * std::exp(-kEnd);
  for (int i = 1; i < kIntervals; ++i) {
    const double t = i * kStep;
    sum += (i % 2 == 1 ? 4 : 2) * g(t) * std::exp(-t);
  }
  return sum * kStep / 3 + g(kEnd) * std::exp(-kEnd);
}

TEST(ContinuousClocks, PredicatesChangeTruthAtTheirCrossingTimes) {
  const auto results = answers(
      "P=? [ F[0,4] (r.s1 && r.y >= 3) ]\n"
      "P=? [ F[0,1] r.x > 0.5 ]\n"
      "P=? [ G[0,2] r.x - r.y < 1 ]\n"
      "P=? [ F[0,3] r.x >= 2 && r.s0 ]\n",
      31);
  ASSERT_EQ(results.size(), 4u);
  // Read at steps only, the first would be 0 (y is 0 at the only step after the reset) and
  // the second 1 - e^-1 (x read at the step of `go`).
  EXPECT_NEAR(results[0].estimate, 1 - std::exp(-1.0), kDelta);
  EXPECT_EQ(results[1].estimate, 1.0);
  EXPECT_NEAR(results[2].estimate, 1 - std::exp(-1.0) + std::exp(-2.0), kDelta);
  EXPECT_NEAR(results[3].estimate, std::exp(-2.0), kDelta);
}

TEST(ContinuousClocks, ADeadlockAtARandomDateHoldsFromThenOnWhileClocksGrow) {
  const auto results = answers(
      "P=? [ F[0,2] deadlock ]\n"
      "P=? [ F[0,2] (deadlock && r.y >= 0.5) ]\n"
      "P=? [ F[0,2] \"deadlock\" ]\n"
      "P=? [ G[0,2] !deadlock ]\n",
      32);
  ASSERT_EQ(results.size(), 4u);
  EXPECT_NEAR(results[0].estimate, 1 - std::exp(-2.0), kDelta);
  EXPECT_NEAR(results[1].estimate, 1 - std::exp(-1.5), kDelta);
  EXPECT_NEAR(results[2].estimate, 1 - std::exp(-2.0), kDelta);
  EXPECT_NEAR(results[3].estimate, std::exp(-2.0), kDelta);
}

TEST(ContinuousClocks, ExpectationsFollowTheClocksBetweenSteps) {
  const auto results = answers(
      "E[<=4; 20000](last: r.y)\n"
      "E[<=4; 20000](max: r.y)\n"
      "E[<=4; 20000](int: r.y)\n"
      "E[<=4; 20000](count: fired(r.go))\n"
      "E[<=4; 20000](min: r.x - r.y)\n",
      33);
  ASSERT_EQ(results.size(), 5u);
  const double last = 3 + 5 * std::exp(-4.0);
  const double max = expectation([](double t) { return t < 4 ? std::max(t, 4 - t) : 4; });
  const double integral =
      expectation([](double t) { return t < 4 ? t * t / 2 + (4 - t) * (4 - t) / 2 : 8; });
  const double count = 1 - std::exp(-4.0);
  const double expected[] = {last, max, integral, count, 0};
  for (std::size_t i = 0; i < results.size(); ++i) {
    EXPECT_LE(results[i].ci.low, expected[i]) << "query " << i;
    EXPECT_GE(results[i].ci.high, expected[i]) << "query " << i;
    EXPECT_EQ(results[i].samples, 20000u) << "query " << i;
  }
}

TEST(ContinuousClocks, ComparesTwoProbabilitiesOnTheSameRuns) {
  // P(F[0,2] r.s1) = 1 - e^-2 (0.86) against P(G[0,1] r.s0) = e^-1 (0.37): the paired SPRT
  // (delta 0.01 around 1/2 for the share of runs where only the left one holds, here
  // (0.86 - 0.37) / (1 - 0.37 + ...) far above) decides for the left at alpha = beta = 0.01.
  const bipc::ir::System& system = tests::model_in("tests/smc/models", "clock_reset.bip");
  CheckOptions options;
  options.alpha = options.beta = 0.01;
  options.seed = 35;
  options.threads = 2;
  const auto results = check_properties(system,
                                        tests::properties("Pr[<=2](F r.s1) >= Pr[<=1](G r.s0)\n"
                                                          "Pr[<=2](F r.s1) < Pr[<=1](G r.s0)\n"
                                                          "Pr[<=1](G r.s0) > Pr[<=2](F r.s1)\n",
                                                          system),
                                        options);
  ASSERT_EQ(results.size(), 3u);
  for (const QueryResult& r : results) {
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.method, Method::Paired);
    ASSERT_TRUE(r.verdict.has_value());
  }
  EXPECT_TRUE(*results[0].verdict);
  EXPECT_FALSE(*results[1].verdict);
  EXPECT_FALSE(*results[2].verdict);
  // The estimate is the difference of the two estimates on the runs made.
  EXPECT_NEAR(results[0].estimate, 1 - std::exp(-2.0) - std::exp(-1.0), 0.25);
}

TEST(ContinuousClocks, SimulateFollowsTheExpressionsToTheBound) {
  // Each run: y grows from 0, is reset at T (the time of the point where x - y jumps to T),
  // and grows again after the deadlock up to 4 ms, where y = 4 - T.
  const bipc::ir::System& system = tests::model_in("tests/smc/models", "clock_reset.bip");
  CheckOptions options;
  options.seed = 36;
  const auto results = check_properties(
      system, tests::properties("simulate [<=4; 20] { r.y, r.x - r.y }\n", system), options);
  ASSERT_EQ(results.size(), 1u);
  ASSERT_TRUE(results[0].trajectories);
  const Trajectories& t = *results[0].trajectories;
  EXPECT_EQ(t.series, (std::vector<std::string>{"r.y", "r.x - r.y"}));
  ASSERT_EQ(t.runs.size(), 20u);
  for (const auto& run : t.runs) {
    ASSERT_GE(run.size(), 2u);
    EXPECT_EQ(run.front(), (std::vector<double>{0, 0, 0}));
    const std::vector<double>& end = run.back();
    EXPECT_DOUBLE_EQ(end[0], 4);
    const double reset = end[2];  // x - y after the reset is T
    if (reset > 0) {
      EXPECT_NEAR(end[1], 4 - reset, 1e-9);
    } else {
      EXPECT_NEAR(end[1], 4, 1e-9);  // no reset within 4 ms
    }
    for (std::size_t i = 1; i < run.size(); ++i) EXPECT_LE(run[i - 1][0], run[i][0]);
  }
}

TEST(ContinuousClocks, KeepsWhenPhiFirstHeldForThePlot) {
  // F (r.s1 && r.y >= 1) first holds at T + 1 (T exponential of mean 1 ms): every first time
  // lies in [1, 4], and the share of runs where it came by 2 ms is P(T <= 1) = 1 - e^-1, within
  // delta = 0.01 with probability 0.99 (Hoeffding, the 26,492 runs of PESTIM at these settings).
  const bipc::ir::System& system = tests::model_in("tests/smc/models", "clock_reset.bip");
  CheckOptions options;
  options.method = Method::Pestim;
  options.delta = kDelta;
  options.alpha = kAlpha;
  options.seed = 37;
  options.threads = 2;
  options.first_hits = true;
  const auto results = check_properties(
      system, tests::properties("Pr[<=4](<> r.s1 && r.y >= 1)\n", system), options);
  ASSERT_EQ(results.size(), 1u);
  const QueryResult& r = results[0];
  EXPECT_EQ(r.first_hit_horizon, 4.0);
  ASSERT_EQ(r.first_hits.size(), static_cast<std::size_t>(r.estimate * r.samples + 0.5));
  std::size_t by_two = 0;
  for (double t : r.first_hits) {
    EXPECT_GE(t, 1.0);
    EXPECT_LE(t, 4.0);
    by_two += t <= 2.0;
  }
  EXPECT_NEAR(static_cast<double>(by_two) / static_cast<double>(r.samples), 1 - std::exp(-1.0),
              kDelta);
}

TEST(ContinuousClocks, PrismsSpellingsOfTheDieReadAsPrismReadsThem) {
  // P=? [ F s=7 & d=1 ] is F (s=7 & d=1) in PRISM: 1/6 (models/knuth_yao.bip).
  CheckOptions options;
  options.method = Method::Pestim;
  options.delta = 0.02;
  options.alpha = 0.01;
  options.seed = 34;
  options.threads = 2;
  const auto results = tests::check("knuth_yao.bip",
                                    "P=? [ F die.s=7 & die.d=1 ]\n"
                                    "P=? [ <> die.s == 7 and die.d == 1 ]\n",
                                    options);
  ASSERT_EQ(results.size(), 2u);
  for (const QueryResult& r : results) EXPECT_NEAR(r.estimate, 1.0 / 6.0, 0.02);
}

}  // namespace
}  // namespace smcbip::smc
