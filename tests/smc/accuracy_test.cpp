// smc::check_properties against probabilities derived by hand, one family of dates per model in
// tests/smc/models/ (each model's header works its values out): uniform windows racing, sums of
// delays (Erlang, gamma, Irwin-Hall) and normal dates racing deadlines. Races of exponentials
// are in check_test.cpp. Every estimate is PESTIM's, within delta = 0.005 of the true value with
// probability 1 - alpha = 0.99: for a sound method and engine each EXPECT_NEAR below fails with
// probability at most alpha, the file's eight at most 8% (the seeds are fixed, so a given build
// passes or fails for good).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "smc/smc.h"
#include "tests/smc/check_fixtures.h"

namespace smcbip::smc {
namespace {

constexpr double kDelta = 0.005;
constexpr double kAlpha = 0.01;

const bipc::ir::System& model(const std::string& file) {
  return tests::model_in("tests/smc/models", file);
}

/// The answers to `queries` on `file` by PESTIM at kDelta, kAlpha, each checked to have its
/// full sample count and no undecided run, so that only the estimates are left to compare.
std::vector<QueryResult> estimate(const std::string& file, const std::string& queries,
                                  std::uint64_t seed) {
  const monitors::PropertyFile properties = tests::properties(queries, model(file));
  CheckOptions options;
  options.method = Method::Pestim;
  options.delta = kDelta;
  options.alpha = kAlpha;  // 105,967 runs per query
  options.seed = seed;
  options.threads = 2;
  std::vector<QueryResult> results = check_properties(model(file), properties, options);
  for (const QueryResult& r : results) {
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.method, Method::Pestim);
    EXPECT_EQ(r.samples, chernoff_samples(kDelta, kAlpha));
    EXPECT_EQ(r.undecided, 0u);
  }
  return results;
}

/// The standard normal CDF.
double phi(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

/// P(X < d) for X normal(mu, sd) conditioned on X > 0.
double truncated_normal_below(double mu, double sd, double d) {
  const double at_zero = phi(-mu / sd);
  return (phi((d - mu) / sd) - at_zero) / (1 - at_zero);
}

/// P(S <= t) for S the sum of k exponential delays of rate `rate`.
double erlang_cdf(int k, double rate, double t) {
  double term = std::exp(-rate * t);  // e^-rt (rt)^i / i!, from i = 0
  double below = 0;
  for (int i = 0; i < k; ++i) {
    below += term;
    term *= rate * t / (i + 1);
  }
  return 1 - below;
}

/// P(S <= x) for S the sum of n uniform delays on [0, 1] (Irwin-Hall), for 0 <= x <= n:
/// sum over j <= x of (-1)^j C(n, j) (x - j)^n / n!.
double irwin_hall_cdf(int n, double x) {
  double sum = 0;
  double binomial = 1;  // C(n, j)
  for (int j = 0; j <= n && j <= x; ++j) {
    sum += (j % 2 == 0 ? 1 : -1) * binomial * std::pow(x - j, n);
    binomial = binomial * (n - j) / (j + 1);
  }
  return sum / std::tgamma(n + 1);
}

TEST(Accuracy, UniformWindowsRacing) {
  // a on [0, 10] ms against b on [5, 20] ms: b wins only from [5, 10], with probability
  // integral over [5, 10] of (1/15) (10 - y)/10 dy = 1/12.
  const auto results = estimate("uniform_windows.bip",
                                "P=? [ F judge.winner == 1 ]\n"
                                "P=? [ F[0,7] judge.CLOSED ]\n"
                                "P=? [ F[0,12] b.DONE ]\n",
                                21);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_NEAR(results[0].estimate, 11.0 / 12.0, kDelta);
  // Nobody has fired by 7 ms when both dates are later.
  EXPECT_NEAR(results[1].estimate, 1 - (3.0 / 10.0) * (13.0 / 15.0), kDelta);
  // b keeps its law whether it wins or fires alone after a.
  EXPECT_NEAR(results[2].estimate, 7.0 / 15.0, kDelta);
}

TEST(Accuracy, SumsOfDelays) {
  const auto results = estimate("stages.bip",
                                "P=? [ F[0,6] erlang.n == 3 ]\n"
                                "P=? [ F[0,6] gamma.n == 3 ]\n"
                                "P=? [ F[0,12] irwin_hall.n == 3 ]\n",
                                22);
  ASSERT_EQ(results.size(), 3u);
  // Three exponential stages of mean 2 ms, and the one gamma(3, 2) stage of the same law.
  EXPECT_NEAR(results[0].estimate, erlang_cdf(3, 0.5, 6), kDelta);
  EXPECT_NEAR(results[1].estimate, erlang_cdf(3, 0.5, 6), kDelta);
  // Three uniform stages on [0, 10] ms: 12 ms is 1.2 on Irwin-Hall's scale.
  EXPECT_NEAR(results[2].estimate, irwin_hall_cdf(3, 1.2), kDelta);
}

TEST(Accuracy, NormalDatesRacingDeadlines) {
  const auto results = estimate("normal_deadlines.bip",
                                "P=? [ F on_time.DONE ]\n"
                                "P=? [ F early.DONE ]\n",
                                23);
  ASSERT_EQ(results.size(), 2u);
  // normal(10, 2) against 11 ms: the mass below 0 is Phi(-5) < 3e-7, so this is Phi(0.5).
  EXPECT_NEAR(results[0].estimate, phi((11.0 - 10.0) / 2.0), kDelta);
  // normal(2, 4) against 4 ms, conditioned on a date after 0: about 0.554, where clamping
  // negative dates to 0 would give Phi(0.5), about 0.691.
  EXPECT_NEAR(results[1].estimate, truncated_normal_below(2, 4, 4), kDelta);
}

}  // namespace
}  // namespace smcbip::smc
