// Assumptions: parsed by Z3 with located errors, used only once inductive, and the verdicts
// they give compared with an exhaustive exploration of the producer/consumer benchmark (and
// of its variant with a bug injected).
#include <gtest/gtest.h>

#include <string>

#include "fdir/fdir.h"
#include "monitors/monitors.h"
#include "tests/engines/temp_model.h"
#include "tests/fdir/exhaustive.h"
#include "tests/fdir/prove_support.h"

namespace smcbip::fdir {
namespace {

using testing::prove_text;

const std::string kSource = SMCBIP_SOURCE_DIR;
const std::string kBenchmark = kSource + "/models/fdir/benchmarks/producer_consumer.bip";
const std::string kDoubleCount = kSource + "/tests/fdir/models/producer_consumer_double_count.bip";

/// The assumption of models/fdir/benchmarks/producer_consumer.smt2.
const std::string kInductive = "(assert (= ROOT.p.x (+ ROOT.c.y (ite ROOT.p.full 1 0))))\n";

/// The error `sources` are refused with (an empty file name when they are accepted).
AssumptionError refusal(const bipc::ir::System& system,
                        const std::vector<AssumptionSource>& sources) {
  try {
    Prover prover(system, ProveOptions{});
    prover.assume(sources);
  } catch (const AssumptionError& e) {
    return e;
  }
  return AssumptionError("", 0, 0, "accepted");
}

// Slots of the benchmark's atoms (atoms p then c; Producer: x, item; Consumer: y, last;
// Producer's places idle, full), read from concrete engine states.
std::int64_t datum(const engines::RunState& s, const engines::Layout& layout, Index atom,
                   Index slot) {
  return s.data[layout.atom_data[atom] + slot].i;
}
bool producer_full(const engines::RunState& s, const engines::Layout& layout) {
  return s.marking[layout.atom_places[0] + 1] != 0;
}

/// Some reachable state has y > x.
bool consumer_ahead_reachable(const bipc::ir::System& system) {
  return tests::some_reachable(system,
                               [](const engines::RunState& s, const engines::Layout& layout, bool) {
                                 return datum(s, layout, 1, 0) > datum(s, layout, 0, 0);
                               });
}

/// Some reachable state breaks x = y + (1 if the producer is full).
bool inductive_assumption_broken(const bipc::ir::System& system) {
  return tests::some_reachable(system,
                               [](const engines::RunState& s, const engines::Layout& layout, bool) {
                                 const std::int64_t waiting = producer_full(s, layout) ? 1 : 0;
                                 return datum(s, layout, 0, 0) != datum(s, layout, 1, 0) + waiting;
                               });
}

TEST(Assumptions, ProducerConsumerHoldsUnderAnInductiveAssumption) {
  const auto system = tests::load_model(kBenchmark, "Top(3)");
  ASSERT_TRUE(system);
  ASSERT_EQ(system->atoms[0].path, "p");
  // The reference verdicts, by every reachable state: y never exceeds x, and the assumption is
  // true in every reachable state.
  ASSERT_FALSE(consumer_ahead_reachable(*system));
  ASSERT_FALSE(inductive_assumption_broken(*system));
  const QueryOutcome o = prove_text(*system, "A[] c.y <= p.x", {}, {{"pc.smt2", kInductive}});
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.method, "invariants");
  ASSERT_EQ(o.assumptions.size(), 1u);
  EXPECT_EQ(o.assumptions[0].file, "pc.smt2");
  EXPECT_EQ(o.assumptions[0].line, 1u);
}

TEST(Assumptions, WithoutTheAssumptionALargeProducerConsumerIsLeftOpen) {
  // Whatever n, y <= x relates two atoms: the invariants alone cannot prove it, and with a
  // million items the search cannot exhaust the states.
  const auto system = tests::load_model(kBenchmark, "Top(1000000)");
  ASSERT_TRUE(system);
  EXPECT_EQ(prove_text(*system, "A[] c.y <= p.x").verdict, Verdict::Open);
  const QueryOutcome o = prove_text(*system, "A[] c.y <= p.x", {}, {{"pc.smt2", kInductive}});
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.method, "invariants");
}

TEST(Assumptions, ATrueButNotInductiveAssumptionIsRefusedNamingTheTransition) {
  const auto system = tests::load_model(kBenchmark, "Top(3)");
  ASSERT_TRUE(system);
  ASSERT_FALSE(consumer_ahead_reachable(*system));  // true in every reachable state...
  const AssumptionError e =
      refusal(*system, {{"weak.smt2", "; y <= x alone\n(assert (<= ROOT.c.y ROOT.p.x))\n"}});
  // ...but from y = x with an item waiting, the transfer makes y exceed x.
  EXPECT_EQ(e.file, "weak.smt2");
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.column, 1u);
  EXPECT_NE(std::string(e.what()).find("not inductive: net transition ROOT.t:"), std::string::npos)
      << e.what();
}

