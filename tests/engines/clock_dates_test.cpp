// The clock arithmetic of the stochastic draws (clock_dates.h): ceil_of is std::ceil to the bit,
// and the date a clock reaches a value is the first whole nanosecond at or past it.
#include "engines/stochastic/clock_dates.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace smcbip::engines {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

TEST(ClockDates, CeilOfIsTheLibrarysCeilToTheBit) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> values = {0.0,
                                -0.0,
                                0.25,
                                -0.25,
                                1.0,
                                1.0000000000000002,
                                2.5,
                                -2.5,
                                4503599627370495.5,  // 2^52 - 0.5: the last doubles with halves
                                4503599627370496.0,
                                9007199254740993.0,
                                9.2e18,
                                std::nextafter(9.2e18, 0.0),
                                9.3e18,
                                1e300,
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::min(),
                                inf,
                                -inf,
                                std::numeric_limits<double>::quiet_NaN()};
  // Exponential delays in nanoseconds, as the draws make them, over many scales.
  std::mt19937_64 random(20261127);
  std::exponential_distribution<double> delay(1.0);
  for (int scale = -3; scale <= 15; ++scale) {
    for (int i = 0; i < 2000; ++i) values.push_back(delay(random) * std::pow(10.0, scale));
  }
  for (double x : values) {
    EXPECT_EQ(bits(ceil_of(x)), bits(std::ceil(x))) << x;
  }
}

TEST(ClockDates, AClockReachesAValueAtTheFirstWholeNanosecondPastIt) {
  const TimeValue ms = 1'000'000;
  // Reset at 10 ns, running at rate 1.
  const ClockState clock{0.0, 10, 1.0};
  EXPECT_EQ(clock_reaches(clock, ms, 10, 0.0), 10);
  EXPECT_EQ(clock_reaches(clock, ms, 10, 1.0), 10 + ms);
  EXPECT_EQ(clock_reaches(clock, ms, 10, 1.0000005), 10 + ms + 1);
  EXPECT_EQ(clock_reaches(clock, ms, 10, 0.0000000001), 11);
  // A stopped clock never gets there; a value beyond the end of time neither.
  EXPECT_EQ(clock_reaches(ClockState{0.0, 10, 0.0}, ms, 10, 1.0), kPlusInfinity);
  EXPECT_EQ(clock_reaches(clock, ms, 10, 1e300), kPlusInfinity);
}

}  // namespace
}  // namespace smcbip::engines
