// SDL processes translated to BIP atoms and run by the engines: inputs copy their parameters,
// outputs carry values, decisions take the branch their answer names, calls a state does not
// handle are consumed, and the chain of a transition takes no time.
#include <gtest/gtest.h>

#include "tests/taste2bip/sdl_atom_harness.h"

namespace smcbip::taste2bip::test {
namespace {

const char* const kTypes = R"(
T-Int ::= INTEGER (-1000..1000)
T-Real ::= REAL (-1000.0 .. 1000.0)
Color ::= ENUMERATED { red, green(5), blue }
Pair ::= SEQUENCE { a T-Int, b T-Int }
)";

FunctionSpec go_report() {
  return FunctionSpec{kTypes, {{"go", {{"x", "T-Int"}}}}, {{"report", {{"v", "T-Int"}}}}, {}};
}

/// The values `report` carried, in order.
std::vector<double> reports(const RunRecord& r) {
  std::vector<double> out;
  for (const Event& e : r.of("out_report")) out.push_back(e.data.at("k.report_a0"));
  return out;
}

std::vector<double> times(const std::vector<Event>& events) {
  std::vector<double> out;
  for (const Event& e : events) out.push_back(e.time);
  return out;
}

TEST(SdlAtomBehaviour, InputCopiesItsParameterAndOutputCarriesAValue) {
  const Translated t = translate_process(go_report(), R"(process F;
  dcl n T_Int := 0;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      output report(n * 2);
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"7"}}, {10, "go", {"3"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{14, 6}));
  // Run to completion: the output and the return come at the date of the call.
  EXPECT_EQ(times(r.of("out_report")), (std::vector<double>{0, 10}));
  EXPECT_EQ(times(r.of("ret_go")), (std::vector<double>{0, 10}));
  EXPECT_EQ(r.events.back().data.at("f.n"), 3);
}

TEST(SdlAtomBehaviour, DecisionTakesTheAnswerItsValueNames) {
  const Translated t = translate_process(go_report(), R"(process F;
  dcl n T_Int;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      decision n;
        (< 0): output report(-1);
        (0): output report(0);
        (1:5): output report(1);
        (7, 9): output report(3);
        else: output report(2);
      enddecision;
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(
      t,
      {{0, "go", {"-3"}}, {1, "go", {"0"}}, {2, "go", {"4"}}, {3, "go", {"6"}}, {4, "go", {"9"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{-1, 0, 1, 2, 3}));
}

TEST(SdlAtomBehaviour, UnhandledCallIsConsumedAndNextstateDashStays) {
  FunctionSpec spec = go_report();
  spec.provided.push_back({"poke", {}});
  const Translated t = translate_process(spec, R"(process F;
  dcl n T_Int;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      output report(n);
      nextstate -;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "poke", {}}, {5, "go", {"4"}}, {6, "poke", {}}});
  EXPECT_EQ(times(r.of("ret_poke")), (std::vector<double>{0, 6}));
  EXPECT_EQ(reports(r), (std::vector<double>{4}));
}

TEST(SdlAtomBehaviour, InputStarAndStateStar) {
  FunctionSpec spec = go_report();
  spec.provided.push_back({"poke", {}});
  spec.provided.push_back({"flip", {}});
  const Translated t = translate_process(spec, R"(process F;
  dcl n T_Int := 0;
  start;
    nextstate A;
  state A;
    input flip;
      nextstate B;
    input *;
      output report(1);
      nextstate -;
  endstate;
  state B;
    input flip;
      nextstate A;
  endstate;
  state *;
    input poke;
      output report(100);
      nextstate -;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  // In A, go is caught by `input *` and poke by the input of `state *`, which every state has;
  // in B, poke by `state *` and go is consumed.
  const RunRecord r = run_process(
      t, {{0, "go", {"1"}}, {1, "poke", {}}, {2, "flip", {}}, {3, "poke", {}}, {4, "go", {"1"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{1, 100, 100}));
}

TEST(SdlAtomBehaviour, JoinLoopsBackToALabel) {
  const Translated t = translate_process(go_report(), R"(process F;
  dcl n T_Int;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      again:
      decision n > 0;
        (true):
          task n := n - 1;
          output report(n);
          join again;
        (false):
          nextstate Idle;
      enddecision;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"3"}}, {1, "go", {"1"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{2, 1, 0, 0}));
}

TEST(SdlAtomBehaviour, ALabelInAnUnrolledLoopIsOnePlacePerIteration) {
  // Each iteration passes the label once: the second must not lead back into the first.
  const Translated t = translate_process(go_report(), R"(process F;
  dcl n T_Int;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      for i in range(3):
        here:
        task n := n + 1;
        output report(n);
      endfor;
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"10"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{11, 12, 13}));
}

TEST(SdlAtomBehaviour, FloatingLabelIsReachedByJoin) {
  const Translated t = translate_process(go_report(), R"(process F;
  dcl n T_Int;
  start;
    join init;
  connection init:
    task n := 41;
    nextstate Idle;
  endconnection;
  state Idle;
    input go(n);
      output report(n);
      join init;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"5"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{5}));
  EXPECT_EQ(r.events.back().data.at("f.n"), 41);
}

TEST(SdlAtomBehaviour, ProcedureCopiesInAndInOutParameters) {
  const Translated t = translate_process(go_report(), R"(process F;
  dcl n T_Int, m T_Int := 1;
  procedure twice;
    fpar in a T_Int, in/out b T_Int;
    start;
      task b := b + a * 2;
      return;
  endprocedure;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      call twice(n, m);
      output report(m);
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"5"}}, {1, "go", {"1"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{11, 13}));
}

TEST(SdlAtomBehaviour, SynchronousRequiredInterfaceReturnsItsOutParameter) {
  FunctionSpec spec = go_report();
  spec.required.push_back(
      {"compute", {{"a", "T-Int"}, {"b", "T-Int", true}}, InterfaceKind::Protected});
  const Translated t = translate_process(spec, R"(process F;
  dcl n T_Int, m T_Int;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      call compute(n + 1, m);
      output report(m);
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"2"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{30}));  // the sink answers 10 times its input
}

TEST(SdlAtomBehaviour, RecordsEnumerantsLoopsAndWriteln) {
  const Translated t = translate_process(go_report(), R"(process F;
  dcl n T_Int, p Pair, c Color := green;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      task p := {a 3, b n};
      task for i in range(1, 4): p.a := p.a + i; endfor;
      decision c;
        (green): output report(p.a + p.b);
        else: output report(-1);
      enddecision;
      call writeln('sum ', p.a + p.b, ' color ', c, ' ', c = green, ' 100%');
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"4"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{13}));  // 3 + 1 + 2 + 3, plus 4
  EXPECT_EQ(r.output, "sum 13 color 5 TRUE 100%\n");
}

TEST(SdlAtomBehaviour, ContinuousSignalFiresAsSoonAsItHolds) {
  const Translated t = translate_process(go_report(), R"(process F;
  dcl n T_Int := 0;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      nextstate Idle;
    provided n > 5;
      priority 2;
      output report(n);
      task n := 0;
      nextstate Idle;
    provided n > 8;
      priority 1;
      output report(-n);
      task n := 0;
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"3"}}, {1, "go", {"7"}}, {2, "go", {"9"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{7, -9}));
  EXPECT_EQ(times(r.of("out_report")), (std::vector<double>{1, 2}));
}

}  // namespace
}  // namespace smcbip::taste2bip::test
