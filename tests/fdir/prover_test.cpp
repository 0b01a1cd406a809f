// The prover's verdicts on the benchmarks and on the same models with a bug injected, each
// compared with the verdict of an exhaustive exploration of the model.
#include <gtest/gtest.h>

#include <string>

#include "fdir/fdir.h"
#include "monitors/monitors.h"
#include "tests/engines/temp_model.h"
#include "tests/fdir/exhaustive.h"
#include "tests/fdir/prove_support.h"

namespace smcbip::fdir {
namespace {

struct Case {
  std::string file, root;
};

using testing::prove_text;

std::optional<bipc::ir::System> load(const Case& c) { return testing::load(c.file, c.root); }

const Case kOneAtATime{"models/fdir/benchmarks/philosophers_one_at_a_time.bip", "Table()"};
const Case kTogether{"models/fdir/benchmarks/philosophers_together.bip", "Table()"};
const Case kAsymmetric{"tests/fdir/models/philosophers_asymmetric.bip", "Table()"};
const Case kStickyFork{"tests/fdir/models/philosophers_sticky_fork.bip", "Table()"};
const Case kCounter{"tests/fdir/models/bounded_counter.bip", "Top()"};
const Case kCounterBug{"tests/fdir/models/bounded_counter_off_by_one.bip", "Top()"};

TEST(Prover, PhilosophersTakingForksOneAtATimeDeadlockWithATrace) {
  const auto system = load(kOneAtATime);
  ASSERT_TRUE(system);
  ASSERT_EQ(tests::reachable_deadlocks(*system), 1u);
  const QueryOutcome o = prove_text(*system, "A[] !deadlock");
  EXPECT_EQ(o.verdict, Verdict::Fails);
  EXPECT_EQ(o.method, "trace");
  // Every philosopher holds its left fork after three steps, the shortest way there.
  ASSERT_EQ(o.trace.size(), 4u);
  for (const char* p : {"ROOT.p0.has_left", "ROOT.p1.has_left", "ROOT.p2.has_left"}) {
    EXPECT_NE(std::find(o.trace.back().places.begin(), o.trace.back().places.end(), p),
              o.trace.back().places.end());
  }
}

TEST(Prover, PhilosophersTakingForksTogetherAreProvedDeadlockFreeByTraps) {
  const auto system = load(kTogether);
  ASSERT_TRUE(system);
  ASSERT_EQ(tests::reachable_deadlocks(*system), 0u);
  ProveOptions traps;
  traps.method = Method::Traps;
  const QueryOutcome o = prove_text(*system, "A[] !deadlock", traps);
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.method, "invariants");
  EXPECT_FALSE(o.linear);
  EXPECT_GT(o.traps, 0u);  // the atoms' invariants alone do not exclude the deadlocks of DIS
}

TEST(Prover, AStickyForkFlipsTheVerdictOfThePhilosophersTakingForksTogether) {
  const auto system = load(kStickyFork);
  ASSERT_TRUE(system);
  ASSERT_GT(tests::reachable_deadlocks(*system), 0u);
  const QueryOutcome o = prove_text(*system, "A[] !deadlock");
  EXPECT_EQ(o.verdict, Verdict::Fails);
  EXPECT_FALSE(o.trace.empty());
}

TEST(Prover, AnAsymmetricPhilosopherFlipsTheVerdictOfTakingForksOneAtATime) {
  const auto system = load(kAsymmetric);
  ASSERT_TRUE(system);
  ASSERT_EQ(tests::reachable_deadlocks(*system), 0u);
  // Traps do not exclude every candidate here; the candidates left are unreachable, which the
  // complete search shows. The state equation excludes them.
  ProveOptions traps;
  traps.method = Method::Traps;
  EXPECT_EQ(prove_text(*system, "A[] !deadlock", traps).verdict, Verdict::Holds);
  traps.explore_depth = 2;
  EXPECT_EQ(prove_text(*system, "A[] !deadlock", traps).verdict, Verdict::Open);
  ProveOptions linear;
  linear.method = Method::Linear;
  linear.explore_depth = 0;
  const QueryOutcome o = prove_text(*system, "A[] !deadlock", linear);
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.method, "invariants");
  EXPECT_EQ(o.traps, 0u);
}

