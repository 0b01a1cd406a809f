// The run counts and pilot behind `smcbip check --compile auto` (smc/tools/run_time_estimate.h).
#include "smc/tools/run_time_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "smc/stats/sampling_plans.h"
#include "smc/stats/sprt.h"
#include "tests/smc/check_fixtures.h"

namespace smcbip::smc {
namespace {

using tools::expected_runs;

const bipc::ir::System& knuth_yao() { return tests::model_in("models", "knuth_yao.bip"); }

std::uint64_t runs_of(const std::string& query, const CheckOptions& options, bool explore,
                      bool& sequential) {
  const monitors::PropertyFile file = tests::properties(query, knuth_yao());
  return expected_runs(file, file.queries.at(0), options, explore, sequential);
}

/// The SPRT's mean sample number over `tests` tests on runs that hold with probability p.
double sprt_mean_samples(double p, double theta, const CheckOptions& o, int tests) {
  std::mt19937_64 random(7);
  std::bernoulli_distribution run(p);
  double total = 0;
  for (int t = 0; t < tests; ++t) {
    Sprt sprt(theta, o.delta, o.alpha, o.beta);
    while (sprt.add(run(random)) == Decision::Undecided) {
    }
    total += static_cast<double>(sprt.samples());
  }
  return total / tests;
}

TEST(RunTimeEstimate, SprtCountIsItsLargestAverageSampleNumber) {
  // Wald's E[N] = -ab/E[Z^2] holds where a run's expected log-ratio step is 0, and neglects
  // the overshoot of the thresholds: 2,000 simulated tests at that p must average within 15%
  // of it (their standard error is about 2%), and fewer runs away from it.
  CheckOptions o;
  o.delta = 0.05;
  bool sequential = false;
  const double estimate =
      static_cast<double>(runs_of("P>=0.3 [ F die.s == 7 ]\n", o, false, sequential));
  EXPECT_TRUE(sequential);
  const double p0 = 0.35, p1 = 0.25;
  const double on_success = std::log(p1 / p0), on_failure = std::log((1 - p1) / (1 - p0));
  const double slowest = on_failure / (on_failure - on_success);
  const double simulated = sprt_mean_samples(slowest, 0.3, o, 2000);
  EXPECT_NEAR(estimate, simulated, 0.15 * simulated);
  EXPECT_LT(sprt_mean_samples(0.5, 0.3, o, 2000), 0.5 * estimate);
}

TEST(RunTimeEstimate, FixedSizeMethodsCountTheirRuns) {
  CheckOptions o;
  bool sequential = false;
  EXPECT_EQ(runs_of("P=? [ F die.s == 7 ]\n", o, false, sequential), chernoff_samples(0.01, 0.05));
  o.method = Method::Ssp;
  EXPECT_EQ(runs_of("P>=0.3 [ F die.s == 7 ]\n", o, false, sequential),
            single_sampling_plan(0.3, 0.01, 0.05, 0.05).n);
  EXPECT_EQ(runs_of("E[<=100; 700](max: die.s)\n", o, false, sequential), 700u);
  EXPECT_FALSE(sequential);
  // A sweep's points share their runs: check counts one point's, explore splits alpha.
  o.method = Method::Pestim;
  const std::string sweep = "param k = {1, 2, 3, 4, 5, 6}\nP=? [ F (die.s == 7 && die.d == k) ]\n";
  EXPECT_EQ(runs_of(sweep, o, false, sequential), chernoff_samples(0.01, 0.05));
  EXPECT_EQ(runs_of(sweep, o, true, sequential), chernoff_samples(0.01, 0.05 / 6));
  EXPECT_EQ(runs_of("A[] die.s >= 0\n", o, false, sequential), 0u);
}

TEST(RunTimeEstimate, PilotTimesRunsOfTheFirstQuery) {
  const monitors::PropertyFile file =
      tests::properties("A[] die.s >= 0\nP=? [ F die.s == 7 ]\n", knuth_yao());
  CheckOptions o;
  o.delta = 0.05;
  o.threads = 2;
  const tools::RunTimeEstimate estimate = tools::estimate_run_time(knuth_yao(), file, o, false);
  EXPECT_EQ(estimate.runs, chernoff_samples(0.05, 0.05));
  EXPECT_GT(estimate.run_seconds, 0);
  EXPECT_DOUBLE_EQ(estimate.seconds, estimate.run_seconds * static_cast<double>(estimate.runs) / 2);
  // No query that makes runs: nothing to time.
  const monitors::PropertyFile exact = tests::properties("A[] die.s >= 0\n", knuth_yao());
  EXPECT_EQ(tools::estimate_run_time(knuth_yao(), exact, o, false).seconds, 0);
}

}  // namespace
}  // namespace smcbip::smc
