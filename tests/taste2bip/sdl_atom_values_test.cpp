// SDL constructs that compute values, run by the engines: a loop whose bound is known only at
// run time, a procedure returning a value into a task, a conditional expression, SEQUENCE OF
// elements written at a variable index, CHOICE values and their `present`.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/taste2bip/sdl_atom_harness.h"

namespace smcbip::taste2bip::test {
namespace {

const char* const kTypes = R"(
T-Int ::= INTEGER (-1000..1000)
Vec ::= SEQUENCE (SIZE (1..4)) OF T-Int
Either ::= CHOICE { num T-Int, flag BOOLEAN }
)";

FunctionSpec spec() {
  return FunctionSpec{kTypes, {{"go", {{"x", "T-Int"}}}}, {{"report", {{"v", "T-Int"}}}}, {}};
}

std::vector<double> reports(const RunRecord& r) {
  std::vector<double> out;
  for (const Event& e : r.of("out_report")) out.push_back(e.data.at("k.report_a0"));
  return out;
}

TEST(SdlAtomValues, LoopWithARunTimeBoundAndVariableIndex) {
  const Translated t = translate_process(spec(), R"(process F;
  dcl n T_Int, s T_Int, v Vec;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      task v := {0, 0, 0, 0};
      task for i in range(n): v(i) := i * 10; endfor;
      task s := 0;
      task for i in range(length(v)): s := s + i; endfor;
      output report(v(0) + v(1) + v(2) + v(3) + s);
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"2"}}, {1, "go", {"4"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{10 + 6, 60 + 6}));
}

TEST(SdlAtomValues, LoopOverTheElementsOfAVariableSizeSequence) {
  const Translated t = translate_process(spec(), R"(process F;
  dcl n T_Int, s T_Int, v Vec;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      decision n;
        (1): task v := {7};
        else: task v := {1, 2, 3};
      enddecision;
      task s := 0;
      task for x in v: s := s * 10 + x; endfor;
      output report(s);
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"1"}}, {1, "go", {"0"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{7, 123}));
}

TEST(SdlAtomValues, ProcedureReturnsAValueIntoATask) {
  const Translated t = translate_process(spec(), R"(process F;
  dcl n T_Int, m T_Int;
  procedure square;
    fpar in a T_Int;
    returns T_Int;
    start;
      decision a < 0;
        (true): return -a * a;
        (false): return a * a;
      enddecision;
  endprocedure;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      task m := call square(n + 1);
      output report(m);
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"2"}}, {1, "go", {"-4"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{9, -9}));
}

TEST(SdlAtomValues, ConditionalExpressionAndChoice) {
  const Translated t = translate_process(spec(), R"(process F;
  dcl n T_Int, e Either;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      task e := if n > 0 then num: n else flag: true fi;
      decision present(e);
        (num): output report(e.num);
        (flag): output report(-1);
      enddecision;
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"6"}}, {1, "go", {"0"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{6, -1}));
}

TEST(SdlAtomValues, DecisionAnyTakesEitherAnswer) {
  const Translated t = translate_process(spec(), R"(process F;
  dcl n T_Int;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      decision any;
        ('one'): output report(1);
        ('two'): output report(2);
      enddecision;
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  std::vector<Call> calls;
  for (int k = 0; k < 12; ++k) calls.push_back({static_cast<double>(k), "go", {"0"}});
  const std::vector<double> seen = reports(run_process(t, calls));
  ASSERT_EQ(seen.size(), 12u);
  EXPECT_NE(std::count(seen.begin(), seen.end(), 1.0), 0);
  EXPECT_NE(std::count(seen.begin(), seen.end(), 2.0), 0);
}

TEST(SdlAtomValues, EnablingConditionKeepsTheCallWaiting) {
  FunctionSpec s = spec();
  s.provided.push_back({"open", {}});
  const Translated t = translate_process(s, R"(process F;
  dcl n T_Int, ready Boolean := false;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      provided ready;
      output report(n);
      nextstate Idle;
    input open;
      task ready := true;
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  // The driver's go at 0 waits until ready; nothing else can open it, so the run deadlocks.
  const RunRecord r = run_process(t, {{0, "go", {"4"}}, {1, "open", {}}});
  EXPECT_TRUE(reports(r).empty());
  EXPECT_EQ(r.result.end, engines::RunEnd::Deadlock);
}

TEST(SdlAtomValues, StructuredValuesComparedWithLiterals) {
  const Translated t = translate_process(spec(), R"(process F;
  dcl n T_Int, e Either, v Vec;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      task e := num: n, v := {n, 2};
      decision e;
        (num: 3): output report(30);
        (flag: true): output report(-1);
        else:
          decision v = {4, 2};
            (true): output report(42);
            (false): output report(0);
          enddecision;
      enddecision;
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  const RunRecord r = run_process(t, {{0, "go", {"3"}}, {1, "go", {"4"}}, {2, "go", {"5"}}});
  EXPECT_EQ(reports(r), (std::vector<double>{30, 42, 0}));
}

TEST(SdlAtomValues, ContextParameterHasItsValue) {
  FunctionSpec s = spec();
  s.context.push_back({"limit", "T-Int", "42"});
  const Translated t = translate_process(s, R"(process F;
  dcl n T_Int;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      output report(n + f_ctxt.limit);
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  EXPECT_EQ(reports(run_process(t, {{0, "go", {"1"}}})), (std::vector<double>{43}));
}

}  // namespace
}  // namespace smcbip::taste2bip::test
