// The prover on the D-Finder benchmarks written from their published descriptions (train gate,
// temperature control), on each with a bug injected, and on the FDIR worked example of
// models/fdir/: every verdict compared with an exhaustive exploration of the model by the
// engines, and every counterexample's length with the shortest distance that exploration finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <string>
#include <unordered_map>

#include "fdir/fdir.h"
#include "monitors/monitors.h"
#include "tests/engines/temp_model.h"
#include "tests/fdir/exhaustive.h"
#include "tests/fdir/prove_support.h"

namespace smcbip::fdir {
namespace {

using testing::load;
using testing::prove_text;

/// Reads places and data of a reachable state by name ("gate", "down"), for the predicates of
/// the exhaustive explorations.
class StateReader {
 public:
  explicit StateReader(const bipc::ir::System& system) : system_(system) {}

  bool marked(const engines::RunState& s, const engines::Layout& layout, const std::string& atom,
              const std::string& place) const {
    const std::size_t a = atom_index(atom);
    const auto& places = system_.atom_types[system_.atoms[a].type].places;
    const auto found = std::find(places.begin(), places.end(), place);
    EXPECT_NE(found, places.end()) << atom << "." << place;
    return s.marking[layout.atom_places[a] + static_cast<std::size_t>(found - places.begin())] != 0;
  }

  std::int64_t value(const engines::RunState& s, const engines::Layout& layout,
                     const std::string& atom, const std::string& name) const {
    const std::size_t a = atom_index(atom);
    const auto& data = system_.atom_types[system_.atoms[a].type].data;
    const auto found = std::find_if(data.begin(), data.end(),
                                    [&](const bipc::ir::Data& d) { return d.name == name; });
    EXPECT_NE(found, data.end()) << atom << "." << name;
    return s.data[layout.atom_data[a] + static_cast<std::size_t>(found - data.begin())].i;
  }

 private:
  std::size_t atom_index(const std::string& path) const {
    for (std::size_t a = 0; a < system_.atoms.size(); ++a) {
      if (system_.atoms[a].path == path) return a;
    }
    ADD_FAILURE() << "no atom " << path;
    return 0;
  }

