// What the SDL translation refuses: each refusal is an error at the construct, in the SDL
// file, and no atom is made.
#include <gtest/gtest.h>

#include "tests/taste2bip/sdl_atom_harness.h"

namespace smcbip::taste2bip::test {
namespace {

FunctionSpec spec() {
  return FunctionSpec{"T-Int ::= INTEGER (-1000..1000)\nArr ::= SEQUENCE (SIZE (3)) OF T-Int\n",
                      {{"go", {{"x", "T-Int"}}}},
                      {{"report", {{"v", "T-Int"}}}},
                      {}};
}

/// The errors of translating a process whose state Idle runs `actions` on `go(n)`.
std::string errors_of(const std::string& actions, const std::string& declarations = "") {
  const Translated t =
      translate_process(spec(), "process F;\n  dcl n T_Int, a Arr;\n" + declarations +
                                    "  start;\n    nextstate Idle;\n"
                                    "  state Idle;\n    input go(n);\n" +
                                    actions + "\n  endstate;\nendprocess F;\n");
  EXPECT_FALSE(t.atom) << t.atom->text;
  return t.errors;
}

TEST(SdlAtomRefusals, OutputToNoRequiredInterface) {
  EXPECT_EQ(errors_of("      output nope(1);\n      nextstate Idle;"),
            "test.pr:7:14: error: output 'nope' names no required interface of F\n");
}

TEST(SdlAtomRefusals, IndexThatIsNotAConstantInAnExpression) {
  EXPECT_EQ(errors_of("      output report(a(n));\n      nextstate Idle;"),
            "test.pr:7:23: error: indexing with an index that is not a constant is not "
            "translated\n");
}

TEST(SdlAtomRefusals, UnknownName) {
  EXPECT_EQ(errors_of("      task n := zork + 1;\n      nextstate Idle;"),
            "test.pr:7:17: error: unknown name 'zork'\n");
}

TEST(SdlAtomRefusals, RecursiveProcedure) {
  const std::string recursive =
      "  procedure p;\n    start;\n      call p;\n      return;\n  endprocedure;\n";
  EXPECT_EQ(errors_of("      call p;\n      nextstate Idle;", recursive),
            "test.pr:5:7: error: recursive call of procedure 'p' is not translated\n");
}

TEST(SdlAtomRefusals, LoopOfMoreThan64Iterations) {
  EXPECT_EQ(errors_of("      task for i in range(100): n := n + i; endfor;\n      nextstate Idle;"),
            "test.pr:7:21: error: a loop of more than 64 iterations is not unrolled\n");
}

TEST(SdlAtomRefusals, TransitionWithoutTerminator) {
  EXPECT_NE(errors_of("      task n := 1;")
                .find("error: a transition that ends without nextstate, join or stop"),
            std::string::npos);
}

TEST(SdlAtomRefusals, LeavingAStateAggregationAndSpontaneousTransition) {
  const Translated t = translate_process(spec(), R"(process F;
  state aggregation Both;
  substructure
    state A;
    substructure
      start;
        nextstate S;
      state S;
        input go(n);
          return;
      endstate;
    endsubstructure;
  endsubstructure;
  dcl n T_Int;
  start;
    nextstate Idle;
  state Idle;
    input none;
      nextstate Both;
  endstate;
  state Both;
    input go(n);
      nextstate Idle;
  endstate;
endprocess F;)");
  EXPECT_FALSE(t.atom);
  EXPECT_EQ(t.errors,
            "test.pr:18:11: error: a spontaneous transition (input none) is not translated\n"
            "test.pr:21:3: error: transitions of a state enclosing a state aggregation are not "
            "translated\n"
            "test.pr:10:11: error: leaving a state aggregation or one of its regions is not "
            "translated\n");
}

}  // namespace
}  // namespace smcbip::taste2bip::test
