// The reference evaluator on traces whose verdicts are worked out by hand: punctual bounds,
// equal timestamps, non-strict until, runs cut short, nesting over continuous time.
#include "reference_semantics.h"

#include <gtest/gtest.h>

#include <string>

#include "monitors/monitors.h"

namespace smcbip::tests {
namespace {

/// The verdict of `formula` on `trace`.
Tri verdict(const ReferenceTrace& trace, const std::string& formula) {
  const monitors::ParsedProperties parsed =
      monitors::parse_properties("P=? [ " + formula + " ]", "f.mtl");
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  return ReferenceEvaluator(trace, 100).verdict(*parsed.file.queries.at(0).formula);
}

ReferenceStep step(std::int64_t time, double p, double q = 0, std::string fired = "") {
  return {time, {{"p", p}, {"q", q}}, std::move(fired)};
}

// p false on [0, 5), true from 5 on (deadlocked).
const ReferenceTrace kLateP{{step(0, 0), step(5, 1)}, true};

TEST(ReferenceSemantics, TimeBoundsAreClosed) {
  EXPECT_EQ(verdict(kLateP, "F[0,4] p"), Tri::False);
  EXPECT_EQ(verdict(kLateP, "F[0,5] p"), Tri::True);
  EXPECT_EQ(verdict(kLateP, "F[5,5] p"), Tri::True);
  EXPECT_EQ(verdict(kLateP, "G[0,4] !p"), Tri::True);
  EXPECT_EQ(verdict(kLateP, "G[0,5] !p"), Tri::False);
  EXPECT_EQ(verdict(kLateP, "G[5,100] p"), Tri::True);
  EXPECT_EQ(verdict(kLateP, "F p"), Tri::True);
}

TEST(ReferenceSemantics, StepsAtOneTimestampHoldForAnInstant) {
  // p holds only at the instant 3, between two steps that share it.
  const ReferenceTrace trace{{step(0, 0), step(3, 1), step(3, 0)}, true};
  EXPECT_EQ(verdict(trace, "F[3,3] p"), Tri::True);
  EXPECT_EQ(verdict(trace, "G[3,3] !p"), Tri::False);
  EXPECT_EQ(verdict(trace, "F[0,10] (p && F[1,1] p)"), Tri::False);
  EXPECT_EQ(verdict(trace, "G[4,10] !p"), Tri::True);
}

TEST(ReferenceSemantics, UntilIsNonStrict) {
  const ReferenceTrace trace{{step(0, 0, 1), step(2, 0, 0)}, true};
  EXPECT_EQ(verdict(trace, "p U[0,5] q"), Tri::True);
  EXPECT_EQ(verdict(trace, "p U[1,5] q"), Tri::False);
  // p until q: p must hold on [0, 4) and q at 4.
  const ReferenceTrace later{{step(0, 1, 0), step(4, 0, 1)}, true};
  EXPECT_EQ(verdict(later, "p U[0,5] q"), Tri::True);
  EXPECT_EQ(verdict(later, "p U[0,3] q"), Tri::False);
  EXPECT_EQ(verdict(later, "q R[0,3] p"), Tri::True);
}

TEST(ReferenceSemantics, ARunCutShortLeavesTheFutureUndecided) {
  const ReferenceTrace cut{{step(0, 0), step(2, 0)}, false};
  EXPECT_EQ(verdict(cut, "F[0,2] p"), Tri::False);
  EXPECT_EQ(verdict(cut, "F[0,10] p"), Tri::Unknown);
  EXPECT_EQ(verdict(cut, "G[0,10] p"), Tri::False);  // decided by the prefix
  EXPECT_EQ(verdict(cut, "G[0,10] !p"), Tri::Unknown);
  EXPECT_EQ(verdict(cut, "X X p"), Tri::Unknown);
}

TEST(ReferenceSemantics, NestedBoundsReadContinuousTime) {
  // p from 1 on: at every time of [0, 2], p comes within 1.
  const ReferenceTrace trace{{step(0, 0), step(1, 1)}, true};
  EXPECT_EQ(verdict(trace, "G[0,2] F[0,1] p"), Tri::True);
  EXPECT_EQ(verdict(trace, "G[0,2] F[0,0.5] p"), Tri::False);
  // p only on [1, 2): F[0,1] p fails from time 2 on, and at 1.5 G[0,1] p fails already.
  const ReferenceTrace pulse{{step(0, 0), step(1, 1), step(2, 0)}, true};
  EXPECT_EQ(verdict(pulse, "F[0,5] G[0,1] p"), Tri::False);
  EXPECT_EQ(verdict(pulse, "F[0,5] G[0,0] p"), Tri::True);
  EXPECT_EQ(verdict(pulse, "F[0,1] G[0,0.5] p"), Tri::True);
}

TEST(ReferenceSemantics, NextAndStepBoundsCountSteps) {
  const ReferenceTrace trace{{step(0, 0), step(7, 0), step(9, 1)}, true};
  EXPECT_EQ(verdict(trace, "X p"), Tri::False);
  EXPECT_EQ(verdict(trace, "X X p"), Tri::True);
  EXPECT_EQ(verdict(trace, "F{1} p"), Tri::False);
  EXPECT_EQ(verdict(trace, "F{2} p"), Tri::True);
  EXPECT_EQ(verdict(trace, "F[0,8] fired(go) || F{2} p"), Tri::True);
}

}  // namespace
}  // namespace smcbip::tests
