// The scheduler's choice on untimed models, where every item has the same window: two draws
// stand for the race of one date per item, so the winner must still be uniform among the items
// and the date increment distributed as the earliest of the items' dates.
//
// The model has five items always enabled: four binary rendezvous and one internal port. Each
// test runs kSteps steps from a fixed seed, on every engine, and checks against theory:
// - uniformity: Pearson's chi-square statistic of the five counts, 4 degrees of freedom, below
//   18.467, its 0.999 quantile;
// - dates: the old race gave now + floor(min of 5 exponentials of mean 10 ns) = now + floor(E)
//   with E exponential of mean mu = 2 (--first-enabled: the winner's own date, mu = 10). floor(E)
//   is geometric: with q = exp(-1/mu), its mean is q/(1-q) and its variance q/(1-q)^2. The
//   mean of kSteps increments must lie within 5 standard errors of q/(1-q) (a normal tail of
//   6e-7). A delay of mean 10/4 or 10 instead of 10/5, or one left unfloored, is off by more.
// With fixed seeds each test is deterministic; a correct scheduler fails one with probability
// about 0.001 over the choice of seed.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engines/engines.h"
#include "engines/semantics/shared_window.h"
#include "engines/stochastic/random_stream.h"
#include "tests/engines/temp_model.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::engines {
namespace {

constexpr std::uint64_t kSteps = 20000;
constexpr std::size_t kItems = 5;
constexpr double kChiSquareQuantile = 18.467;  // 0.999 quantile, 4 degrees of freedom

const char* const kModel = R"(package shared
  port type Tick()
  connector type Pair(Tick a, Tick b)
    define a b
  end
  atom type Cycler()
    export port Tick step()
    place S
    initial to S
    on step from S to S
  end
  atom type Solo()
    port Tick tick()
    place S
    initial to S
    on tick from S to S
  end
  compound type Top()
    component Cycler c0(), c1(), c2(), c3(), c4(), c5(), c6(), c7()
    component Solo s()
    connector Pair p0(c0.step, c1.step)
    connector Pair p1(c2.step, c3.step)
    connector Pair p2(c4.step, c5.step)
    connector Pair p3(c6.step, c7.step)
  end
end
)";

/// Which item each step fired (connector index, or kItems - 1 for the internal port) and the
/// date increments between steps.
class Tally : public RunObserver {
 public:
  bool observe(const StepInfo& step, const StateView& /*state*/) override {
    if (step.fired == StepInfo::Fired::Nothing) return true;
    const std::size_t item =
        step.fired == StepInfo::Fired::Interaction ? step.connector : kItems - 1;
    if (item < kItems) ++counts[item];
    increments.push_back(step.time - last_);
    last_ = step.time;
    return true;
  }
  std::array<std::uint64_t, kItems> counts{};
  std::vector<TimeValue> increments;

 private:
  TimeValue last_ = 0;
};

Tally run(const bipc::ir::System& system, SimulateOptions options) {
  options.seed = 1;
  options.limit = kSteps;
  options.silent = true;
  Simulator simulator(system, options, Externs::with_builtins());
  std::ostringstream out;
  Tally tally;
  const RunResult result = simulator.run(0, RunStreams{out, out, nullptr}, &tally);
  EXPECT_EQ(result.code, kRunOk) << result.message;
  EXPECT_EQ(result.steps, kSteps);
  return tally;
}

double chi_square(const std::array<std::uint64_t, kItems>& counts) {
  const double expected = static_cast<double>(kSteps) / kItems;
  double sum = 0;
  for (std::uint64_t c : counts)
    sum += (static_cast<double>(c) - expected) * (static_cast<double>(c) - expected) / expected;
  return sum;
}

double mean(const std::vector<TimeValue>& values) {
  double sum = 0;
  for (TimeValue v : values) sum += static_cast<double>(v);
  return values.empty() ? 0 : sum / static_cast<double>(values.size());
}

/// Checks the counts' uniformity and, unless `mu` is 0 (every date is now), the increments'
/// mean against floor of an exponential of mean `mu`.
void expect_race_distribution(const Tally& tally, double mu) {
  EXPECT_LT(chi_square(tally.counts), kChiSquareQuantile)
      << tally.counts[0] << " " << tally.counts[1] << " " << tally.counts[2] << " "
      << tally.counts[3] << " " << tally.counts[4];
  if (mu == 0) {
    EXPECT_EQ(mean(tally.increments), 0.0);
    return;
  }
  const double q = std::exp(-1 / mu);
  const double expected = q / (1 - q);
  const double standard_error = std::sqrt(q / ((1 - q) * (1 - q)) / kSteps);
  EXPECT_NEAR(mean(tally.increments), expected, 5 * standard_error);
}

