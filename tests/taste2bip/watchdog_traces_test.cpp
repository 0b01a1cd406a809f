// The projected traces of the original watchdog BIP's untimed abstraction (watchdog_traces.h):
// the joystick command's chain of calls derived by hand from the model is among them, and the
// comparison finds and reports the first difference with a deliberately altered copy.
#include "tests/taste2bip/watchdog_traces.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "tests/taste2bip/watchdog_model.h"
#include "tests/taste2bip/watchdog_untimed.h"

namespace smcbip::taste2bip::test {
namespace {

/// The original's calls and SDL states, and Watchdog's calls and place Wait.
WatchdogObservation original_observation() {
  return watchdog_observation(WatchdogNaming::Original, /*watchdog_calls=*/true,
                              /*watchdog_wait=*/true);
}

/// The traces of the untimed abstraction of `text` (an adapted original, or a variant of it).
TraceSet traces_of(const std::string& text, const TraceBounds& bounds, bool nominal = false) {
  std::string why;
  std::optional<bipc::ir::System> system =
      load_bip_text(text, "InterfaceViewFull.bip", "Syst()", why);
  EXPECT_TRUE(system) << why;
  if (!system) return {};
  if (nominal) remove_fault_transitions(*system);
  EXPECT_EQ(make_untimed(*system), "");
  const engines::Externs externs = watchdog_externs();
  TraceSet traces = projected_traces(*system, externs, original_observation(), bounds);
  EXPECT_EQ(traces.problem, "");
  EXPECT_EQ(traces.errors, 0u);
  EXPECT_FALSE(traces.cut) << "the bounds left states unexplored";
  return traces;
}

std::string adapted_original() {
  std::string why;
  const std::optional<std::string> text = watchdog_adapted_original(why);
  EXPECT_TRUE(text) << why;
  return text.value_or("");
}

TEST(WatchdogTraces, TheOriginalHasTheJoystickCommandsChainOfCalls) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  // The nominal original (fault transitions removed) to k = 10 events: 21,772 traces from
  // 27,167 (trace, state) pairs, explored whole (each trace's silent closure within 50 steps).
  TraceBounds bounds;
  bounds.events = 10;
  bounds.silent_steps = 50;
  bounds.states = 100'000;
  const TraceSet traces = traces_of(adapted_original(), bounds, /*nominal=*/true);
  EXPECT_EQ(traces.traces.size(), 21'772u);
  EXPECT_EQ(traces.states, 27'167u);
  // By hand from InterfaceViewFull.bip, with every call served as soon as it is made and
  // JoystickDriver's return (to Wait) left for later: the cyclic step, the command to
  // CmdDispatcher's FIFO, CmdDispatcher's start, its log_cmd served by Logger (which prints and
  // returns to Wait), its test_cmd served by Watchdog, which relays it to BLSClient.
  const Trace chain = {"JoystickDriver.step",    "JoystickDriver.cmd", "CmdDispatcher.cmd",
                       "CmdDispatcher.log_cmd",  "Logger.log_cmd",     "Logger.Wait",
                       "CmdDispatcher.test_cmd", "Watchdog.test_cmd",  "Watchdog.mot_cmd",
                       "BLSClient.mot_cmd"};
  EXPECT_TRUE(traces.traces.contains(chain));
  // CmdDispatcher logs only the command it received, after receiving it.
  EXPECT_FALSE(traces.traces.contains(
      Trace{"JoystickDriver.step", "JoystickDriver.cmd", "CmdDispatcher.log_cmd"}));
  // Untimed, the watchdog's timeout is not bound to 110 ms: it may send stop first of all (and
  // return to Wait in the same step).
  EXPECT_TRUE(
      traces.traces.contains(Trace{"Watchdog.mot_cmd", "Watchdog.Wait", "BLSClient.mot_cmd"}));
  // Nothing but JoystickDriver's step or the watchdog's timeout starts a trace.
  for (const Trace& t : traces.traces) {
    if (t.size() != 1) continue;
    EXPECT_TRUE(t[0] == "JoystickDriver.step" || t[0] == "Watchdog.mot_cmd") << t[0];
  }
}

TEST(WatchdogTraces, TheLostHeartbeatReturnsJoystickDriverToWaitWithoutAStep) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  TraceBounds bounds;
  bounds.events = 6;  // 944 traces from 1,446 (trace, state) pairs
  const TraceSet with_fault = traces_of(adapted_original(), bounds);
  const TraceSet nominal = traces_of(adapted_original(), bounds, /*nominal=*/true);
  EXPECT_EQ(with_fault.traces.size(), 944u);
  EXPECT_EQ(nominal.traces.size(), 198u);
  // fault1 (Wait to l5) then the silent recovery (l5 to Wait): Wait entered, no step seen.
  EXPECT_TRUE(with_fault.traces.contains(Trace{"JoystickDriver.Wait"}));
  EXPECT_FALSE(nominal.traces.contains(Trace{"JoystickDriver.Wait"}));
  const TraceDifference diff = compare_traces(with_fault, nominal);
  EXPECT_EQ(diff.only_left, Trace{"JoystickDriver.Wait"});
  EXPECT_FALSE(diff.only_right) << "removing a fault adds no behaviour";
}

TEST(WatchdogTraces, TheComparisonReportsTheFirstDifference) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  const std::string original = adapted_original();
  // The altered copy: CmdDispatcher goes on without calling log_cmd.
  const std::string send_log = "on CmdDispatcher_log_cmd_out\n      from l3 to l4\n      eager";
  std::string altered = original;
  const std::size_t at = altered.find(send_log);
  ASSERT_NE(at, std::string::npos);
  altered.replace(at, send_log.size(), "internal\n      from l3 to l4");
  TraceBounds bounds;
  bounds.events = 6;
  const TraceSet left = traces_of(original, bounds), right = traces_of(altered, bounds);
  const TraceSet again = traces_of(original, bounds);
  EXPECT_TRUE(compare_traces(left, again).equal()) << "the original against itself";

  const TraceDifference diff = compare_traces(left, right);
  ASSERT_FALSE(diff.equal());
  const Trace logs = {"JoystickDriver.step", "JoystickDriver.cmd", "CmdDispatcher.cmd",
                      "CmdDispatcher.log_cmd"};
  const Trace skips = {"JoystickDriver.step", "JoystickDriver.cmd", "CmdDispatcher.cmd",
                       "CmdDispatcher.test_cmd"};
  EXPECT_EQ(diff.only_left, logs);
  EXPECT_EQ(diff.only_right, skips);
  const std::string report = difference_report(left, right, diff, "original", "altered");
  std::cerr << report;
  EXPECT_NE(report.find("original has the trace [JoystickDriver.step, JoystickDriver.cmd, "
                        "CmdDispatcher.cmd, CmdDispatcher.log_cmd] that altered has not; altered "
                        "after [JoystickDriver.step, JoystickDriver.cmd, CmdDispatcher.cmd] it "
                        "continues with:"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find(" CmdDispatcher.test_cmd;"), std::string::npos) << report;
}

}  // namespace
}  // namespace smcbip::taste2bip::test