  const bipc::ir::System& system_;
};

using tests::shortest_distance;

bool has_place(const TraceState& state, const std::string& place) {
  return std::find(state.places.begin(), state.places.end(), place) != state.places.end();
}

std::string data_of(const TraceState& state, const std::string& name) {
  for (const auto& [key, value] : state.data) {
    if (key == name) return value;
  }
  return "";
}

bool deadlocked(const engines::RunState&, const engines::Layout&, bool deadlock) {
  return deadlock;
}

// ------------------------------------------------------------------------------- train gate

const std::string kTrainGate = "models/fdir/benchmarks/train_gate.bip";
const std::string kTrainGateEarlyRaise = "tests/fdir/models/train_gate_early_raise.bip";
const std::string kGateSafety = "A[] (t0.crossing || t1.crossing || t2.crossing) -> gate.down";

/// Some train is crossing while the gate is not down: the safety query's bad states.
tests::StatePredicate crossing_with_gate_up(const StateReader& read) {
  return [&read](const engines::RunState& s, const engines::Layout& layout, bool) {
    const bool crossing = read.marked(s, layout, "t0", "crossing") ||
                          read.marked(s, layout, "t1", "crossing") ||
                          read.marked(s, layout, "t2", "crossing");
    return crossing && !read.marked(s, layout, "gate", "down");
  };
}

TEST(Benchmarks, TheTrainGateIsSafeAndDeadlockFree) {
  const auto system = load(kTrainGate, "Crossing()");
  ASSERT_TRUE(system);
  const StateReader read(*system);
  ASSERT_FALSE(tests::some_reachable(*system, crossing_with_gate_up(read)));
  ASSERT_EQ(tests::reachable_deadlocks(*system), 0u);
  // The controller's count of trains between approach and exit is what keeps the gate down; no
  // invariant of one atom or trap relates it to the trains' places, so the exhaustive search
  // decides.
  const QueryOutcome safe = prove_text(*system, kGateSafety);
  EXPECT_EQ(safe.verdict, Verdict::Holds);
  EXPECT_EQ(safe.method, "exploration");
  EXPECT_EQ(prove_text(*system, "A[] !deadlock").verdict, Verdict::Holds);
  ASSERT_TRUE(tests::some_reachable(
      *system, [&read](const engines::RunState& s, const engines::Layout& layout, bool) {
        return read.marked(s, layout, "t0", "crossing") && read.marked(s, layout, "t1", "crossing");
      }));
  const QueryOutcome both = prove_text(*system, "E<> t0.crossing && t1.crossing");
  EXPECT_EQ(both.verdict, Verdict::Holds);
  ASSERT_FALSE(both.trace.empty());
  EXPECT_TRUE(has_place(both.trace.back(), "ROOT.t0.crossing"));
  EXPECT_TRUE(has_place(both.trace.back(), "ROOT.t1.crossing"));
}

TEST(Benchmarks, RaisingTheGateEarlyFlipsTheTrainGateSafety) {
  const auto system = load(kTrainGateEarlyRaise, "Crossing()");
  ASSERT_TRUE(system);
  const StateReader read(*system);
  const int shortest = shortest_distance(*system, crossing_with_gate_up(read));
  ASSERT_EQ(shortest, 7);  // two approaches, lower, two entries, one exit, raise
  const QueryOutcome o = prove_text(*system, kGateSafety);
  EXPECT_EQ(o.verdict, Verdict::Fails);
  EXPECT_EQ(o.method, "trace");
  ASSERT_EQ(o.trace.size(), static_cast<std::size_t>(shortest) + 1);
  EXPECT_TRUE(has_place(o.trace.back(), "ROOT.gate.up"));
  EXPECT_TRUE(has_place(o.trace.back(), "ROOT.t0.crossing") ||
              has_place(o.trace.back(), "ROOT.t1.crossing") ||
              has_place(o.trace.back(), "ROOT.t2.crossing"));
}

// ---------------------------------------------------------------------- temperature control

const std::string kTemperature = "models/fdir/benchmarks/temperature_control.bip";
const std::string kTemperatureOneRod = "tests/fdir/models/temperature_control_one_rod.bip";

std::string reactor(int heat, int cool, int rest) {
  return "Reactor(" + std::to_string(heat) + ", " + std::to_string(cool) + ", " +
         std::to_string(rest) + ")";
}

TEST(Benchmarks, TheTemperatureControlDeadlocksExactlyWhenTwoHeatingsAndACoolingAreTooShort) {
  // The condition derived in temperature_control.bip, against exhaustive exploration over a
  // grid of parameters reaching beyond it on both sides.
  for (int heat = 1; heat <= 3; ++heat) {
    for (int cool = 1; cool <= 2; ++cool) {
      for (int rest = 1; rest <= 2 * heat + cool + 2; ++rest) {
        const auto system = load(kTemperature, reactor(heat, cool, rest));
        ASSERT_TRUE(system);
        EXPECT_EQ(tests::reachable_deadlocks(*system) > 0, 2 * heat + cool < rest)
            << reactor(heat, cool, rest);
      }
    }
  }
}

TEST(Benchmarks, TheTemperatureControlDeadlockIsFoundWithTheShortestTrace) {
  const auto system = load(kTemperature, reactor(2, 1, 6));  // 2H + C = 5 < 6
  ASSERT_TRUE(system);
  const int shortest = shortest_distance(*system, deadlocked);
  // Eight ticks (the third maximum is at 3H + 2C = 8) and four moves of the rods.
  ASSERT_EQ(shortest, 12);
  const QueryOutcome o = prove_text(*system, "A[] !deadlock");
  EXPECT_EQ(o.verdict, Verdict::Fails);
  EXPECT_EQ(o.method, "trace");
  ASSERT_EQ(o.trace.size(), static_cast<std::size_t>(shortest) + 1);
  const TraceState& last = o.trace.back();
  EXPECT_TRUE(has_place(last, "ROOT.controller.heating"));
  EXPECT_EQ(data_of(last, "ROOT.controller.elapsed"), "2");  // at the maximum
  // Neither rod has rested R = 6: the one withdrawn first 2H + C = 5, the other H = 2.
  EXPECT_EQ(data_of(last, "ROOT.rod1.rested"), "5");
  EXPECT_EQ(data_of(last, "ROOT.rod2.rested"), "2");
}

TEST(Benchmarks, TheTemperatureControlWithRestingRodsIsDeadlockFree) {
  const auto system = load(kTemperature, reactor(2, 2, 6));  // 2H + C = 6 >= 6
  ASSERT_TRUE(system);
  ASSERT_EQ(tests::reachable_deadlocks(*system), 0u);
  const StateReader read(*system);
  ASSERT_FALSE(tests::some_reachable(*system, [&read](const engines::RunState& s,
                                                      const engines::Layout& layout, bool) {
    return read.marked(s, layout, "rod1", "inserted") && read.marked(s, layout, "rod2", "inserted");
  }));
  // Deadlock-freedom rests on the rods' rest counts against the controller's: no invariant of
  // one atom or trap states it, so the exhaustive search decides.
  const QueryOutcome o = prove_text(*system, "A[] !deadlock");
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.method, "exploration");
  EXPECT_EQ(prove_text(*system, "A[] !(rod1.inserted && rod2.inserted)").verdict, Verdict::Holds);
  // Both traps and the controller's places: a cooling controller has a rod inserted.
  const QueryOutcome inserted =
      prove_text(*system, "A[] controller.cooling -> (rod1.inserted || rod2.inserted)");
  EXPECT_EQ(inserted.verdict, Verdict::Holds);
  EXPECT_EQ(inserted.method, "invariants");
}

TEST(Benchmarks, WiringBothInsertionsToOneRodFlipsTheTemperatureControl) {
  const auto system = load(kTemperatureOneRod, reactor(2, 2, 6));  // H = 2 < 6
  ASSERT_TRUE(system);
  const int shortest = shortest_distance(*system, deadlocked);
  ASSERT_EQ(shortest, 8);  // six ticks (the second maximum, at 2H + C) and two moves
  const QueryOutcome o = prove_text(*system, "A[] !deadlock");
  EXPECT_EQ(o.verdict, Verdict::Fails);
  ASSERT_EQ(o.trace.size(), static_cast<std::size_t>(shortest) + 1);
  EXPECT_EQ(data_of(o.trace.back(), "ROOT.rod1.rested"), "2");
}

// --------------------------------------------------------------------- the FDIR worked example

tests::StatePredicate observer_error(const StateReader& read) {
  return [&read](const engines::RunState& s, const engines::Layout& layout, bool) {
    return read.marked(s, layout, "observer", "error");
  };
}

TEST(Benchmarks, TheRoverPowerFeedToleratesOneFault) {
  const auto system = load("models/fdir/single_fault.bip", "SingleFault()");
  ASSERT_TRUE(system);
  const StateReader read(*system);
  ASSERT_FALSE(tests::some_reachable(*system, observer_error(read)));
  ASSERT_EQ(tests::reachable_deadlocks(*system), 0u);
  EXPECT_EQ(prove_text(*system, "A[] !observer.error").verdict, Verdict::Holds);
  const QueryOutcome o = prove_text(*system, "A[] !deadlock");
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.method, "invariants");
  // The fault is isolated in some run: the detector watches the redundant unit.
  ASSERT_TRUE(tests::some_reachable(
      *system, [&read](const engines::RunState& s, const engines::Layout& layout, bool) {
        return read.marked(s, layout, "detector", "watching_redundant") &&
               read.marked(s, layout, "drive", "idle");
      }));
  EXPECT_EQ(prove_text(*system, "E<> detector.watching_redundant && drive.idle").verdict,
            Verdict::Holds);
}

