// The translation of the ESROCOS watchdog design (taste2bip's translate) against the BIP the
// original translator made of it (watchdog_model.h), by the projected traces of their untimed
// abstractions (watchdog_traces.h): equal on the SDL functions' calls and states; the
// differences that involve the C++ function Watchdog (a hand-written body with a timeout in the
// original, an abstract atom in the translation) are printed and checked to be Watchdog's.
// The original is compared without its hand-added fault transitions (the translation's nominal
// package has none); the translation's counters of dropped calls are erased (see
// translation_observation). Bounds: SDL calls and states to k = 9 events (11,090 traces each,
// from about 120,000 and 86,000 (trace, state) pairs); Watchdog's calls alone to k = 4 (silent
// closures over everything else: about 160,000 and 240,000 pairs). Both explored whole.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "tests/taste2bip/watchdog_model.h"
#include "tests/taste2bip/watchdog_translation.h"
#include "tests/taste2bip/watchdog_untimed.h"

namespace smcbip::taste2bip::test {
namespace {

/// The traces of the untimed abstraction of `system` under `observation`, explored whole.
TraceSet untimed_traces(bipc::ir::System system, const WatchdogObservation& observation,
                        const TraceBounds& bounds) {
  EXPECT_EQ(make_untimed(system), "");
  const engines::Externs externs = watchdog_externs();
  TraceSet traces = projected_traces(system, externs, observation, bounds);
  EXPECT_EQ(traces.problem, "");
  EXPECT_EQ(traces.errors, 0u);
  EXPECT_FALSE(traces.cut) << "the bounds left states unexplored";
  return traces;
}

TEST(WatchdogCompare, TheSdlFunctionsCallsAndStatesAreTheOriginals) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  const BothModels both = load_both();
  ASSERT_TRUE(both.original && both.translation);
  TraceBounds bounds;
  bounds.events = 9;
  bounds.silent_steps = 50;
  bounds.states = 400'000;
  const TraceSet original = untimed_traces(
      *both.original, watchdog_observation(WatchdogNaming::Original, false, false), bounds);
  const TraceSet translation =
      untimed_traces(*both.translation, translation_observation(false), bounds);
  std::cerr << "SDL calls and states, k = " << bounds.events << ": original "
            << original.traces.size() << " traces (" << original.states << " pairs), translation "
            << translation.traces.size() << " traces (" << translation.states << " pairs)\n";
  EXPECT_EQ(original.traces.size(), 11'090u);
  const TraceDifference diff = compare_traces(original, translation);
  EXPECT_TRUE(diff.equal()) << difference_report(original, translation, diff, "original",
                                                 "translation");
  EXPECT_TRUE(original.traces.contains(Trace{"JoystickDriver.step", "JoystickDriver.cmd",
                                             "CmdDispatcher.cmd", "CmdDispatcher.log_cmd"}));
}

/// Only Watchdog's calls (test_cmd received, mot_cmd sent) are observed.
WatchdogObservation watchdog_calls_only(WatchdogObservation o) {
  std::erase_if(o.ports, [](const auto& port) { return port.second.rfind("Watchdog.", 0) != 0; });
  o.places.clear();
  return o;
}

TEST(WatchdogCompare, TheDifferencesInvolveTheWatchdog) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  const BothModels both = load_both();
  ASSERT_TRUE(both.original && both.translation);
  TraceBounds bounds;
  bounds.events = 4;
  bounds.silent_steps = 10'000;
  bounds.states = 3'000'000;
  const TraceSet original = untimed_traces(
      *both.original,
      watchdog_calls_only(watchdog_observation(WatchdogNaming::Original, true, false)), bounds);
  const TraceSet translation =
      untimed_traces(*both.translation, watchdog_calls_only(translation_observation(true)), bounds);
  const TraceDifference diff = compare_traces(original, translation);
  std::cout << "[Watchdog's calls, k = " << bounds.events << ": original " << original.traces.size()
            << " traces (" << original.states << " pairs), translation "
            << translation.traces.size() << " (" << translation.states << " pairs)] "
            << difference_report(original, translation, diff, "original", "translation");
  // By hand: the original's Watchdog relays each test_cmd as a mot_cmd before it takes the
  // next; the translation's abstract Watchdog may skip the relay. Untimed, both may send a
  // mot_cmd on their own at any time (the original's timeout, the translation's cyclic purge),
  // so the original has no trace the translation lacks.
  EXPECT_EQ(diff.only_right, (Trace{"Watchdog.test_cmd", "Watchdog.test_cmd"}));
  EXPECT_FALSE(diff.only_left) << trace_text(*diff.only_left);
}

}  // namespace
}  // namespace smcbip::taste2bip::test