TEST(Assumptions, AConjunctionIsInductiveWhereEachHalfIsNot) {
  const auto system = tests::load_model(kBenchmark, "Top(3)");
  ASSERT_TRUE(system);
  const AssumptionSource idle{"idle.smt2", "(assert (=> ROOT.p.idle (= ROOT.p.x ROOT.c.y)))"};
  const AssumptionSource full{"full.smt2", "(assert (=> ROOT.p.full (= ROOT.p.x (+ ROOT.c.y 1))))"};
  // Idle alone: the transfer from a full producer is unconstrained; full alone: producing from
  // an idle one is.
  EXPECT_EQ(refusal(*system, {idle}).file, "idle.smt2");
  EXPECT_EQ(refusal(*system, {full}).file, "full.smt2");
  EXPECT_EQ(refusal(*system, {idle, full}).file, "");
  const QueryOutcome o = prove_text(*system, "A[] c.y <= p.x", {}, {idle, full});
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(o.assumptions.size(), 2u);
}

TEST(Assumptions, AnAssumptionFalseInitiallyIsRefused) {
  const auto system = tests::load_model(kBenchmark, "Top(3)");
  ASSERT_TRUE(system);
  const AssumptionError e = refusal(*system, {{"init.smt2", "(assert (= ROOT.c.y 1))"}});
  EXPECT_NE(std::string(e.what()).find("initial state"), std::string::npos) << e.what();
}

TEST(Assumptions, CountingTwiceFlipsTheVerdictAndTheAssumptionIsRefused) {
  const auto system = tests::load_model(kDoubleCount, "Top(3)");
  ASSERT_TRUE(system);
  // The reference: y exceeds x in a reachable state, and the assumption is broken in one, so
  // that using it would have been unsound.
  ASSERT_TRUE(consumer_ahead_reachable(*system));
  ASSERT_TRUE(inductive_assumption_broken(*system));
  const QueryOutcome o = prove_text(*system, "A[] c.y <= p.x");
  EXPECT_EQ(o.verdict, Verdict::Fails);
  EXPECT_EQ(o.method, "trace");
  EXPECT_EQ(o.trace.size(), 3u);  // produce, then transfer: y = 2 > x = 1
  const AssumptionError e = refusal(*system, {{"pc.smt2", kInductive}});
  EXPECT_NE(std::string(e.what()).find("ROOT.t:"), std::string::npos) << e.what();
}

TEST(Assumptions, UnknownNamesAndSyntaxErrorsAreLocated) {
  const auto system = tests::load_model(kBenchmark, "Top(3)");
  ASSERT_TRUE(system);
  AssumptionError e = refusal(*system, {{"a.smt2", "(assert\n  (<= ROOT.c.y ROOT.p.z))"}});
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.column, 16u);
  EXPECT_NE(std::string(e.what()).find("unknown name ROOT.p.z"), std::string::npos) << e.what();
  e = refusal(*system, {{"a.smt2", "(assert (<= ROOT.c.y ROOT.p.x)"}});
  EXPECT_EQ(e.line, 1u);
  EXPECT_NE(std::string(e.what()).find("')' expected"), std::string::npos) << e.what();
  e = refusal(*system, {{"a.smt2", "(assert (<= ROOT.c.y ROOT.p.full))"}});
  EXPECT_NE(std::string(e.what()).find("Sort mismatch"), std::string::npos) << e.what();
  e = refusal(*system, {{"a.smt2", "\n (declare-const k Int)\n(assert (<= ROOT.c.y k))"}});
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.column, 2u);
  EXPECT_NE(std::string(e.what()).find("'declare-const' is not allowed"), std::string::npos);
}

TEST(Assumptions, PlacesSharingADatumsNameAreWrittenWithAnAt) {
  const auto system = tests::load_model_text(R"(
package clash
  port type Sync()
  connector type Solo(Sync p)
    define p
  end
  atom type A()
    data bool lit
    data float level
    export port Sync flip()
    place lit, dark
    initial to dark do { lit = false; }
    on flip from dark to lit do { lit = true; }
    on flip from lit to dark do { lit = false; }
  end
  compound type Top()
    component A a()
    connector Solo f(a.flip)
  end
end
)",
                                             "Top()");
  ASSERT_TRUE(system);
  // ROOT.a.lit is the datum; the place is @ROOT.a.lit. The datum follows the place.
  EXPECT_EQ(refusal(*system, {{"a.smt2", "(assert (= ROOT.a.lit |@ROOT.a.lit|))"}}).file, "");
  const AssumptionError e = refusal(*system, {{"a.smt2", "(assert (> ROOT.a.level 0.0))"}});
  EXPECT_NE(std::string(e.what()).find("ROOT.a.level is a float datum"), std::string::npos)
      << e.what();
}

}  // namespace
}  // namespace smcbip::fdir
