// The progress line of smcbip check and explore.
#include "smc/tools/progress_bar.h"

#include <gtest/gtest.h>

#include <sstream>

namespace smcbip::tools {
namespace {

TEST(ProgressBar, ShowsRunsAgainstTheTargetAndTimeLeft) {
  std::ostringstream out;
  ProgressBar bar(out, 3);
  smc::Progress p;
  p.query = 1;
  p.runs = 500;
  p.target = 1000;
  p.estimate = 0.25;
  p.seconds = 2;
  EXPECT_EQ(bar.line(p),
            "query 2/3  [############............] 500/1000 runs  p~0.25  250 runs/s  2.0 s left");
}

TEST(ProgressBar, PlacesTheRatioOfATestBetweenItsThresholds) {
  std::ostringstream out;
  ProgressBar bar(out, 1);
  smc::Progress p;
  p.points = 4;
  p.open = 3;
  p.runs = 64;
  p.seconds = 1;
  p.estimate = 0.5;
  p.test_position = 1.0;
  EXPECT_EQ(bar.line(p),
            "query 1/1, 1/4 points done  accept |-----------------------*| reject 64 runs  p~0.5  "
            "64 runs/s");
}

TEST(ProgressBar, WipesItsLineOnlyIfItDrewOne) {
  std::ostringstream out;
  { ProgressBar bar(out, 1); }
  EXPECT_EQ(out.str(), "");
  {
    ProgressBar bar(out, 1);
    bar.show(smc::Progress{});
  }
  EXPECT_EQ(out.str().substr(out.str().size() - 4), "\r\x1b[K");
}

}  // namespace
}  // namespace smcbip::tools
