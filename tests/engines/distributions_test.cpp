// Tests of the random streams and firing-date distributions of the stochastic engine.
//
// Goodness of fit: one-sample Kolmogorov-Smirnov tests (see kolmogorov.h), n = 10,000 samples
// from a fixed seed, significance alpha = 0.001. With fixed seeds each test is deterministic; a
// correct sampler fails a given one with probability 0.001 over the choice of seed.
#include "engines/stochastic/distributions.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "engines/stochastic/random_stream.h"
#include "kolmogorov.h"

namespace smcbip::engines {
namespace {

namespace fs = std::filesystem;
using bipc::ir::Distribution;

static_assert(std::uniform_random_bit_generator<RandomStream>);

constexpr std::size_t kSamples = 10000;
const double kKolmogorovCritical = tests::kolmogorov_critical();
using tests::kolmogorov_statistic;

DateDistribution make(Distribution kind, std::vector<double> params,
                      const EmpiricalCdf* custom = nullptr) {
  auto made = DateDistribution::make(kind, params, custom);
  if (const auto* error = std::get_if<std::string>(&made)) throw std::runtime_error(*error);
  return std::get<DateDistribution>(made);
}

std::string make_error(Distribution kind, std::vector<double> params,
                       const EmpiricalCdf* custom = nullptr) {
  auto made = DateDistribution::make(kind, params, custom);
  const auto* error = std::get_if<std::string>(&made);
  return error == nullptr ? std::string("(accepted)") : *error;
}

// A fresh directory per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() / ("smcbip_distributions_" + std::string(info->name()) + "_" +
                                         std::to_string(std::random_device{}()));
    fs::create_directories(root_);
  }
  ~TempDir() { fs::remove_all(root_); }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path path = root_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

 private:
  fs::path root_;
};

EmpiricalCdf load_cdf(const std::string& path) {
  auto loaded = EmpiricalCdf::load(path);
  if (const auto* error = std::get_if<std::string>(&loaded)) throw std::runtime_error(*error);
  return std::get<EmpiricalCdf>(std::move(loaded));
}

// The test CDF of `custom`: continuous (first cdf 0), three segments of different slopes.
constexpr const char* kCustomCdfText =
    "# response time of the radio link, in ms\n"
    "2.0 0.0\n"
    "3.0, 0.25\n"
    "\n"
    "5.0\t0.75   # the bulk\n"
    "10.0 1.0\n";

// ---------------------------------------------------------------------------------------------
// RandomStream

TEST(RandomStream, SameSeedAndRunGiveTheSameSequence) {
  RandomStream a(20240611, 7);
  RandomStream b(20240611, 7);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.next_u64(), b.next_u64()) << "draw " << i;
}

// Known answers: a change of the generator silently changes every recorded trace, so it must
// show up here (update these only on purpose).
TEST(RandomStream, KnownAnswers) {
  RandomStream r(42, 0);
  const std::uint64_t first = r.next_u64();
  const std::uint64_t second = r.next_u64();
  EXPECT_EQ(first, 3049041522653517529u);
  EXPECT_EQ(second, 13502985542161943348u);
  EXPECT_EQ(RandomStream(42, 1).next_u64(), 17322283105884714868u);
}

TEST(RandomStream, DifferentRunsAndSeedsDiffer) {
  // Equal 64-bit draws at the same position happen with probability 1000·2^-64 by chance.
  RandomStream run0(1, 0);
  RandomStream run1(1, 1);
  RandomStream other_seed(2, 0);
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t x = run0.next_u64();
    ASSERT_NE(x, run1.next_u64()) << "draw " << i;
    ASSERT_NE(x, other_seed.next_u64()) << "draw " << i;
  }
}