/// Whether some reachable state has `c.x` above `bound`.
bool counter_exceeds(const bipc::ir::System& system, std::int64_t bound) {
  return tests::some_reachable(
      system, [bound](const engines::RunState& s, const engines::Layout& layout, bool) {
        return s.data[layout.atom_data[0]].i > bound;
      });
}

TEST(Prover, ComponentInvariantsBoundTheCounterWithoutSearch) {
  const auto system = load(kCounter);
  ASSERT_TRUE(system);
  ASSERT_FALSE(counter_exceeds(*system, 5));
  ProveOptions no_search;
  no_search.explore_depth = 0;  // a proof may not rest on the search
  const QueryOutcome o = prove_text(*system, "A[] c.x <= 5", no_search);
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.method, "invariants");
  EXPECT_EQ(o.component_invariants, 1u);
  EXPECT_EQ(prove_text(*system, "A[] c.high -> !c.up", no_search).verdict, Verdict::Holds);
  EXPECT_EQ(prove_text(*system, "E<> c.x == 6", no_search).verdict, Verdict::Fails);
}

TEST(Prover, WithoutComponentIterationsTheCounterIsLeftOpen) {
  const auto system = load(kCounter);
  ASSERT_TRUE(system);
  ProveOptions none;
  none.component_iterations = 0;
  none.explore_depth = 3;
  EXPECT_EQ(prove_text(*system, "A[] c.x <= 5", none).verdict, Verdict::Open);
}

TEST(Prover, AnOffByOneFlipsTheCounterBound) {
  const auto system = load(kCounterBug);
  ASSERT_TRUE(system);
  ASSERT_TRUE(counter_exceeds(*system, 5));
  const QueryOutcome o = prove_text(*system, "A[] c.x <= 5");
  EXPECT_EQ(o.verdict, Verdict::Fails);
  ASSERT_EQ(o.trace.size(), 7u);  // six increments
  EXPECT_EQ(o.trace.back().data.front(), (std::pair<std::string, std::string>{"ROOT.c.x", "6"}));
}

TEST(Prover, ReachabilityIsAnsweredWithAWitness) {
  const auto system = load(kCounter);
  ASSERT_TRUE(system);
  ASSERT_TRUE(
      tests::some_reachable(*system, [](const engines::RunState& s, const engines::Layout& layout,
                                        bool) { return s.data[layout.atom_data[0]].i == 5; }));
  const QueryOutcome o = prove_text(*system, "E<> c.x == 5 && c.low");
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.trace.size(), 6u);
}

TEST(Prover, ClocksInAPropertyAreRefusedAtTheirPosition) {
  const tests::TempDir dir;
  const auto system = tests::load_model(
      dir.write("timed.bip",
                "package timed\n  port type P()\n  connector type Solo(P p)\n"
                "    define p\n  end\n  atom type A()\n    clock x unit millisecond\n"
                "    export port P tick()\n    place s\n    initial to s\n"
                "    on tick from s to s provided (x >= 1) do { x = 0; }\n  end\n"
                "  compound type Top()\n    component A a()\n"
                "    connector Solo c(a.tick)\n  end\nend\n"),
      "Top()");
  ASSERT_TRUE(system);
  try {
    prove_text(*system, "A[] a.x <= 3");
    ADD_FAILURE() << "a clock in a predicate was accepted";
  } catch (const UnsupportedModel& e) {
    EXPECT_TRUE(e.in_property);
    ASSERT_TRUE(e.at);
    EXPECT_EQ(e.at->line, 1u);
    EXPECT_EQ(e.at->column, 5u);
  }
  // Clocks are dropped: the clock guard may be false in DIS, and no search ignoring time is
  // made, so the query is left open rather than decided wrongly.
  const QueryOutcome o = prove_text(*system, "A[] !deadlock");
  EXPECT_EQ(o.verdict, Verdict::Open);
  EXPECT_NE(o.note.find("clocks"), std::string::npos);
}

}  // namespace
}  // namespace smcbip::fdir
