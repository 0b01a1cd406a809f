// Composite SDL states flattened into the atom, run by the engines: entering one runs its
// entry procedure and the start of the entry point named, its substates answer the calls,
// the enclosing state's inputs apply inside it, and `return` leaves through `connect`.
#include <gtest/gtest.h>

#include "tests/taste2bip/sdl_atom_harness.h"

namespace smcbip::taste2bip::test {
namespace {

std::vector<double> reports(const RunRecord& r) {
  std::vector<double> out;
  for (const Event& e : r.of("out_report")) out.push_back(e.data.at("k.report_a0"));
  return out;
}

TEST(SdlAtomNested, CompositeStateEntersWorksAndLeaves) {
  const FunctionSpec spec{"T-Int ::= INTEGER (-1000..1000)\n",
                          {{"go", {{"x", "T-Int"}}}, {"poke", {}}},
                          {{"report", {{"v", "T-Int"}}}},
                          {}};
  const Translated t = translate_process(spec, R"(process F;
  dcl n T_Int := 0;
  state Busy;
  substructure
    in (fast);
    out (done);
    procedure entry;
      start;
        task n := n + 100;
        return;
    endprocedure;
    start;
      nextstate One;
    start fast;
      nextstate Two;
    state One;
      input go(n);
        output report(1);
        nextstate Two;
    endstate;
    state Two;
      input go(n);
        output report(2);
        return done;
    endstate;
  endsubstructure;
  start;
    nextstate Idle;
  state Idle;
    input go(n);
      decision n;
        (0): nextstate Busy;
        else: nextstate Busy via fast;
      enddecision;
  endstate;
  state Busy;
    input poke;
      output report(50);
      nextstate Idle;
    connect done;
      output report(n);
      nextstate Idle;
  endstate;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  EXPECT_NE(t.atom->text.find("Busy_One"), std::string::npos) << t.atom->text;
  // Properties see SDL states only: Idle stays marked, and `ready` taken, until Busy's start
  // (with its entry procedure) has reached Busy_One.
  EXPECT_NE(t.atom->text.find("on go_return from Idle__2 to Busy_from_Idle\n"), std::string::npos)
      << t.atom->text;
  EXPECT_NE(t.atom->text.find("from Idle, Busy_from_Idle to Busy_One, ready eager"),
            std::string::npos);
  const RunRecord r = run_process(
      t, {{0, "go", {"0"}}, {1, "go", {"7"}}, {2, "go", {"5"}}, {3, "go", {"3"}}, {4, "poke", {}}});
  // go(0) enters Busy at One; go(7) in One; go(5) in Two leaves through `connect done`;
  // go(3) enters through `fast` at Two; poke is the enclosing state's input.
  EXPECT_EQ(reports(r), (std::vector<double>{1, 2, 5, 50}));
  EXPECT_EQ(r.events.back().data.at("f.n"), 103);  // the entry procedure ran on each entry
}

TEST(SdlAtomNested, StateAggregationRunsItsRegionsSideBySide) {
  const FunctionSpec spec{"T-Int ::= INTEGER (-1000..1000)\n",
                          {{"go", {{"x", "T-Int"}}}, {"poke", {}}},
                          {{"report", {{"v", "T-Int"}}}},
                          {}};
  const Translated t = translate_process(spec, R"(process F;
  dcl n T_Int := 0, flag Boolean := false;
  state aggregation Both;
  substructure
    state Left;
    substructure
      start;
        nextstate L1;
      state L1;
        input go(n);
          output report(n);
          task flag := true;
          nextstate L1;
      endstate;
    endsubstructure;
    state Right;
    substructure
      start;
        nextstate R1;
      state R1;
        provided flag;
          task flag := false;
          output report(100);
          nextstate R1;
        input poke;
          output report(7);
          nextstate R1;
      endstate;
    endsubstructure;
    state Left;
    endstate;
    state Right;
    endstate;
  endsubstructure;
  start;
    nextstate Both;
endprocess F;)");
  ASSERT_TRUE(t.atom) << t.errors;
  // go goes to the left region, poke to the right one; the right region's continuous signal
  // sees the flag the left one sets.
  const RunRecord r = run_process(t, {{0, "go", {"5"}}, {1, "poke", {}}});
  EXPECT_EQ(reports(r), (std::vector<double>{5, 100, 7}));
}

}  // namespace
}  // namespace smcbip::taste2bip::test
