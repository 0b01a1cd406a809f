// SDL timers in the translated atom, run by the engines: a timer set to a duration expires
// that long after, once; a reset timer never expires; the expiry is consumed in a state that
// has no input for it.
#include <gtest/gtest.h>

#include "tests/taste2bip/sdl_atom_harness.h"

namespace smcbip::taste2bip::test {
namespace {

FunctionSpec spec() {
  return FunctionSpec{"T-Int ::= INTEGER (-1000..1000)\n",
                      {{"go", {{"x", "T-Int"}}}},
                      {{"report", {{"v", "T-Int"}}}},
                      {}};
}

std::vector<double> report_times(const RunRecord& r) {
  std::vector<double> out;
  for (const Event& e : r.of("out_report")) out.push_back(e.time);
  return out;
}

TEST(SdlAtomTimers, SetTimerFiresAfterItsValue) {
  const Translated t = translate_process(spec(), R"(process F;
  timer t;
  dcl n T_Int;
  start;
    call set_timer(50, t);
    nextstate Wait;
  state Wait;
    input t;
      output report(1);
      nextstate Done;
  endstate;
  state Done;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {});
  EXPECT_EQ(report_times(r), (std::vector<double>{50}));
}

TEST(SdlAtomTimers, ResetTimerNeverFires) {
  const Translated t = translate_process(spec(), R"(process F;
  timer t;
  dcl n T_Int;
  start;
    call Set_Timer(50, T);
    nextstate Wait;
  state Wait;
    input go(n);
      call Reset_timer(t);
      nextstate Wait;
    input t;
      output report(1);
      nextstate Wait;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{10, "go", {"0"}}});
  EXPECT_TRUE(report_times(r).empty());
  EXPECT_EQ(r.result.end, engines::RunEnd::Deadlock) << r.trace;
}

TEST(SdlAtomTimers, ContextTimerRearmedByItsOwnInput) {
  FunctionSpec s = spec();
  s.timers = {"tick"};
  const Translated t = translate_process(s, R"(process F;
  dcl n T_Int := 0;
  start;
    call set_timer(20, tick);
    nextstate Run;
  state Run;
    input tick;
      task n := n + 1;
      output report(n);
      decision n < 3;
        (true): call set_timer(20, tick);
        (false):
      enddecision;
      nextstate Run;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {});
  EXPECT_EQ(report_times(r), (std::vector<double>{20, 40, 60}));
}

TEST(SdlAtomTimers, ExpiryInAStateWithoutItsInputIsConsumed) {
  const Translated t = translate_process(spec(), R"(process F;
  timer t;
  dcl n T_Int;
  start;
    call set_timer(30, t);
    nextstate Other;
  state Other;
    input go(n);
      nextstate Wait;
  endstate;
  state Wait;
    input t;
      output report(1);
      nextstate Wait;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  // The timer expires at 30 while the process is in Other: lost there, so Wait never hears it.
  const RunRecord r = run_process(t, {{40, "go", {"0"}}});
  EXPECT_TRUE(report_times(r).empty());
}

TEST(SdlAtomTimers, SdlSetAndResetForms) {
  const Translated t = translate_process(spec(), R"(process F;
  timer t, u;
  dcl n T_Int;
  start;
    call set(now + 30, t);
    call set(now + 10, u);
    call reset(u);
    nextstate Wait;
  state Wait;
    input t;
      output report(1);
      nextstate Wait;
    input u;
      output report(2);
      nextstate Wait;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {});
  EXPECT_EQ(report_times(r), (std::vector<double>{30}));
}

TEST(SdlAtomTimers, SavedCallWaitsForAStateThatTakesIt) {
  FunctionSpec s = spec();
  s.provided.push_back({"poke", {}});
  const Translated t = translate_process(s, R"(process F;
  timer t;
  start;
    call set_timer(20, t);
    nextstate A;
  state A;
    save poke;
    input t;
      nextstate B;
  endstate;
  state B;
    input poke;
      output report(5);
      nextstate B;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  ASSERT_EQ(t.atom->notes.size(), 1u);
  EXPECT_EQ(t.atom->notes[0], "'poke' is saved in state A: the call waits there");
  const RunRecord r = run_process(t, {{0, "poke", {}}});
  EXPECT_EQ(report_times(r), (std::vector<double>{20}));  // the call at 0 waited for B
}

}  // namespace
}  // namespace smcbip::taste2bip::test
