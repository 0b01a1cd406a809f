// The untimed abstraction (watchdog_untimed.h) on small models: clock comparisons hold, data
// conditions still decide, invariants and urgency are gone, and what it cannot abstract is
// refused with a reason.
#include "tests/taste2bip/watchdog_untimed.h"

#include <gtest/gtest.h>

#include "engines/engines.h"
#include "tests/engines/temp_model.h"
#include "tests/taste2bip/watchdog_traces.h"

namespace smcbip::taste2bip::test {
namespace {

// `go` needs x >= 5 and n == 0, `back` needs x < 3 or n > 10, and b bounds x by 2: timed, `back`
// can never follow `go`. Untimed, both clock conditions hold: go, back, then n == 1 keeps `go`
// off for good.
constexpr const char* kModel = R"(package untimed
  port type P()
  atom type A()
    clock x unit millisecond
    data int n = 0
    port P go(), back()
    place a, b
    initial to a do { x = 0; }
    on go from a to b provided (n == 0 && x >= 5) eager do { n = n + 1; }
    on back from b to a provided (x < 3 || n > 10)
    invariant i at b provided (x <= 2)
  end
  compound type Top()
    component A a()
  end
end
)";

TEST(WatchdogUntimed, ClockComparisonsHoldAndDataStillDecides) {
  std::optional<bipc::ir::System> system = tests::load_model_text(kModel, "Top()");
  ASSERT_TRUE(system);
  ASSERT_EQ(make_untimed(*system), "");
  const bipc::ir::AtomType& type = system->atom_types.at(0);
  EXPECT_TRUE(type.invariants.empty());
  for (const bipc::ir::Transition& t : type.transitions) {
    EXPECT_EQ(t.urgency, bipc::ir::Urgency::Lazy);
    for (const bipc::ir::Instr& in : t.guard.instrs) {
      EXPECT_FALSE(in.op == bipc::ir::Op::Load && in.scope == bipc::ir::Scope::Clock);
    }
  }
  WatchdogObservation observation;
  observation.ports = {{"a.go", "go"}, {"a.back", "back"}};
  TraceBounds bounds;
  bounds.events = 5;
  const TraceSet traces =
      projected_traces(*system, engines::Externs::with_builtins(), observation, bounds);
  EXPECT_EQ(traces.problem, "");
  const std::set<Trace, ShorterFirst> expected = {{}, {"go"}, {"go", "back"}};
  EXPECT_EQ(traces.traces, expected);
  EXPECT_FALSE(traces.cut);

  // Unobserved, `go` and `back` are silent steps: one silent step allowed leaves `back`'s
  // state unexplored, and the exploration says so.
  bounds.silent_steps = 1;
  const TraceSet silent =
      projected_traces(*system, engines::Externs::with_builtins(), WatchdogObservation{}, bounds);
  EXPECT_TRUE(silent.cut);
  EXPECT_EQ(silent.states, 2u);
}

TEST(WatchdogUntimed, AClockPassedToAFunctionIsRefused) {
  bipc::ir::System system;
  bipc::ir::ExternFunction f;
  f.name = "f";
  f.result = bipc::ir::DataType{bipc::ir::ValueKind::Bool};
  f.params = {bipc::ir::DataType{bipc::ir::ValueKind::Float}};
  system.functions.push_back(f);
  bipc::ir::Transition t;
  bipc::ir::Instr load, call;
  load.op = bipc::ir::Op::Load;
  load.scope = bipc::ir::Scope::Clock;
  call.op = bipc::ir::Op::Call;
  call.arg = 1;
  t.guard.instrs = {load, call};
  system.atom_types.emplace_back().transitions.push_back(t);
  EXPECT_EQ(make_untimed(system), "a clock's value is passed to a function");
}

}  // namespace
}  // namespace smcbip::taste2bip::test
