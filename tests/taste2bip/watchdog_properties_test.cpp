// The watchdog's properties (tests/taste2bip/watchdog/watchdog.mtl) answered by statistical
// model checking on the adapted original (watchdog_model.h). The smcbip tool cannot register
// the model's extern functions, so the queries go through smc::check_properties, which takes
// extern functions only from a model entry (engines::PluginEntry): here the interpreted model of
// the same system with the watchdog externs, not generated code. (`smcbip check` on the
// original stops at its `@cpp(src=...)`: "extern source .../ext-cpp/ExternInterfaceViewFcns.cpp:
// no such file"; the data holds no C++.)
//
// Statistics: PESTIM with delta = 0.02 and alpha = 0.01, so N = ceil(ln(2/alpha) / (2 delta^2))
// = 6,623 runs per query and each estimate is within 0.02 of the true probability with
// probability 0.99 (Okamoto's bound); seeds are fixed, so a given build passes or fails for good.
// Answers recorded (seed 20261125, with the fault): (i) 1 [0.98, 1]; (ii) 1 [0.98, 1];
// (iii) 0 [0, 0.02]. Nominal (seed 20261126): no stop 0 [0, 0.02]; (i) 1 [0.98, 1]. The true
// values are 1 and 0 by the model's structure (derived in watchdog.mtl), so each assertion
// below allows the estimate its delta.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/taste2bip/shared_data.h"
#include "tests/taste2bip/watchdog_answers.h"
#include "tests/taste2bip/watchdog_model.h"

namespace smcbip::taste2bip::test {
namespace {

constexpr double kDelta = kWatchdogDelta;

TEST(WatchdogProperties, TheOriginalAnswersItsPropertyFile) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  const std::string file =
      file_text(std::filesystem::path(SMCBIP_SOURCE_DIR) / "tests/taste2bip/watchdog/watchdog.mtl");
  ASSERT_FALSE(file.empty());
  const std::vector<smc::QueryResult> r =
      original_watchdog_answers(file, /*nominal=*/false, 20261125);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_GE(r[0].estimate, 1 - kDelta) << "(i) a command missed the motors' deadline";
  EXPECT_GE(r[1].estimate, 1 - kDelta) << "(ii) a lost heartbeat without a stop in 110 ms";
  EXPECT_LE(r[2].estimate, kDelta) << "(iii) the stop within 100 ms of the first fault";
}

TEST(WatchdogProperties, WithoutALostHeartbeatNoStopIsSent) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  const std::vector<smc::QueryResult> r = original_watchdog_answers(
      "P=? [ F[0,1000] BLSClient.l4 ]\n"
      "P=? [ G[0,1000] (fired(JoystickDriver2CmdDispatcher_cmd) -> "
      "F[0,10] fired(BLSClient_mot_cmd2BLSClient)) ]\n",
      /*nominal=*/true, 20261126);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_LE(r[0].estimate, kDelta) << "the watchdog stopped the rover without a fault";
  EXPECT_GE(r[1].estimate, 1 - kDelta);
}

}  // namespace
}  // namespace smcbip::taste2bip::test