TEST(RandomStream, IndependentOfCreationOrderAndThread) {
  constexpr std::uint64_t kSeed = 99;
  constexpr int kRuns = 8;
  constexpr int kDraws = 100;
  std::vector<std::vector<std::uint64_t>> forward(kRuns);
  for (int run = 0; run < kRuns; ++run) {
    RandomStream r(kSeed, run);
    for (int i = 0; i < kDraws; ++i) forward[run].push_back(r.next_u64());
  }
  // Created in reverse order, drawn interleaved.
  std::vector<RandomStream> streams;
  for (int run = kRuns - 1; run >= 0; --run) streams.emplace_back(kSeed, run);
  for (int i = 0; i < kDraws; ++i) {
    for (int k = 0; k < kRuns; ++k) {
      ASSERT_EQ(streams[k].next_u64(), forward[kRuns - 1 - k][i]);
    }
  }
  // Drawn on other threads.
  std::vector<std::vector<std::uint64_t>> threaded(kRuns);
  std::vector<std::thread> threads;
  for (int run = 0; run < kRuns; ++run) {
    threads.emplace_back([&threaded, run] {
      RandomStream r(kSeed, run);
      for (int i = 0; i < kDraws; ++i) threaded[run].push_back(r.next_u64());
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(threaded, forward);
}

TEST(RandomStream, DiscardSkipsDraws) {
  RandomStream a(5, 3);
  RandomStream b(5, 3);
  for (int i = 0; i < 10; ++i) a.next_u64();
  b.discard(10);
  EXPECT_EQ(a.draws(), 10u);
  EXPECT_EQ(b.draws(), 10u);
  EXPECT_EQ(a.next_u64(), b.next_u64());
}

TEST(RandomStream, Uniform01IsOpenAndFitsTheUniformLaw) {
  RandomStream r(11, 0);
  std::vector<double> u(kSamples);
  for (double& x : u) {
    x = r.uniform01_open();
    ASSERT_GT(x, 0.0);
    ASSERT_LT(x, 1.0);
  }
  EXPECT_LT(kolmogorov_statistic(u, [](double x) { return x; }), kKolmogorovCritical);
}

TEST(RandomStream, BelowIsInRangeAndUnbiased) {
  // Pearson's chi-square over 6 cells, 60,000 draws: 5 degrees of freedom, critical value
  // 20.515 at alpha = 0.001 (chi-square table; gsl_cdf_chisq_Qinv(0.001, 5)).
  RandomStream r(12, 0);
  constexpr int kCells = 6;
  constexpr int kDraws = 60000;
  std::vector<int> counts(kCells, 0);
  for (int i = 0; i < kDraws; ++i) {
    const std::uint64_t k = r.below(kCells);
    ASSERT_LT(k, static_cast<std::uint64_t>(kCells));
    ++counts[k];
  }
  const double expected = static_cast<double>(kDraws) / kCells;
  double chi2 = 0.0;
  for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
  EXPECT_LT(chi2, gsl_cdf_chisq_Qinv(tests::kKsAlpha, kCells - 1));
  EXPECT_EQ(r.below(1), 0u);
  // A bound just above 2^63: half the 64-bit range is rejected, results stay below it.
  const std::uint64_t big = (std::uint64_t{1} << 63) + 12345;
  for (int i = 0; i < 100; ++i) ASSERT_LT(r.below(big), big);
}

/// Lemire's rule, written out: the high word of x·n for the first draw x whose low word is not
/// below 2^64 mod n.
std::uint64_t lemire_below(RandomStream& raw, std::uint64_t n) {
  __extension__ using Wide = unsigned __int128;
  const std::uint64_t threshold = (0 - n) % n;
  Wide product = Wide{raw.next_u64()} * n;
  while (static_cast<std::uint64_t>(product) < threshold) product = Wide{raw.next_u64()} * n;
  return static_cast<std::uint64_t>(product >> 64);
}

TEST(RandomStream, BelowIsTheHighWordOfTheFirstAcceptedProduct) {
  // below() skips the division unless the low word is below n: it must give Lemire's result
  // for bounds of every magnitude (1, powers of two and their neighbours, 2^64 - 1, where
  // rejection is frequent), and for bounds changing between draws.
  std::vector<std::uint64_t> bounds = {1, 2, 3, 5, 6, 7, 10, 500, 1000, 0xFFFFFFFFFFFFFFFFu};
  for (unsigned k = 1; k < 64; ++k) {
    const std::uint64_t power = std::uint64_t{1} << k;
    bounds.insert(bounds.end(), {power - 1, power, power + 1, power + power / 3});
  }
  RandomStream pick(21, 0);
  for (int i = 0; i < 200; ++i) bounds.push_back((pick.next_u64() >> (pick.next_u64() % 64)) | 1);
  for (const std::uint64_t n : bounds) {
    RandomStream drawn(22, n), raw(22, n);
    for (int i = 0; i < 50; ++i) {
      ASSERT_EQ(drawn.below(n), lemire_below(raw, n)) << "n = " << n << ", draw " << i;
    }
    EXPECT_EQ(drawn.draws(), raw.draws()) << "n = " << n;
  }
  RandomStream alternating(23, 0), raw(23, 0);
  for (std::uint64_t i = 1; i < 2000; ++i) {
    const std::uint64_t n = i % 2 == 0 ? i : (std::uint64_t{1} << 63) + i;
    ASSERT_EQ(alternating.below(n), lemire_below(raw, n)) << "n = " << n;
  }
}

TEST(RandomStream, DrivesStandardDistributions) {
  RandomStream r(13, 0);
  std::uniform_int_distribution<int> die(1, 6);
  for (int i = 0; i < 100; ++i) {
    const int x = die(r);
    ASSERT_GE(x, 1);
    ASSERT_LE(x, 6);
  }
}

// ---------------------------------------------------------------------------------------------
// Goodness of fit of sample(): each distribution against its GSL CDF.

struct FitCase {
  const char* name;
  Distribution kind;
  std::vector<double> params;
  std::function<double(double)> reference;  // the CDF written independently, from GSL
};

std::vector<FitCase> fit_cases() {
  return {
      {"normal",
       Distribution::Normal,
       {10.0, 2.0},
       [](double x) { return gsl_cdf_gaussian_P(x - 10.0, 2.0); }},
      {"exponential",
       Distribution::Exponential,
       {3.0},
       [](double x) { return gsl_cdf_exponential_P(x, 3.0); }},
      {"gamma",
       Distribution::Gamma,
       {2.5, 1.5},
       [](double x) { return gsl_cdf_gamma_P(x, 2.5, 1.5); }},
      // Shape 0.2: GSL's gamma Pinv returns NaN over most of the lower tail, so this exercises
      // the checked-inverse fallback.
      {"gamma_small_shape",
       Distribution::Gamma,
       {0.2, 4.0},
       [](double x) { return gsl_cdf_gamma_P(x, 0.2, 4.0); }},
      {"chi2", Distribution::Chi2, {3.0}, [](double x) { return gsl_cdf_chisq_P(x, 3.0); }},
      {"uniform",
       Distribution::Uniform,
       {-1.0, 4.0},
       [](double x) { return gsl_cdf_flat_P(x, -1.0, 4.0); }},
      {"lognormal",
       Distribution::Lognormal,
       {1.0, 0.5},
       [](double x) { return gsl_cdf_lognormal_P(x, 1.0, 0.5); }},
      {"weibull",
       Distribution::Weibull,
       {2.0, 1.5},
       [](double x) { return gsl_cdf_weibull_P(x, 2.0, 1.5); }},
  };
}

TEST(DateDistribution, SamplesFitTheirCdf) {
  std::uint64_t run = 0;
  for (const FitCase& c : fit_cases()) {
    SCOPED_TRACE(c.name);
    const DateDistribution d = make(c.kind, c.params);
    RandomStream r(/*seed=*/1001, run++);
    std::vector<double> samples(kSamples);
    for (double& x : samples) x = d.sample(r);
    EXPECT_EQ(r.draws(), kSamples) << "one uniform per sample";
    EXPECT_LT(kolmogorov_statistic(samples, c.reference), kKolmogorovCritical);
    // The distribution's own cdf() agrees with the reference.
    for (double x : {samples[0], samples[1], samples[2]}) {
      EXPECT_NEAR(d.cdf(x), c.reference(x), 1e-12);
      EXPECT_NEAR(d.cdf(x) + d.survival(x), 1.0, 1e-12);
    }
  }
}

TEST(DateDistribution, CustomSamplesFitTheFileCdf) {
  TempDir dir;
  const EmpiricalCdf cdf = load_cdf(dir.write("link.cdf", kCustomCdfText));
  const DateDistribution d = make(Distribution::Custom, {}, &cdf);
  // The CDF written out by hand from kCustomCdfText.
  const auto reference = [](double x) {
    if (x < 2.0) return 0.0;
    if (x < 3.0) return 0.25 * (x - 2.0);
    if (x < 5.0) return 0.25 + 0.25 * (x - 3.0);
    if (x < 10.0) return 0.75 + 0.05 * (x - 5.0);
    return 1.0;
  };
  RandomStream r(/*seed=*/1002, 0);
  std::vector<double> samples(kSamples);
  for (double& x : samples) x = d.sample(r);
  EXPECT_LT(kolmogorov_statistic(samples, reference), kKolmogorovCritical);
}

// ---------------------------------------------------------------------------------------------
// Truncated sampling: X given X > c, against (F(x) - F(c)) / (1 - F(c)).

TEST(DateDistribution, TruncatedSamplesFitTheConditionalCdf) {
  std::uint64_t run = 0;
  for (const FitCase& c : fit_cases()) {
    const DateDistribution d = make(c.kind, c.params);
    for (double level : {0.5, 0.99}) {
      SCOPED_TRACE(std::string(c.name) + " above the " + std::to_string(level) + " quantile");
      const double lower = d.quantile(level);
      const double below = c.reference(lower);
      ASSERT_NEAR(below, level, 1e-9);
      RandomStream r(/*seed=*/2002, run++);
      std::vector<double> samples(kSamples);
      for (double& x : samples) {
        const std::optional<double> s = d.sample_above(lower, r);
        ASSERT_TRUE(s.has_value());
        ASSERT_GT(*s, lower);
        x = *s;
      }
      const auto conditional = [&](double x) { return (c.reference(x) - below) / (1.0 - below); };
      EXPECT_LT(kolmogorov_statistic(samples, conditional), kKolmogorovCritical);
    }
  }
}

TEST(DateDistribution, TruncationFarInTheUpperTail) {
  // Normal(0,1) above 10 (tail 7.6e-24, where 1 - F(c) is 0 in doubles). Every sample lies in
  // (10, 12) but with probability 1000·Q(12)/Q(10) = 2.3e-7. The excess X - c has mean
  // lambda - c and variance 1 + c·lambda - lambda², lambda = phi(c)/Q(c) the inverse Mills ratio
  // (truncated normal moments, Johnson & Kotz): 0.0981 and sd 0.0972, so the mean of 1000
  // excesses has standard error 0.0031; allow 4 of them.
  const DateDistribution normal = make(Distribution::Normal, {0.0, 1.0});
  const double c = 10.0;
  const double lambda = gsl_ran_ugaussian_pdf(c) / gsl_cdf_ugaussian_Q(c);
  const double excess_sd = std::sqrt(1.0 + c * lambda - lambda * lambda);
  RandomStream r(/*seed=*/3003, 0);
  constexpr int kDraws = 1000;
  double sum = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const std::optional<double> x = normal.sample_above(c, r);
    ASSERT_TRUE(x.has_value());
    ASSERT_GT(*x, c);
    ASSERT_LT(*x, 12.0);
    sum += *x - c;
  }
  EXPECT_NEAR(sum / kDraws, lambda - c, 4.0 * excess_sd / std::sqrt(kDraws));

  // Gamma far in its tail: exercises the checked upper inverse.
  const DateDistribution gamma = make(Distribution::Gamma, {3.0, 1.0});
  for (int i = 0; i < 100; ++i) {
    const std::optional<double> x = gamma.sample_above(200.0, r);
    ASSERT_TRUE(x.has_value());
    ASSERT_GT(*x, 200.0);
    ASSERT_LT(*x, 230.0);  // P(X > 230 | X > 200) = 1.2e-13
  }
}

TEST(DateDistribution, TruncationBelowTheSupportIsNoTruncation) {
  const DateDistribution d = make(Distribution::Exponential, {2.0});
  RandomStream a(4004, 0);
  RandomStream b(4004, 0);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(d.sample_above(-5.0, a), d.sample(b));
}

TEST(DateDistribution, DrawsAboveTheTruncationAreTheUntruncatedOnes) {
  // A truncation in the lower tail (F(5) = 0.0062 for normal(10, 2)) keeps every plain draw
  // above it and asks for the masses only for the others, which it draws again above 5.
  const DateDistribution d = make(Distribution::Normal, {10.0, 2.0});
  RandomStream truncated(4005, 0), plain(4005, 0);
  int asked = 0, redrawn = 0;
  for (int i = 0; i < 10000; ++i) {
    const double x = d.sample(plain);
    const std::optional<double> y = d.sample_above(5.0, truncated, [&] {
      ++asked;
      return d.masses(5.0);
    });
    ASSERT_TRUE(y.has_value());
    ASSERT_GT(*y, 5.0);
    if (x > 5.0) {
      ASSERT_EQ(*y, x);
    } else {
      ++redrawn;
    }
  }
  EXPECT_EQ(asked, redrawn);
  EXPECT_GT(redrawn, 0);
}

TEST(DateDistribution, MissedSupportIsNullopt) {
  RandomStream r(5005, 0);
  EXPECT_FALSE(make(Distribution::Uniform, {0.0, 1.0}).sample_above(2.0, r));
  EXPECT_FALSE(make(Distribution::Uniform, {0.0, 1.0}).sample_above(1.0, r));
  EXPECT_FALSE(make(Distribution::Normal, {0.0, 1.0}).sample_above(40.0, r));  // tail < 1e-300
  EXPECT_FALSE(make(Distribution::Exponential, {1.0}).sample_above(1e4, r));
  TempDir dir;
  const EmpiricalCdf cdf = load_cdf(dir.write("c.cdf", kCustomCdfText));
  EXPECT_FALSE(make(Distribution::Custom, {}, &cdf).sample_above(10.0, r));
  EXPECT_EQ(r.draws(), 5u) << "a refused truncation draws its one uniform";
  EXPECT_TRUE(make(Distribution::Uniform, {0.0, 1.0}).sample_above(0.999, r));
}

TEST(DateDistribution, SamplesAreReproducible) {
  const DateDistribution d = make(Distribution::Gamma, {0.5, 2.0});
  RandomStream a(6006, 17);
  RandomStream b(6006, 17);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(d.sample(a), d.sample(b));
}

// The exponential's inverse is computed inline, not through GSL: its samples must be GSL's
// Pinv(u) below 1/2 and Qinv(1 - u) above, to the bit, as the other distributions' are.
TEST(DateDistribution, ExponentialSamplesAreGslsInversesToTheBit) {
  for (const double mean : {1.0, 0.03571428571428571, 5.0, 1e-300, 1e300}) {
    const DateDistribution d = make(Distribution::Exponential, {mean});
    RandomStream r(8008, 3);
    for (int i = 0; i < 20000; ++i) {
      RandomStream copy = r;
      const double u = copy.uniform01_open();
      const double gsl = u <= 1.0 - u ? gsl_cdf_exponential_Pinv(u, mean)
                                      : gsl_cdf_exponential_Qinv(1.0 - u, mean);
      const double x = d.sample(r);
      ASSERT_EQ(std::memcmp(&x, &gsl, sizeof x), 0) << "mean " << mean << ", u = " << u;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// A race of two exponential dates: the first wins with probability r1 / (r1 + r2).

TEST(DateDistribution, ExponentialRaceWinningFrequency) {
  const double m1 = 2.0;
  const double m2 = 5.0;
  const DateDistribution first = make(Distribution::Exponential, {m1});
  const DateDistribution second = make(Distribution::Exponential, {m2});
  RandomStream r(/*seed=*/7007, 0);
  constexpr int kRaces = 10000;
  int won = 0;
  for (int i = 0; i < kRaces; ++i) {
    if (first.sample(r) < second.sample(r)) ++won;
  }
  const double p = (1.0 / m1) / (1.0 / m1 + 1.0 / m2);  // 5/7
  // Binomial: the frequency has standard error sqrt(p(1-p)/n) = 0.0045; allow 3 of them.
  const double standard_error = std::sqrt(p * (1.0 - p) / kRaces);
  EXPECT_NEAR(static_cast<double>(won) / kRaces, p, 3.0 * standard_error);
}

// ---------------------------------------------------------------------------------------------
// Parameters

TEST(DateDistribution, ParameterErrors) {
  EXPECT_EQ(make_error(Distribution::Normal, {1.0}), "normal(mean, sd) takes 2 parameters, got 1");
  EXPECT_EQ(make_error(Distribution::Normal, {1.0, 0.0}),
            "normal(mean, sd): sd must be > 0, got 0");
  EXPECT_EQ(make_error(Distribution::Normal, {NAN, 1.0}),
            "normal(mean, sd): mean must be a finite number, got nan");
  EXPECT_EQ(make_error(Distribution::Exponential, {1.0, 2.0}),
            "exponential(mean) takes 1 parameter, got 2");
  EXPECT_EQ(make_error(Distribution::Exponential, {-3.0}),
            "exponential(mean): mean must be > 0, got -3");
  EXPECT_EQ(make_error(Distribution::Gamma, {0.0, 1.0}),
            "gamma(shape, scale): shape must be > 0, got 0");
  EXPECT_EQ(make_error(Distribution::Gamma, {1.0, -1.0}),
            "gamma(shape, scale): scale must be > 0, got -1");
  EXPECT_EQ(make_error(Distribution::Chi2, {-1.0}), "chi2(k): k must be > 0, got -1");
  EXPECT_EQ(make_error(Distribution::Uniform, {2.0, 2.0}),
            "uniform(a, b): needs a < b, got a = 2, b = 2");
  EXPECT_EQ(make_error(Distribution::Lognormal, {0.0, -0.5}),
            "lognormal(zeta, sigma): sigma must be > 0, got -0.5");
  EXPECT_EQ(make_error(Distribution::Weibull, {1.0, INFINITY}),
            "weibull(scale, shape): shape must be a finite number, got inf");
  EXPECT_EQ(make_error(Distribution::Custom, {}), "custom: no empirical CDF given");
  EXPECT_EQ(make_error(Distribution::Custom, {1.0}),
            "custom takes no numeric parameters (its CDF comes from a file), got 1");
  // Accepted: negative normal mean, lognormal zeta, uniform bounds.
  EXPECT_EQ(make_error(Distribution::Normal, {-5.0, 1.0}), "(accepted)");
  EXPECT_EQ(make_error(Distribution::Lognormal, {-2.0, 1.0}), "(accepted)");
  EXPECT_EQ(make_error(Distribution::Uniform, {-3.0, -2.0}), "(accepted)");
}

TEST(DateDistribution, DescribeAndNames) {
  EXPECT_EQ(make(Distribution::Normal, {10.0, 2.0}).describe(), "normal(10, 2)");
  EXPECT_EQ(make(Distribution::Exponential, {0.5}).describe(), "exponential(0.5)");
  EXPECT_STREQ(distribution_name(Distribution::Chi2), "chi2");
  EXPECT_STREQ(distribution_name(Distribution::Custom), "custom");
}

TEST(DateDistribution, QuantileInvertsTheCdf) {
  for (const FitCase& c : fit_cases()) {
    SCOPED_TRACE(c.name);
    const DateDistribution d = make(c.kind, c.params);
    for (double p : {1e-12, 0.01, 0.3, 0.5, 0.9, 1.0 - 1e-9}) {
      const double x = d.quantile(p);
      EXPECT_NEAR(d.cdf(x) / p, 1.0, 1e-7) << "p = " << p;
    }
    // Far upper tail, where the survival function, not the CDF, is the precise side
    // (tail = 2^-50 makes 1 - tail exact).
    const double tail = std::ldexp(1.0, -50);
    const double x = d.quantile(1.0 - tail);
    // A uniform quantile that close to b is a few ulps from it: no relative precision to check.
    if (c.kind != Distribution::Uniform) {
      EXPECT_NEAR(d.survival(x) / tail, 1.0, 1e-6);
    }
  }
  EXPECT_EQ(make(Distribution::Uniform, {1.0, 3.0}).quantile(0.0), 1.0);
  EXPECT_EQ(make(Distribution::Uniform, {1.0, 3.0}).quantile(1.0), 3.0);
  EXPECT_EQ(make(Distribution::Exponential, {1.0}).quantile(1.0), INFINITY);
}

TEST(DateDistribution, MassesAreTheCdfAndTheSurvivalFunction) {
  // The CDF as it is; the survival function as 1 - cdf(x) where the CDF is at most 1/2, so
  // within a few ulps of GSL's Q (relative 1e-14 allows both functions' own errors).
  for (const FitCase& c : fit_cases()) {
    SCOPED_TRACE(c.name);
    const DateDistribution d = make(c.kind, c.params);
    for (double p : {1e-300, 1e-12, 0.01, 0.3, 0.5, 0.9, 1.0 - 1e-9, 1.0 - 1e-15}) {
      const double x = d.quantile(p);
      const DateDistribution::Masses m = d.masses(x);
      EXPECT_EQ(m.below, d.cdf(x)) << "p = " << p;
      EXPECT_NEAR(m.above / d.survival(x), 1.0, 1e-14) << "p = " << p;
    }
    const DateDistribution::Masses far = d.masses(d.quantile(1.0 - std::ldexp(1.0, -50)));
    if (c.kind != Distribution::Uniform) {
      EXPECT_GT(far.above, 0.0) << "the tail is not 1 - 1";
    }
  }
}

// ---------------------------------------------------------------------------------------------
// EmpiricalCdf

TEST(EmpiricalCdf, PiecewiseLinearWithAnAtomAtTheFirstValue) {
  TempDir dir;
  const EmpiricalCdf cdf = load_cdf(dir.write("atom.cdf", "1 0.2\n2 0.2\n4 1\n"));
  ASSERT_EQ(cdf.points().size(), 3u);
  EXPECT_EQ(cdf.cdf(0.5), 0.0);
  EXPECT_EQ(cdf.cdf(1.0), 0.2);  // the mass at or below the first value
  EXPECT_EQ(cdf.cdf(1.5), 0.2);  // flat segment
  EXPECT_DOUBLE_EQ(cdf.cdf(3.0), 0.6);
  EXPECT_EQ(cdf.cdf(4.0), 1.0);
  EXPECT_EQ(cdf.cdf(100.0), 1.0);
  EXPECT_EQ(cdf.inverse(0.1), 1.0);
  EXPECT_EQ(cdf.inverse(0.2), 1.0);  // inf{x | F(x) >= 0.2}, not the end of the flat part
  EXPECT_EQ(cdf.inverse(0.2000001), 2.0 + 0.0000001 / 0.8 * 2.0);
  EXPECT_DOUBLE_EQ(cdf.inverse(0.6), 3.0);
  EXPECT_EQ(cdf.inverse(1.0), 4.0);

  // The atom carries its mass: P(X = 1) = 0.2, so of 10,000 samples about 2,000 equal 1
  // (binomial sd 40; allow 4 sd = 160); none lies in the flat part (1, 2).
  const DateDistribution d = make(Distribution::Custom, {}, &cdf);
  RandomStream r(/*seed=*/8008, 0);
  int at_atom = 0;
  for (std::size_t i = 0; i < kSamples; ++i) {
    const double x = d.sample(r);
    if (x == 1.0) ++at_atom;
    ASSERT_FALSE(x > 1.0 && x < 2.0) << x;
  }
  EXPECT_NEAR(at_atom, 2000, 160);
}

TEST(EmpiricalCdf, AcceptsCommentsCommasAndRoundedLastCdf) {
  auto parsed = EmpiricalCdf::parse("# header\n\n 0 , 0 \n1,0.5# mid\n+2 0.9999999999\n", "t");
  ASSERT_TRUE(std::holds_alternative<EmpiricalCdf>(parsed)) << std::get<std::string>(parsed);
  const EmpiricalCdf& cdf = std::get<EmpiricalCdf>(parsed);
  ASSERT_EQ(cdf.points().size(), 3u);
  EXPECT_EQ(cdf.points().back().cdf, 1.0);
  EXPECT_EQ(cdf.points()[1].value, 1.0);
  EXPECT_EQ(cdf.points()[1].cdf, 0.5);
}

TEST(EmpiricalCdf, ErrorsNameFileAndLine) {
  const auto error = [](const std::string& text) {
    auto parsed = EmpiricalCdf::parse(text, "t.cdf");
    const auto* message = std::get_if<std::string>(&parsed);
    return message == nullptr ? std::string("(accepted)") : *message;
  };
  EXPECT_EQ(error("0 0\n1\n"), "t.cdf:2: expected two numbers 'value cdf', got 1 field");
  EXPECT_EQ(error("0 0 1\n"), "t.cdf:1: expected two numbers 'value cdf', got 3 fields");
  EXPECT_EQ(error("# c\nx 0.5\n"), "t.cdf:2: value 'x' is not a number");
  EXPECT_EQ(error("1 0.5e\n"), "t.cdf:1: cdf '0.5e' is not a number");
  EXPECT_EQ(error("inf 1\n"), "t.cdf:1: value must be finite");
  EXPECT_EQ(error("0 1.5\n"), "t.cdf:1: cdf must lie in [0, 1], got 1.5");
  EXPECT_EQ(error("0 0\n0 1\n"), "t.cdf:2: values must be strictly increasing: 0 after 0");
  EXPECT_EQ(error("0 0.5\n1 0.4\n2 1\n"), "t.cdf:2: cdf must be non-decreasing: 0.4 after 0.5");
  EXPECT_EQ(error("0 0\n1 0.9\n\n# end\n"), "t.cdf:2: the last cdf must be 1, got 0.9");
  EXPECT_EQ(error("# nothing\n\n"), "t.cdf: no points (expected lines 'value cdf')");
  EXPECT_EQ(error("5 1"), "(accepted)");  // a point mass, no final newline

  auto missing = EmpiricalCdf::load("/nonexistent/smcbip/x.cdf");
  ASSERT_TRUE(std::holds_alternative<std::string>(missing));
  EXPECT_EQ(std::get<std::string>(missing),
            "/nonexistent/smcbip/x.cdf: cannot open the empirical CDF file");
}

TEST(EmpiricalCdf, ErrorQuotesAFieldOfNulBytesEscapedAndCut) {
  // The field was quoted as it was: NUL bytes and a whole megabyte went into the message.
  const auto error = [](const std::string& text) {
    auto parsed = EmpiricalCdf::parse(text, "t.cdf");
    const auto* message = std::get_if<std::string>(&parsed);
    return message == nullptr ? std::string("(accepted)") : *message;
  };
  EXPECT_EQ(error(std::string("l\0\0\0\0\0005 u", 9)),
            "t.cdf:1: value 'l\\x00\\x00\\x00\\x00\\x005' is not a number");
  EXPECT_EQ(error("0 " + std::string(1 << 20, 'x')),
            "t.cdf:1: cdf 'xxxxxxxxxxxxxxxxxxxxxxxx...' is not a number");
  EXPECT_EQ(error("1 0\\1\n"), "t.cdf:1: cdf '0\\x5c1' is not a number");
}

}  // namespace
}  // namespace smcbip::engines
