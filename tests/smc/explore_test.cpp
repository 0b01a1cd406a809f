// smc::explore_properties: sweeps with one guarantee for all their points. On the race of two
// exponentials (models/two_exponentials.bip) the first firing date is exponential of rate
// 0.15 per ms, so P(F[0,t] judge.CLOSED) = 1 - exp(-0.15 t) for every t: the DKW band must
// hold it at every t at once, which fails with probability at most alpha for a sound method
// (fixed seeds, so a given build passes or fails for good). The other tests compare runs that
// must be identical: a band against point-by-point PESTIM on the same runs, shared runs against
// runs of each point alone, one thread against two.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/smc/check_fixtures.h"

namespace smcbip::smc {
namespace {

using tests::check;
using tests::explore;

double first_firing_by(double t) { return 1 - std::exp(-0.15 * t); }

TEST(Sweep, BandHoldsTheDistributionOfTheFirstFiring) {
  CheckOptions options;
  options.delta = 0.01;
  options.alpha = 0.01;
  options.seed = 29;
  options.threads = 2;
  const auto results = explore("two_exponentials.bip",
                               "param t = 0:40:2\n"
                               "P=? [ F[0,t] judge.CLOSED ]\n"
                               "P=? [ G[0,t] !judge.CLOSED ]\n",
                               options);
  ASSERT_EQ(results.size(), 42u);
  const std::uint64_t n = chernoff_samples(0.01, 0.01);
  const double epsilon = dkw_half_width(n, 0.01);
  EXPECT_LE(epsilon, 0.01);
  for (const QueryResult& r : results) {
    const double t = r.parameters.at("t");
    const double exact = r.query == 0 ? first_firing_by(t) : 1 - first_firing_by(t);
    EXPECT_EQ(r.method, Method::Band);
    EXPECT_EQ(r.samples, n);
    EXPECT_EQ(r.undecided, 0u);
    EXPECT_NEAR(r.estimate, exact, epsilon) << "query " << r.query << ", t = " << t;
    EXPECT_LE(r.ci.low, exact);
    EXPECT_GE(r.ci.high, exact);
  }
}

TEST(Sweep, BandJudgesTheSameRunsAsPointByPointEstimates) {
  // One critical bound per run against one monitor per value of t, on the same numbered runs.
  const std::string queries =
      "param t = 0:100:5\n"
      "P=? [ F[0,t] Channel.id_channel > 2 ]\n"
      "P=? [ G[0,t] Channel.lost == 0 ]\n"
      "P=? [ F[0,t] (Channel.lost > 0 && F[0,20] Channel.id_channel > 3) ]\n";
  CheckOptions options;
  options.delta = 0.03;
  options.seed = 4;
  options.threads = 2;
  const auto band = explore("channel.bip", queries, options);
  options.method = Method::Pestim;
  const auto points = check("channel.bip", queries, options);
  ASSERT_EQ(band.size(), points.size());
  for (std::size_t i = 0; i < band.size(); ++i) {
    EXPECT_EQ(band[i].method, Method::Band);
    EXPECT_EQ(band[i].parameters, points[i].parameters);
    EXPECT_EQ(band[i].samples, points[i].samples);
    EXPECT_EQ(band[i].estimate, points[i].estimate)
        << "query " << band[i].query << ", t = " << band[i].parameters.at("t");
  }
}

TEST(Sweep, HypothesesOverABandAreRightOutsideTheIndifferenceRegion) {
  CheckOptions options;
  options.delta = 0.02;
  options.alpha = 0.01;
  options.beta = 0.02;
  options.seed = 8;
  options.threads = 2;
  const auto results = explore("two_exponentials.bip",
                               "param t = 1:20:1\nP>=0.8 [ F[0,t] judge.CLOSED ]\n", options);
  ASSERT_EQ(results.size(), 20u);
  for (const QueryResult& r : results) {
    EXPECT_EQ(r.alpha, 0.01);  // the smaller of alpha and beta
    const double p = first_firing_by(r.parameters.at("t"));
    if (p >= 0.8 + options.delta) {
      EXPECT_EQ(r.verdict, std::optional<bool>(true)) << p;
    } else if (p <= 0.8 - options.delta) {
      EXPECT_EQ(r.verdict, std::optional<bool>(false)) << p;
    }
  }
}

TEST(Sweep, GridsSplitAlphaOverTheirPoints) {
  // The die's six faces, each 1/6: not monotone in k, so PESTIM at alpha / 6 for each.
  CheckOptions options;
  options.delta = 0.02;
  options.alpha = 0.06;
  options.seed = 12;
  options.threads = 2;
  const auto results =
      explore("knuth_yao.bip",
              "param k = {1, 2, 3, 4, 5, 6}\nP=? [ F (die.s == 7 && die.d == k) ]\n", options);
  ASSERT_EQ(results.size(), 6u);
  for (const QueryResult& r : results) {
    EXPECT_EQ(r.method, Method::Pestim);
    EXPECT_EQ(r.split, 6u);
    EXPECT_DOUBLE_EQ(r.alpha, 0.01);
    EXPECT_EQ(r.samples, chernoff_samples(0.02, 0.01));
    EXPECT_NEAR(r.estimate, 1.0 / 6.0, 0.02) << "face " << r.parameters.at("k");
  }
}

TEST(Sweep, SharedRunsGiveEachPointTheAnswerItGetsAlone) {
  // Sequential tests stop at different runs for different points; sharing runs must not
  // change what any point sees.
  CheckOptions options;
  options.delta = 0.02;
  options.seed = 21;
  options.threads = 2;
  const auto shared =
      check("knuth_yao.bip",
            "param k = {1, 2, 3, 4, 5, 6}\nP>=0.15 [ F (die.s == 7 && die.d <= k) ]\n", options);
  ASSERT_EQ(shared.size(), 6u);
  for (int k = 1; k <= 6; ++k) {
    const auto alone =
        check("knuth_yao.bip", "P>=0.15 [ F (die.s == 7 && die.d <= " + std::to_string(k) + ") ]\n",
              options);
    EXPECT_EQ(alone.at(0).samples, shared[k - 1].samples) << "k = " << k;
    EXPECT_EQ(alone.at(0).estimate, shared[k - 1].estimate);
    EXPECT_EQ(alone.at(0).verdict, shared[k - 1].verdict);
  }
}

TEST(Sweep, ThreadCountsGiveTheSameSweeps) {
  const std::string queries =
      "param t = 0:100:10\nparam k = 1:4:1\n"
      "P=? [ F[0,t] Channel.id_channel > 2 ]\n"
      "P>=0.5 [ F[0,100] Channel.id_channel >= k ]\n"
      "E[<=t; 40](max: Sender.sent)\n";
  CheckOptions options;
  options.delta = 0.03;
  options.seed = 2;
  options.threads = 1;
  const auto one = explore("channel.bip", queries, options);
  options.threads = 2;
  const auto two = explore("channel.bip", queries, options);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].samples, two[i].samples);
    EXPECT_EQ(one[i].estimate, two[i].estimate);
    EXPECT_EQ(one[i].verdict, two[i].verdict);
  }
}

}  // namespace
}  // namespace smcbip::smc
