// The SDL reader on transitions (tasks, outputs, calls, decisions, loops, labels) and expressions.
#include <gtest/gtest.h>

#include "sdl_test_support.h"

namespace smcbip::taste2bip::sdl {
namespace {

using testing::in_transition;
using testing::read_ok;
using testing::show;
using testing::transition_of;

std::string expression(const std::string& text) {
  const SdlFile file = read_ok(in_transition("task x := " + text + ";"));
  const auto& actions = transition_of(file);
  if (actions.empty() || actions[0].task.empty()) return "<none>";
  return show(actions[0].task[0].value);
}

TEST(SdlTransition, TasksOfAssignmentsAndInformalText) {
  const SdlFile file = read_ok(in_transition(
      "task a := 1, b(2).c := 'it''s';\ntask 'do something'\n comment 'c';\nnextstate -;"));
  const auto& actions = transition_of(file);
  ASSERT_EQ(actions.size(), 3u);
  ASSERT_EQ(actions[0].kind, Action::Kind::Task);
  ASSERT_EQ(actions[0].task.size(), 2u);
  EXPECT_EQ(actions[0].task[0].kind, TaskElement::Kind::Assignment);
  EXPECT_EQ(show(actions[0].task[0].target), "a");
  EXPECT_EQ(show(actions[0].task[1].target), "(call b 2).c");
  EXPECT_EQ(show(actions[0].task[1].value), "'it's'");
  EXPECT_EQ(actions[0].task[1].at.line, 4u);
  EXPECT_EQ(actions[0].task[1].at.column, 14u);
  ASSERT_EQ(actions[1].task.size(), 1u);
  EXPECT_EQ(actions[1].task[0].kind, TaskElement::Kind::Informal);
  EXPECT_EQ(actions[1].task[0].text, "do something");
  EXPECT_EQ(actions[1].comment, "c");
  EXPECT_EQ(actions[2].kind, Action::Kind::NextState);
}

TEST(SdlTransition, OutputsAndCalls) {
  const SdlFile file = read_ok(in_transition(
      "output housekeeping(31), ping;\noutput s(1) to dest via r;\n"
      "call set_timer(1000, Clock);\ncall reset_timer(Clock);\ncall writeln\n('a', x);\n"
      "call proc;\nset(now + 10, t);\nreset(t);\nstop;"));
  const auto& actions = transition_of(file);
  ASSERT_EQ(actions.size(), 9u);
  EXPECT_EQ(actions[0].kind, Action::Kind::Output);
  ASSERT_EQ(actions[0].outputs.size(), 2u);
  EXPECT_EQ(actions[0].outputs[0].name, "housekeeping");
  ASSERT_EQ(actions[0].outputs[0].arguments.size(), 1u);
  EXPECT_EQ(show(actions[0].outputs[0].arguments[0]), "31");
  EXPECT_EQ(actions[0].outputs[1].name, "ping");
  EXPECT_TRUE(actions[0].outputs[1].arguments.empty());
  ASSERT_TRUE(actions[1].to.has_value());
  EXPECT_EQ(show(*actions[1].to), "dest");
  EXPECT_EQ(actions[1].via, "r");
  EXPECT_EQ(actions[2].kind, Action::Kind::Call);
  EXPECT_EQ(actions[2].name, "set_timer");
  ASSERT_EQ(actions[2].arguments.size(), 2u);
  EXPECT_EQ(show(actions[2].arguments[1]), "Clock");
  EXPECT_EQ(actions[3].name, "reset_timer");
  EXPECT_EQ(actions[4].name, "writeln");
  EXPECT_EQ(actions[4].arguments.size(), 2u);
  EXPECT_TRUE(actions[5].arguments.empty());
  EXPECT_EQ(actions[6].name, "set");
  EXPECT_EQ(show(actions[6].arguments.at(0)), "(+ now 10)");
  EXPECT_EQ(actions[7].name, "reset");
  EXPECT_EQ(actions[8].kind, Action::Kind::Stop);
}

TEST(SdlTransition, DecisionAnswerKinds) {
  const SdlFile file = read_ok(in_transition(R"(decision n;
  (1): task a := 1;
  (<2):
  (>= 3):
  (/= 4):
  (-1:1, 7):
  (a:TRUE):
  else: nextstate S;
enddecision;
decision any;
  ('first'): stop;
  ('second'):
enddecision;
nextstate -;)"));
  const auto& actions = transition_of(file);
  ASSERT_EQ(actions.size(), 3u);
  ASSERT_EQ(actions[0].kind, Action::Kind::Decision);
  const Decision& decision = actions[0].decision;
  EXPECT_FALSE(decision.is_any);
  EXPECT_EQ(show(decision.question), "n");
  ASSERT_EQ(decision.answers.size(), 7u);
  const auto& a = decision.answers;
  EXPECT_EQ(a[0].conditions.at(0).kind, RangeCondition::Kind::Value);
  EXPECT_EQ(show(a[0].conditions.at(0).low), "1");
  EXPECT_EQ(a[0].transition.actions.size(), 1u);
  EXPECT_EQ(a[1].conditions.at(0).kind, RangeCondition::Kind::Open);
  EXPECT_EQ(a[1].conditions.at(0).op, Operator::Less);
  EXPECT_TRUE(a[1].transition.actions.empty());
  EXPECT_EQ(a[2].conditions.at(0).op, Operator::GreaterEqual);
  EXPECT_EQ(show(a[2].conditions.at(0).low), "3");
  EXPECT_EQ(a[3].conditions.at(0).op, Operator::NotEqual);
  ASSERT_EQ(a[4].conditions.size(), 2u);
  EXPECT_EQ(a[4].conditions[0].kind, RangeCondition::Kind::Closed);
  EXPECT_EQ(show(a[4].conditions[0].low), "(- 1)");
  EXPECT_EQ(show(a[4].conditions[0].high), "1");
  EXPECT_EQ(a[4].conditions[1].kind, RangeCondition::Kind::Value);
  // A name before ':' is a CHOICE value, as in OpenGEODE's grammar.
  EXPECT_EQ(a[5].conditions.at(0).kind, RangeCondition::Kind::Value);
  EXPECT_EQ(show(a[5].conditions.at(0).low), "a:true");
  EXPECT_TRUE(a[6].is_else);
  EXPECT_EQ(a[6].at.line, 11u);
  EXPECT_EQ(a[6].at.column, 3u);
  EXPECT_TRUE(actions[1].decision.is_any);
  ASSERT_EQ(actions[1].decision.answers.size(), 2u);
  EXPECT_EQ(show(actions[1].decision.answers[0].conditions.at(0).low), "'first'");
}

TEST(SdlTransition, NestedDecisions) {
  const SdlFile file = read_ok(in_transition(
      "decision a;\n (true): decision b; (1): stop; enddecision;\n (false): enddecision;"));
  const auto& actions = transition_of(file);
  ASSERT_EQ(actions.size(), 1u);
  const Answer& yes = actions[0].decision.answers.at(0);
  ASSERT_EQ(yes.transition.actions.size(), 1u);
  EXPECT_EQ(yes.transition.actions[0].decision.answers.at(0).transition.actions.at(0).kind,
            Action::Kind::Stop);
}

TEST(SdlTransition, LabelsJoinsAndTerminators) {
  const SdlFile file = read_ok(in_transition("Here:\n call f;\n join Here;"));
  const auto& actions = transition_of(file);
  ASSERT_EQ(actions.size(), 3u);
  EXPECT_EQ(actions[0].kind, Action::Kind::Label);
  EXPECT_EQ(actions[0].name, "Here");
  EXPECT_EQ(actions[0].at.line, 4u);
  EXPECT_EQ(actions[2].kind, Action::Kind::Join);
  EXPECT_EQ(actions[2].name, "Here");
}

TEST(SdlTransition, ForLoops) {
  const SdlFile file = read_ok(in_transition(R"(task for x in range(4, 10, 2):
   n := n + x mod 255
   n := n * 2
endfor;
task for x in seq1:
  call writeln(x);
endfor, y := 2;
nextstate -;)"));
  const auto& actions = transition_of(file);
  ASSERT_EQ(actions.size(), 3u);
  ASSERT_EQ(actions[0].task.size(), 1u);
  EXPECT_EQ(actions[0].task[0].kind, TaskElement::Kind::ForLoop);
  const ForLoop& range = actions[0].task[0].loop.at(0);
  EXPECT_EQ(range.variable, "x");
  EXPECT_EQ(show(range.iterable), "(call range 4 10 2)");
  ASSERT_EQ(range.body.actions.size(), 2u);
  EXPECT_EQ(range.body.actions[0].kind, Action::Kind::Task);
  EXPECT_EQ(show(range.body.actions[0].task.at(0).value), "(+ n (mod x 255))");
  ASSERT_EQ(actions[1].task.size(), 2u);
  const ForLoop& over = actions[1].task[0].loop.at(0);
  EXPECT_EQ(show(over.iterable), "seq1");
  EXPECT_EQ(over.body.actions.at(0).kind, Action::Kind::Call);
  EXPECT_EQ(actions[1].task[1].kind, TaskElement::Kind::Assignment);
}

TEST(SdlTransition, EmptyActionsAreAccepted) {
  const SdlFile file = read_ok(in_transition("task foo := 1;;\nnextstate -;"));
  EXPECT_EQ(transition_of(file).size(), 2u);
}

TEST(SdlExpression, Literals) {
  EXPECT_EQ(expression("42"), "42");
  EXPECT_EQ(expression("-10.0"), "(- 10.0)");
  EXPECT_EQ(expression("1.5e3"), "1.5e3");
  EXPECT_EQ(expression("PLUS-INFINITY"), "plus-infinity");
  EXPECT_EQ(expression("plus - infinity"), "(- plus infinity)");
  EXPECT_EQ(expression("'text'"), "'text'");
  EXPECT_EQ(expression("TRUE"), "true");
  EXPECT_EQ(expression("hello"), "hello");
  EXPECT_EQ(expression("'0101'B"), "'0101'B");
  EXPECT_EQ(expression("'0aFF'h"), "'0aFF'H");
  EXPECT_EQ(expression("\"01 10\"B"), "'0110'B");
  EXPECT_EQ(expression("\"0A\"H"), "'0A'H");
  EXPECT_EQ(expression("'xyz' // 'ab'"), "(// 'xyz' 'ab')");
}

TEST(SdlExpression, Precedence) {
  EXPECT_EQ(expression("42 + 5 * 3 - 1"), "(- (+ 42 (* 5 3)) 1)");
  EXPECT_EQ(expression("(a + 1) mod 10"), "(mod (+ a 1) 10)");
  EXPECT_EQ(expression("a / b rem c"), "(rem (/ a b) c)");
  EXPECT_EQ(expression("a = 1 and b /= 2 or not c"), "(or (and (= a 1) (/= b 2)) (not c))");
  EXPECT_EQ(expression("a or b xor c"), "(xor (or a b) c)");
  EXPECT_EQ(expression("a and then b or else c"), "(or else (and then a b) c)");
  EXPECT_EQ(expression("a implies b or c"), "(implies a (or b c))");
  EXPECT_EQ(expression("a => b => c"), "(implies (implies a b) c)");
  EXPECT_EQ(expression("x < 1 and y <= 2 and z > 3 and w >= 4"),
            "(and (and (and (< x 1) (<= y 2)) (> z 3)) (>= w 4))");
  EXPECT_EQ(expression("n in {1, 2}"), "(in n {1, 2})");
  EXPECT_EQ(expression("s // 'x'"), "(// s 'x')");
  EXPECT_EQ(expression("- a * b"), "(* (- a) b)");
}

TEST(SdlExpression, NamesFieldsCallsAndConditionals) {
  EXPECT_EQ(expression("a.b!c"), "a.b.c");
  EXPECT_EQ(expression("b(1)"), "(call b 1)");
  EXPECT_EQ(expression("length(b)"), "(call length b)");
  EXPECT_EQ(expression("present(tc!content) = patch"), "(= (call present tc.content) patch)");
  EXPECT_EQ(expression("if e!a then 8 else if b(0) = hello then a else 9 fi fi"),
            "(if e.a 8 (if (= (call b 0) hello) a 9))");
  EXPECT_EQ(expression("call multireturn(a)"), "(pcall multireturn a)");
}

TEST(SdlExpression, Asn1Values) {
  EXPECT_EQ(expression("{ hello, world }"), "{hello, world}");
  EXPECT_EQ(expression("{a 5, b taste}"), "{a 5, b taste}");
  EXPECT_EQ(expression("{}"), "{}");
  EXPECT_EQ(expression("{ a { x if e!a then 5 else 9 fi, y 6 } }"), "{a {x (if e.a 5 9), y 6}}");
  EXPECT_EQ(expression("{ {x 4}, {x 5} }"), "{{x 4}, {x 5}}");
  EXPECT_EQ(expression("b:{a 33, b you}"), "b:{a 33, b you}");
  EXPECT_EQ(expression("B:C:TRUE"), "B:C:true");
  EXPECT_EQ(expression("{a call f(1), b not c}"), "{a (pcall f 1), b (not c)}");
  EXPECT_EQ(expression("{mantissa 1, base 2, exponent -5}"),
            "{mantissa 1, base 2, exponent (- 5)}");
}

TEST(SdlExpression, Locations) {
  const SdlFile file = read_ok(in_transition("task x := a +\n  b(1);"));
  const Expr& sum = transition_of(file).at(0).task.at(0).value;
  EXPECT_EQ(sum.at.line, 4u);
  EXPECT_EQ(sum.at.column, 13u);
  EXPECT_EQ(sum.operands.at(1).at.line, 5u);
  EXPECT_EQ(sum.operands.at(1).at.column, 3u);  // a call sits where its callee starts
  EXPECT_EQ(sum.operands.at(0).at.column, 11u);
}

TEST(SdlTransition, TaskBodiesWithoutTheTaskKeyword) {
  const SdlFile file = read_ok(in_transition(
      "x := 1, y := 2;\na(1)!b := 3;\n'informal';\nfor i in range(3): call f(i); endfor;\n"
      "task;\nnextstate -;"));
  const auto& actions = transition_of(file);
  ASSERT_EQ(actions.size(), 6u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(actions[i].kind, Action::Kind::Task) << i;
  EXPECT_EQ(actions[0].task.size(), 2u);
  EXPECT_EQ(show(actions[1].task.at(0).target), "(call a 1).b");
  EXPECT_EQ(actions[2].task.at(0).kind, TaskElement::Kind::Informal);
  EXPECT_EQ(actions[3].task.at(0).kind, TaskElement::Kind::ForLoop);
  EXPECT_TRUE(actions[4].task.empty());
}

}  // namespace
}  // namespace smcbip::taste2bip::sdl