TEST(Benchmarks, TheRoverPowerFeedFailsOnADoubleFault) {
  const auto system = load("models/fdir/double_fault.bip", "DoubleFault()");
  ASSERT_TRUE(system);
  const StateReader read(*system);
  const int to_error = shortest_distance(*system, observer_error(read));
  ASSERT_EQ(to_error, 6);  // a cycle, two faults, two missed demands, the isolation
  const int to_deadlock = shortest_distance(*system, deadlocked);
  ASSERT_EQ(to_deadlock, 6);
  const QueryOutcome error = prove_text(*system, "A[] !observer.error");
  EXPECT_EQ(error.verdict, Verdict::Fails);
  ASSERT_EQ(error.trace.size(), static_cast<std::size_t>(to_error) + 1);
  EXPECT_TRUE(has_place(error.trace.back(), "ROOT.observer.error"));
  const QueryOutcome deadlock = prove_text(*system, "A[] !deadlock");
  EXPECT_EQ(deadlock.verdict, Verdict::Fails);
  ASSERT_EQ(deadlock.trace.size(), static_cast<std::size_t>(to_deadlock) + 1);
  EXPECT_TRUE(has_place(deadlock.trace.back(), "ROOT.detector.lost"));
}

}  // namespace
}  // namespace smcbip::fdir