class SharedWindowChoice : public ::testing::TestWithParam<EngineKind> {
 protected:
  void SetUp() override { system_ = tests::load_model_text(kModel, "Top()"); }
  SimulateOptions options() const {
    SimulateOptions o;
    o.engine = GetParam();
    o.threads = 2;
    return o;
  }
  std::optional<bipc::ir::System> system_;
};

TEST_P(SharedWindowChoice, RaceWinnerUniformAndEarliestDate) {
  ASSERT_TRUE(system_);
  expect_race_distribution(run(*system_, options()), 10.0 / kItems);
}

TEST_P(SharedWindowChoice, AsapWinnerUniformAtNow) {
  ASSERT_TRUE(system_);
  SimulateOptions o = options();
  o.asap = true;
  expect_race_distribution(run(*system_, o), 0);
}

TEST_P(SharedWindowChoice, FirstEnabledWinnerUniformWithItsOwnDate) {
  ASSERT_TRUE(system_);
  SimulateOptions o = options();
  o.first_enabled = true;
  expect_race_distribution(run(*system_, o), 10.0);
}

// The chooser skips the logarithm where the delay is 0: its dates must be those of the formula
// now + floor(-mean ln u), bit for bit, for item counts whose cut lies anywhere in (0, 1)
// (and underflows to 0, from about 7,500 items), counts changing between draws, and both means.
TEST(SharedWindowChooser, DatesAreTheFormulasBitForBit) {
  SharedWindowChooser chooser;
  RandomStream drawn(31, 0), raw(31, 0);
  const std::vector<std::size_t> counts = {1, 2, 3, 5, 9, 10, 11, 40, 368, 369, 500, 7500, 100000};
  for (int round = 0; round < 40000; ++round) {
    const std::size_t n = counts[static_cast<std::size_t>(round / 7) % counts.size()];
    const bool first_enabled = round % 3 == 0;
    const auto choice = chooser.choose(n, 100, true, false, first_enabled, drawn);
    const auto chosen = static_cast<std::size_t>(raw.below(n));
    const double mean = first_enabled ? 10.0 : 10.0 / static_cast<double>(n);
    const TimeValue expected =
        100 + static_cast<TimeValue>(std::floor(-mean * std::log(raw.uniform01_open())));
    ASSERT_EQ(choice.chosen, chosen) << "n = " << n;
    ASSERT_EQ(choice.date, expected) << "n = " << n << ", round " << round;
  }
  // The draws nearest the cut for two items (mean 5): u = exp(-1/5) rounded, and the doubles
  // around it, where the formula's delay turns from 0 to 1.
  EXPECT_EQ(std::floor(-5.0 * std::log(std::nextafter(std::exp(-0.2), 1.0))), 0.0);
}

// The delays next to every bound exp(-k / mean) where the formula's delay turns from k - 1 to
// k, a few units of 2^-53 and a few parts in 10^7 and 10^5 either side, and anywhere in (0, 1).
TEST(SharedWindowChooser, DelaysNextToTheirBoundsAreTheFormulas) {
  RandomStream random(5, 0);
  for (const std::size_t n : {1, 2, 3, 5, 10, 11, 500}) {
    SharedWindowChooser chooser;
    chooser.choose(n, 0, true, false, false, random);  // keeps the mean 10 / n
    const double mean = 10.0 / static_cast<double>(n);
    const auto check = [&](double u) {
      if (!(u > 0.0 && u < 1.0)) return;
      ASSERT_EQ(chooser.delay(u), static_cast<TimeValue>(std::floor(-mean * std::log(u))))
          << "mean " << mean << ", u = " << u;
    };
    for (int k = 0; k <= 40; ++k) {
      const double bound = std::exp(-k / mean);
      double below = bound, above = bound;
      for (int step = 0; step < 8; ++step) {
        check(below = std::nextafter(below, 0.0));
        check(above = std::nextafter(above, 1.0));
      }
      for (const double relative : {1e-7, 1e-5}) {
        check(bound * (1 - relative));
        check(bound * (1 + relative));
      }
    }
    for (int draw = 0; draw < 20000; ++draw) check(random.uniform01_open());
  }
}

std::string engine_name(const ::testing::TestParamInfo<EngineKind>& info) {
  return tests::engine_label(info.param);
}

INSTANTIATE_TEST_SUITE_P(Engines, SharedWindowChoice,
                         ::testing::Values(EngineKind::Reference, EngineKind::Optimised,
                                           EngineKind::Multithread),
                         engine_name);

}  // namespace
}  // namespace smcbip::engines
