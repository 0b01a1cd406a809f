// The semantics of PROPERTIES.md on hand-worked traces, where the reference evaluator and the
// online monitor must both give the verdict worked out; then the monitor against the
// reference on random formulas over random timed traces (fixed seeds), and its memory on long
// runs.
#include "monitors/online/online_monitor.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include "monitors/monitors.h"
#include "reference_semantics.h"

namespace smcbip::tests {
namespace {

using monitors::OnlineMonitor;
using monitors::RunEnd;
using monitors::Verdict;

/// A reference step read as a state.
class StepView final : public monitors::StateView {
 public:
  explicit StepView(const ReferenceStep& step) : step_(step) {}
  double value(const monitors::Expr& name) const override { return step_.values.at(name.path); }
  bool fired(const monitors::Expr& fired) const override { return step_.fired == fired.path; }
  // The monitor counts half units (kHalves): a slope per unit is half that per tick.
  double slope(const monitors::Expr& name) const override {
    const auto it = step_.slopes.find(name.path);
    return it == step_.slopes.end() ? 0 : it->second / 2;
  }

 private:
  const ReferenceStep& step_;
};

monitors::ParsedProperties parse(const std::string& formula) {
  monitors::ParsedProperties parsed =
      monitors::parse_properties("P=? [ " + formula + " ]", "f.mtl");
  EXPECT_TRUE(parsed.ok()) << formula << "\n" << parsed.diagnostics.format(parsed.sources);
  return parsed;
}

Tri tri_of(Verdict v) {
  return v == Verdict::True ? Tri::True : v == Verdict::False ? Tri::False : Tri::Unknown;
}

// Timestamps and bounds of the reference traces are whole and half units: the monitor counts
// half units.
constexpr monitors::TimeScale kHalves{2.0, 2.0};

/// The monitor's verdict on `trace`; a verdict given before the end must be the final one.
Tri monitor_verdict(const monitors::Formula& formula, const ReferenceTrace& trace,
                    monitors::Reading reading = monitors::Reading::Continuous) {
  OnlineMonitor monitor(formula, kHalves, {}, {}, reading);
  Verdict early = Verdict::Undecided;
  for (const ReferenceStep& step : trace.steps) {
    const Verdict v = monitor.step(StepView(step), 2 * step.time);
    if (early == Verdict::Undecided) early = v;
  }
  const Verdict final = monitor.end(trace.deadlocked ? RunEnd::Deadlock : RunEnd::Cut);
  if (early != Verdict::Undecided) {
    EXPECT_EQ(early, final) << "an early verdict changed";
  }
  return tri_of(final);
}

Tri reference_verdict(const monitors::Formula& formula, const ReferenceTrace& trace) {
  return ReferenceEvaluator(trace, 60).verdict(formula);
}

ReferenceStep step(std::int64_t time, double p, double q = 0, std::string fired = "") {
  return {time, {{"p", p}, {"q", q}}, std::move(fired), {}};
}

/// The verdict the reference evaluator and the monitor give, which must be the same.
Tri verdict(const ReferenceTrace& trace, const std::string& text) {
  const monitors::ParsedProperties parsed = parse(text);
  const monitors::Formula& formula = *parsed.file.queries.at(0).formula;
  const Tri expected = reference_verdict(formula, trace);
  const Tri got = monitor_verdict(formula, trace);
  EXPECT_EQ(got, expected) << text;
  return expected;
}

// Hand-worked verdicts: closed and punctual bounds, equal timestamps, non-strict until, cut
// runs, nested bounds over continuous time, next and step bounds.

// p false on [0, 5), true from 5 on (deadlocked).
const ReferenceTrace kLateP{{step(0, 0), step(5, 1)}, true};

TEST(Semantics, TimeBoundsAreClosed) {
  EXPECT_EQ(verdict(kLateP, "F[0,4] p"), Tri::False);
  EXPECT_EQ(verdict(kLateP, "F[0,5] p"), Tri::True);
  EXPECT_EQ(verdict(kLateP, "F[5,5] p"), Tri::True);
  EXPECT_EQ(verdict(kLateP, "F[4.5,4.5] p"), Tri::False);
  EXPECT_EQ(verdict(kLateP, "G[0,4] !p"), Tri::True);
  EXPECT_EQ(verdict(kLateP, "G[0,5] !p"), Tri::False);
  EXPECT_EQ(verdict(kLateP, "G[5,100] p"), Tri::True);
  EXPECT_EQ(verdict(kLateP, "F p"), Tri::True);
}

TEST(Semantics, StepsAtOneTimestampHoldForAnInstant) {
  // p holds only at the instant 3, between two steps that share it.
  const ReferenceTrace trace{{step(0, 0), step(3, 1), step(3, 0)}, true};
  EXPECT_EQ(verdict(trace, "F[3,3] p"), Tri::True);
  EXPECT_EQ(verdict(trace, "G[3,3] !p"), Tri::False);
  EXPECT_EQ(verdict(trace, "F[0,10] (p && F[1,1] p)"), Tri::False);
  EXPECT_EQ(verdict(trace, "G[4,10] !p"), Tri::True);
  EXPECT_EQ(verdict(trace, "F[0,10] (p && X !p)"), Tri::True);
}

TEST(Semantics, UntilIsNonStrict) {
  const ReferenceTrace trace{{step(0, 0, 1), step(2, 0, 0)}, true};
  EXPECT_EQ(verdict(trace, "p U[0,5] q"), Tri::True);
  EXPECT_EQ(verdict(trace, "p U[1,5] q"), Tri::False);
  // p until q: p must hold on [0, 4) and q at 4.
  const ReferenceTrace later{{step(0, 1, 0), step(4, 0, 1)}, true};
  EXPECT_EQ(verdict(later, "p U[0,5] q"), Tri::True);
  EXPECT_EQ(verdict(later, "p U[0,3] q"), Tri::False);
  EXPECT_EQ(verdict(later, "q R[0,3] p"), Tri::True);
}

TEST(Semantics, AWitnessInsideAnOpenIntervalNeedsTheHoldThere) {
  // p on [0, 3): `p U[1,1] true` holds on [0, 2], closed, and fails on (2, +inf). A witness of
  // its failure lies in (2, 2.5) at the earliest, and the hold must cover part of that.
  const ReferenceTrace trace{{step(0, 1), step(3, 0)}, true};
  EXPECT_EQ(verdict(trace, "G[0,2] (p U[1,1] true)"), Tri::True);
  EXPECT_EQ(verdict(trace, "F[2.5,2.5] (p U[1,1] true)"), Tri::False);
  EXPECT_EQ(verdict(trace, "(p U[1,1] true) U[0,5] !(p U[1,1] true)"), Tri::False);
  EXPECT_EQ(verdict(trace, "(p U[1,1] true) U[0,5] !p"), Tri::False);
  EXPECT_EQ(verdict(trace, "p U[0,5] !(p U[1,1] true)"), Tri::True);
}

TEST(Semantics, ARunCutShortLeavesTheFutureUndecided) {
  const ReferenceTrace cut{{step(0, 0), step(2, 0)}, false};
  EXPECT_EQ(verdict(cut, "F[0,1.5] p"), Tri::False);
  // Another step may come at time 2, the last step's.
  EXPECT_EQ(verdict(cut, "F[0,2] p"), Tri::Unknown);
  EXPECT_EQ(verdict(cut, "F[0,10] p"), Tri::Unknown);
  EXPECT_EQ(verdict(cut, "G[0,10] p"), Tri::False);  // decided by the prefix
  EXPECT_EQ(verdict(cut, "G[0,10] !p"), Tri::Unknown);
  EXPECT_EQ(verdict(cut, "F[5,10] true"), Tri::Unknown);  // the run may never get there
  EXPECT_EQ(verdict(cut, "F[0,5] p || !p"), Tri::True);
  EXPECT_EQ(verdict(cut, "X X p"), Tri::Unknown);
}

TEST(Semantics, NestedBoundsReadContinuousTime) {
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

TEST(Semantics, NextAndStepBoundsCountSteps) {
  const ReferenceTrace trace{{step(0, 0), step(7, 0), step(9, 1)}, true};
  EXPECT_EQ(verdict(trace, "X p"), Tri::False);
  EXPECT_EQ(verdict(trace, "X X p"), Tri::True);
  EXPECT_EQ(verdict(trace, "F{1} p"), Tri::False);
  EXPECT_EQ(verdict(trace, "F{2} p"), Tri::True);
  EXPECT_EQ(verdict(trace, "F[0,8] fired(go) || F{2} p"), Tri::True);
  const ReferenceTrace instants{{step(0, 0), step(1, 0), step(1, 0), step(9, 1)}, true};
  EXPECT_EQ(verdict(instants, "F{2} p"), Tri::False);
  EXPECT_EQ(verdict(instants, "F{3} p"), Tri::True);
  EXPECT_EQ(verdict(instants, "G{2} !p"), Tri::True);
  EXPECT_EQ(verdict(instants, "!p U{3} p"), Tri::True);
  EXPECT_EQ(verdict(instants, "X X X p"), Tri::True);
}

/// The monitor's verdict on `trace` for a whole query, observed for its run bound.
Verdict query_verdict(const ReferenceTrace& trace, const std::string& query) {
  const monitors::ParsedProperties parsed = monitors::parse_properties(query, "q.mtl");
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  const monitors::Query& q = parsed.file.queries.at(0);
  OnlineMonitor monitor(*q.formula, kHalves, {}, q.run);
  for (const ReferenceStep& s : trace.steps) monitor.step(StepView(s), 2 * s.time);
  return monitor.end(trace.deadlocked ? RunEnd::Deadlock : RunEnd::Cut);
}

TEST(OnlineMonitor, ObservesARunUpToItsBound) {
  // Beyond the bound nothing exists: what is awaited fails, what is forbidden holds.
  EXPECT_EQ(query_verdict(kLateP, "Pr[<=4](F p)"), Verdict::False);
  EXPECT_EQ(query_verdict(kLateP, "Pr[<=5](F p)"), Verdict::True);
  EXPECT_EQ(query_verdict(kLateP, "Pr[<=4.5](G !p)"), Verdict::True);
  EXPECT_EQ(query_verdict(kLateP, "Pr[<=5](G !p) >= 0.5"), Verdict::False);
  EXPECT_EQ(query_verdict(kLateP, "Pr[<=20](F[3,30] p)"), Verdict::True);
  EXPECT_EQ(query_verdict(kLateP, "Pr[<=4](!p U p)"), Verdict::False);
  EXPECT_EQ(query_verdict(kLateP, "Pr[<=4](p R !p)"), Verdict::True);
  // p at 3, q never: the response fails within the bound, even on a run cut later.
  const ReferenceTrace request{{step(0, 0), step(3, 1), step(4, 0), step(30, 0)}, false};
  EXPECT_EQ(query_verdict(request, "Pr[<=10](G (p -> F q))"), Verdict::False);
  EXPECT_EQ(query_verdict(request, "Pr[<=2](G (p -> F q))"), Verdict::True);
  EXPECT_EQ(query_verdict(request, "Pr[<=40](G (p -> F q))"), Verdict::Undecided);
  // Steps: the initial state and the next K.
  const ReferenceTrace instants{{step(0, 0), step(1, 0), step(1, 0), step(9, 1)}, true};
  EXPECT_EQ(query_verdict(instants, "Pr[#<=2](F p)"), Verdict::False);
  EXPECT_EQ(query_verdict(instants, "Pr[#<=3](F p)"), Verdict::True);
}

TEST(OnlineMonitor, DecidesAsSoonAsTheStepsDo) {
  const monitors::ParsedProperties parsed = parse("F[0,100] p");
  OnlineMonitor monitor(*parsed.file.queries.at(0).formula, kHalves, {});
  const ReferenceStep off = step(0, 0), on = step(3, 1);
  EXPECT_EQ(monitor.step(StepView(off), 0), Verdict::Undecided);
  EXPECT_EQ(monitor.step(StepView(on), 6), Verdict::Undecided);  // p holds from 3 on...
  const ReferenceStep next = step(4, 0);
  EXPECT_EQ(monitor.step(StepView(next), 8), Verdict::True);  // ...as the next step shows
}

TEST(OnlineMonitor, BoundsMustBeWholeTicks) {
  const monitors::ParsedProperties parsed = parse("F[0,0.25] p");
  EXPECT_THROW(OnlineMonitor(*parsed.file.queries.at(0).formula, kHalves, {}),
               monitors::MonitorError);
}

// Random formulas over p and q, nested up to `depth`, with bounds in half units from 0 to 3
// (punctual ones and a = 0 included), steps bounds, unbounded operators and next.
class FormulaMaker {
 public:
  explicit FormulaMaker(std::uint32_t seed) : random_(seed) {}

  std::string make(int depth) {
    if (depth == 0 || pick(5) == 0) return leaf();
    const auto sub = [&] { return "(" + make(depth - 1) + ")"; };
    switch (pick(13)) {
      case 0:
        return "!" + sub();
      case 1:
        return sub() + " && " + sub();
      case 2:
        return sub() + " || " + sub();
      case 3:
        return sub() + (pick(2) == 0 ? " -> " : " <-> ") + sub();
      case 4:
        return "X " + sub();
      case 5:
        return "F" + interval() + " " + sub();
      case 6:
        return "G" + interval() + " " + sub();
      case 7:
        return sub() + " U" + interval() + " " + sub();
      case 8:
        return sub() + " R" + interval() + " " + sub();
      case 9:
        return "F" + steps() + " " + sub();
      case 10:
        return sub() + " U" + steps() + " " + sub();
      case 11:
        return (pick(2) == 0 ? "F " : "G ") + sub();
      default:
        return sub() + (pick(2) == 0 ? " U " : " R ") + sub();
    }
  }

 private:
  std::string leaf() {
    // The last two hold on sets closed on the right ([0, 2] for p on [0, 3)): their
    // complements start with an open interval.
    // Then predicates over the clock c, whose crossings fall on half units: one instant
    // (c == 2), closed and open sets, and one mixing c with the data p.
    static const char* const kLeaves[] = {"p",
                                          "q",
                                          "!p",
                                          "p == q",
                                          "true",
                                          "false",
                                          "(p U[0.5,0.5] true)",
                                          "(q U[1,1] p)",
                                          "c >= 1",
                                          "c < 2.5",
                                          "c == 2",
                                          "c - p > 1.5"};
    return kLeaves[pick(12)];
  }
  std::string half(int halves) {
    return std::to_string(halves / 2) + (halves % 2 == 0 ? "" : ".5");
  }
  std::string interval() {
    const int low = pick(3) == 0 ? 0 : pick(7);
    const int high = low + (pick(3) == 0 ? 0 : pick(7));
    return "[" + half(low) + "," + half(high) + "]";
  }
  std::string steps() { return "{" + std::to_string(pick(4)) + "}"; }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(random_); }

  std::mt19937 random_;
};

/// Random traces over p, q (0 or 1) and the clock c, reset now and then, whose rate (0, 1/2
/// or 1 per unit) changes at steps: its values and crossings stay on half units.
ReferenceTrace random_trace(std::mt19937& random) {
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
  ReferenceTrace trace;
  trace.deadlocked = pick(2) == 0;
  std::int64_t time = 0;
  double clock = 0, rate = 1;
  const int steps = 1 + pick(8);
  for (int i = 0; i < steps; ++i) {
    if (i > 0) {
      const std::int64_t elapsed = pick(4) == 0 ? 0 : 1 + pick(3);
      time += elapsed;
      clock = pick(3) == 0 ? 0 : clock + rate * static_cast<double>(elapsed);
      rate = pick(3) * 0.5;
    }
    ReferenceStep s = step(time, pick(2), pick(2));
    s.values["c"] = clock;
    s.slopes["c"] = rate;
    trace.steps.push_back(std::move(s));
  }
  return trace;
}

std::string describe(const ReferenceTrace& trace) {
  std::string text;
  for (const ReferenceStep& s : trace.steps) {
    text += "(" + std::to_string(s.time) + ": p=" + std::to_string(int(s.values.at("p"))) +
            " q=" + std::to_string(int(s.values.at("q")));
    if (s.values.contains("c")) {
      text +=
          " c=" + std::to_string(s.values.at("c")) + "+" + std::to_string(s.slopes.at("c")) + "t";
    }
    text += ") ";
  }
  return text + (trace.deadlocked ? "deadlocked" : "cut");
}

TEST(OnlineMonitor, AgreesWithTheReferenceOnRandomFormulasAndTraces) {
  // 30,000 pairs, seeds fixed: a disagreement names the formula and the trace.
  FormulaMaker maker(20261122);
  std::mt19937 traces(7);
  int decided = 0;
  for (int i = 0; i < 30000; ++i) {
    const std::string text = maker.make(1 + i % 4);
    const monitors::ParsedProperties parsed = parse(text);
    const monitors::Formula& formula = *parsed.file.queries.at(0).formula;
    const ReferenceTrace trace = random_trace(traces);
    const Tri expected = reference_verdict(formula, trace);
    const Tri got = monitor_verdict(formula, trace);
    ASSERT_EQ(got, expected) << "case " << i << ": " << text << " on " << describe(trace);
    decided += got != Tri::Unknown;
  }
  EXPECT_GT(decided, 15000);  // the cases are not mostly undecided
}

TEST(OnlineMonitor, AMonitorResetJudgesAsANewOne) {
  // reset() restores the nodes and signals in place: one monitor reused over runs, decided
  // early, cut or deadlocked, must judge each as a monitor made for it does.
  FormulaMaker maker(8128);
  std::mt19937 traces(13);
  for (int i = 0; i < 3000; ++i) {
    const std::string text = maker.make(1 + i % 4);
    const monitors::ParsedProperties parsed = parse(text);
    const monitors::Formula& formula = *parsed.file.queries.at(0).formula;
    OnlineMonitor reused(formula, kHalves, {});
    for (int run = 0; run < 6; ++run) {
      const ReferenceTrace trace = random_trace(traces);
      const RunEnd end = trace.deadlocked ? RunEnd::Deadlock : RunEnd::Cut;
      reused.reset();
      OnlineMonitor fresh(formula, kHalves, {});
      for (const ReferenceStep& s : trace.steps) {
        ASSERT_EQ(reused.step(StepView(s), 2 * s.time), fresh.step(StepView(s), 2 * s.time))
            << "case " << i << ": " << text << " on " << describe(trace);
      }
      ASSERT_EQ(reused.end(end), fresh.end(end))
          << "case " << i << ": " << text << " on " << describe(trace);
    }
  }
}

Tri pointwise(const ReferenceTrace& trace, const std::string& text) {
  const monitors::ParsedProperties parsed = parse(text);
  const monitors::Formula& formula = *parsed.file.queries.at(0).formula;
  const Tri expected = PointwiseReference(trace).verdict(formula);
  EXPECT_EQ(monitor_verdict(formula, trace, monitors::Reading::Pointwise), expected) << text;
  return expected;
}

TEST(Pointwise, WindowsHoldTheStepsInThem) {
  // p at the step at 5 only: continuously it holds on [5, 8); pointwise at 5.
  const ReferenceTrace trace{{step(0, 0), step(5, 1), step(8, 0)}, true};
  EXPECT_EQ(pointwise(trace, "F[6,7] p"), Tri::False);
  EXPECT_EQ(verdict(trace, "F[6,7] p"), Tri::True);
  EXPECT_EQ(pointwise(trace, "F[5,5] p"), Tri::True);
  EXPECT_EQ(pointwise(trace, "G[1,4] p"), Tri::True);  // no step in [1, 4]
  EXPECT_EQ(pointwise(trace, "!p U[0,5] p"), Tri::True);
  EXPECT_EQ(pointwise(trace, "G[6,100] !p"), Tri::True);  // the deadlock: no step after 8
  EXPECT_EQ(pointwise(trace, "F[9,100] !p"), Tri::False);
  EXPECT_EQ(pointwise(trace, "X X X !p"), Tri::True);
  const ReferenceTrace cut{{step(0, 0), step(5, 1)}, false};
  EXPECT_EQ(pointwise(cut, "F[6,7] p"), Tri::Unknown);
  EXPECT_EQ(pointwise(cut, "F[0,4] p"), Tri::False);
  EXPECT_EQ(pointwise(cut, "F[0,5] !p"), Tri::True);
  // A run of equal values over several steps holds their times only, not those between.
  const ReferenceTrace sparse{{step(0, 0, 1), step(2, 0, 1), step(5, 1, 0), step(8, 1, 0)}, true};
  EXPECT_EQ(pointwise(sparse, "G[1,1] F[2,5] (q U[1,1] p)"), Tri::True);
  EXPECT_EQ(pointwise(sparse, "X F[2,5] (q U[1,1] p)"), Tri::False);
  EXPECT_EQ(pointwise(sparse, "G[1,4] !p"), Tri::True);
  EXPECT_EQ(pointwise(sparse, "q U[3,4] p"), Tri::False);
}

TEST(Pointwise, AgreesWithItsReferenceOnRandomFormulasAndTraces) {
  FormulaMaker maker(777);
  std::mt19937 traces(5);
  int decided = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::string text = maker.make(1 + i % 4);
    const monitors::ParsedProperties parsed = parse(text);
    const monitors::Formula& formula = *parsed.file.queries.at(0).formula;
    const ReferenceTrace trace = random_trace(traces);
    const Tri expected = PointwiseReference(trace).verdict(formula);
    ASSERT_EQ(monitor_verdict(formula, trace, monitors::Reading::Pointwise), expected)
        << "case " << i << ": " << text << " on " << describe(trace);
    decided += expected != Tri::Unknown;
  }
  EXPECT_GT(decided, 10000);
}

TEST(CriticalBound, JudgesEveryValueOfTheParameterFromOneRun) {
  // F[0,t] phi and G[0,t] phi for t = 0, 0.5, ..., 5 from one monitor each, against a monitor
  // per value, on random phi (without t) and random traces, deadlocked and cut short.
  FormulaMaker maker(424242);
  std::mt19937 traces(11);
  int decided = 0;
  for (int i = 0; i < 3000; ++i) {
    const std::string phi = maker.make(1 + i % 3);
    const ReferenceTrace trace = random_trace(traces);
    for (const char* op : {"F", "G"}) {
      const std::string text = std::string(op) + "[0,t] (" + phi + ")";
      const monitors::ParsedProperties parsed =
          monitors::parse_properties("param t = 0:5:0.5\nP=? [ " + text + " ]", "t.mtl");
      ASSERT_TRUE(parsed.ok()) << text;
      const monitors::Formula& formula = *parsed.file.queries.at(0).formula;
      ASSERT_TRUE(monitors::has_critical_bound(formula, "t")) << text;
      monitors::CriticalBound sweep(formula, "t", 5.0, kHalves, {});
      for (const ReferenceStep& s : trace.steps) {
        if (sweep.step(StepView(s), 2 * s.time)) break;
      }
      sweep.end(trace.deadlocked ? RunEnd::Deadlock : RunEnd::Cut);
      for (int halves = 0; halves <= 10; ++halves) {
        const double t = halves / 2.0;
        OnlineMonitor single(formula, kHalves, {{"t", t}});
        for (const ReferenceStep& s : trace.steps) single.step(StepView(s), 2 * s.time);
        const Verdict expected = single.end(trace.deadlocked ? RunEnd::Deadlock : RunEnd::Cut);
        ASSERT_EQ(sweep.verdict(t), expected)
            << "case " << i << ": " << text << " at t = " << t << " on " << describe(trace);
        decided += expected != Verdict::Undecided;
      }
    }
  }
  EXPECT_GT(decided, 30000);
}

TEST(CriticalBound, OnlyForFAndGUpToTheParameter) {
  const monitors::ParsedProperties parsed = monitors::parse_properties(
      "param t = {1, 2}\nP=? [ F[0,t] p ]\nP=? [ G[1,t] p ]\nP=? [ F[0,t] (p U[0,t] q) ]\n"
      "P=? [ !F[0,t] p ]\nP=? [ G[0,t] p ]",
      "t.mtl");
  ASSERT_TRUE(parsed.ok());
  const auto& q = parsed.file.queries;
  EXPECT_TRUE(monitors::has_critical_bound(*q[0].formula, "t"));
  EXPECT_FALSE(monitors::has_critical_bound(*q[1].formula, "t"));
  EXPECT_FALSE(monitors::has_critical_bound(*q[2].formula, "t"));
  EXPECT_FALSE(monitors::has_critical_bound(*q[3].formula, "t"));
  EXPECT_TRUE(monitors::has_critical_bound(*q[4].formula, "t"));
  EXPECT_FALSE(monitors::has_critical_bound(*q[4].formula, "u"));
}

monitors::Horizon horizon_of(const std::string& formula) {
  const monitors::ParsedProperties parsed = parse(formula);
  return monitors::horizon(*parsed.file.queries.at(0).formula, {1e6, 1e9}, {});
}

TEST(Horizon, NestedSumsOfUpperBounds) {
  const monitors::Horizon nested = horizon_of("G[0,10] (p -> F[2,5] q) && X X F{3} p");
  EXPECT_TRUE(nested.bounded);
  EXPECT_EQ(nested.time, 15'000'000);  // ticks of a nanosecond, the bounds in milliseconds
  EXPECT_EQ(nested.steps, 5);
  const monitors::Horizon units = horizon_of("F[0,1s] G[0,500us] p U[0,3] q");
  EXPECT_EQ(units.time, 1'003'500'000);  // (F[0,1s] G[0,500us] p) U[0,3] q
  EXPECT_FALSE(horizon_of("G[0,10] F p").bounded);
  EXPECT_TRUE(horizon_of("p && q").bounded);
  EXPECT_EQ(horizon_of("p && q").time, 0);
}

/// A state where p and q take given values.
class PairView final : public monitors::StateView {
 public:
  double value(const monitors::Expr& name) const override { return name.path == "p" ? p : q; }
  bool fired(const monitors::Expr&) const override { return false; }
  bool p = false, q = false;
};

TEST(OnlineMonitor, RemembersTheWindowsNotTheRun) {
  // A million steps 1 tick apart, p at random and q every 10 ticks: the formulas hold all
  // along, so no verdict stops the run, and what the monitor holds depends on their bounds,
  // not on how long the run is.
  for (const char* text :
       {"G (p -> F[0,50] q)", "G[0,2000000] F[0,20] (p || q)", "G (p -> F[5,15] q)", "G F{10} q",
        "G (p R[0,30] !q || F[0,9] q)", "G (p -> (!q U[0,10] q))"}) {
    const monitors::ParsedProperties parsed = parse(text);
    OnlineMonitor monitor(*parsed.file.queries.at(0).formula, {1.0, 1.0}, {});
    PairView view;
    std::mt19937 random(3);
    std::size_t most_early = 0, most = 0;
    for (std::int64_t t = 0; t < 1000000; ++t) {
      view.p = random() % 4 == 0;
      view.q = t % 10 == 0;
      ASSERT_EQ(monitor.step(view, t), Verdict::Undecided) << text << " at " << t;
      std::size_t& peak = t < 100000 ? most_early : most;
      peak = std::max(peak, monitor.held_runs());
    }
    EXPECT_LE(most, most_early + most_early / 2 + 4) << text;  // no growth beyond chance
    EXPECT_LE(most, 200u) << text;
  }
}

}  // namespace
}  // namespace smcbip::tests
