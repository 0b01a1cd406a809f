// A plain recursive evaluator of the semantics PROPERTIES.md commits to: slow, obviously right,
// the oracle the online monitor is compared with.
//
// Continuous reading: state s_i holds on [t_i, t_{i+1}); a step followed by another at the same
// timestamp holds at that instant only; a deadlocked run keeps its last state forever; a run cut
// short (limit, time-lock, error) is unknown past its last step (more steps may come at that
// step's time), and the verdict is then three-valued by Kleene's rules. Clocks grow at their
// slopes between steps and after a deadlock, and predicates read them at every grid point.
//
// Why a grid suffices: when timestamps and bounds are whole multiples of a granule g, the set of
// times at which any subformula holds within one state is a union of intervals with endpoints
// on multiples of g (open or closed), so evaluating at every multiple of g/2 decides every
// quantifier over time exactly. Here g = 1/2: timestamps and bounds must be multiples of 1/2,
// and the grid has kPerUnit = 4 points per time unit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "monitors/property/ast.h"

namespace smcbip::tests {

enum class Tri : std::uint8_t { False, True, Unknown };

inline Tri tri(bool b) { return b ? Tri::True : Tri::False; }
inline Tri tri_not(Tri a) { return a == Tri::Unknown ? a : tri(a == Tri::False); }
inline Tri tri_or(Tri a, Tri b) {
  if (a == Tri::True || b == Tri::True) return Tri::True;
  return a == Tri::Unknown || b == Tri::Unknown ? Tri::Unknown : Tri::False;
}
inline Tri tri_and(Tri a, Tri b) { return tri_not(tri_or(tri_not(a), tri_not(b))); }
inline Tri tri_iff(Tri a, Tri b) {
  if (a == Tri::Unknown || b == Tri::Unknown) return Tri::Unknown;
  return tri(a == b);
}

/// One step of a test trace: its (integer) time, the values of the names its predicates read
/// (booleans as 0 or 1), and the interaction it fired ("" for none). Names with a slope are
/// clocks: from the step on they grow by `slope` per time unit (their crossings of the
/// predicates' constants must fall on multiples of 1/2, as timestamps do, for the grid).
struct ReferenceStep {
  std::int64_t time = 0;  // in whole time units (see the grid above)
  std::map<std::string, double> values;
  std::string fired;
  std::map<std::string, double> slopes;
};

struct ReferenceTrace {
  std::vector<ReferenceStep> steps;  // at least one; times non-decreasing
  bool deadlocked = true;            // else cut short after its last step
};

class ReferenceEvaluator {
 public:
  /// `horizon`: how far (in time units) past the last step unbounded operators look on a
  /// deadlocked run; it must exceed the sum of the formula's bounds, so that every value the
  /// constant tail gives is seen. Bounded operators see twice as far, so that those nested in
  /// unbounded ones never run out of tail.
  ReferenceEvaluator(const ReferenceTrace& trace, std::int64_t horizon)
      : trace_(trace), horizon2_(kPerUnit * horizon) {}

  /// The verdict of `f` at the start of the trace.
  Tri verdict(const monitors::Formula& f) const { return eval(f, {0, first2(0)}); }

 private:
  static constexpr std::int64_t kPerUnit = 4;
  // A point of the trace: a step and a time in grid units (t2 = kPerUnit * t).
  struct Point {
    std::size_t step;
    std::int64_t t2;
  };
  static constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max() / 4;

  std::size_t last() const { return trace_.steps.size() - 1; }
  // The grid times step i holds at: [first, end) (end == first + 1 for an instant).
  std::int64_t first2(std::size_t i) const { return kPerUnit * trace_.steps[i].time; }
  std::int64_t end2(std::size_t i) const {
    if (i < last()) return std::max(first2(i + 1), first2(i) + 1);
    return trace_.deadlocked ? unbounded_end2() + horizon2_ : first2(i) + 1;
  }
  // Where unbounded operators stop looking on a deadlocked run.
  std::int64_t unbounded_end2() const { return first2(last()) + 2 + horizon2_; }
  // Whether step i is followed by another at the same time: it then holds at that instant only.
  bool instant(std::size_t i) const {
    return i < last() && trace_.steps[i + 1].time == trace_.steps[i].time;
  }

  /// Calls `visit` on the points from `from` on, in order, while it returns true and the
  /// points are known; returns whether the points ran out into the unknown (a cut run).
  bool walk(Point from, const std::function<bool(Point)>& visit) const {
    for (std::size_t i = from.step; i <= last(); ++i) {
      const std::int64_t start = i == from.step ? from.t2 : first2(i);
      const std::int64_t end = instant(i) ? first2(i) + 1 : end2(i);
      for (std::int64_t t2 = start; t2 < end; ++t2) {
        if (!visit({i, t2})) return false;
      }
    }
    return !trace_.deadlocked;
  }

  /// The value of `e` `dt` time units after the step `s` (clocks grown).
  double value(const monitors::Expr& e, const ReferenceStep& s, double dt) const {
    using K = monitors::Expr::Kind;
    auto operand = [&](std::size_t k) { return value(*e.operands[k], s, dt); };
    switch (e.kind) {
      case K::Number:
        return e.value.number;
      case K::Bool:
        return e.boolean ? 1 : 0;
      case K::Name: {
        const auto slope = s.slopes.find(e.path);
        return s.values.at(e.path) + (slope == s.slopes.end() ? 0 : slope->second * dt);
      }
      case K::Fired:
        return s.fired == e.path ? 1 : 0;
      case K::Negate:
        return -operand(0);
      case K::Add:
        return operand(0) + operand(1);
      case K::Subtract:
        return operand(0) - operand(1);
      case K::Multiply:
        return operand(0) * operand(1);
      case K::Divide:
        return operand(0) / operand(1);
      case K::Modulo:
        return static_cast<double>(static_cast<std::int64_t>(operand(0)) %
                                   static_cast<std::int64_t>(operand(1)));
      case K::Less:
        return operand(0) < operand(1) ? 1 : 0;
      case K::LessEqual:
        return operand(0) <= operand(1) ? 1 : 0;
      case K::Greater:
        return operand(0) > operand(1) ? 1 : 0;
      case K::GreaterEqual:
        return operand(0) >= operand(1) ? 1 : 0;
      case K::Equal:
        return operand(0) == operand(1) ? 1 : 0;
      case K::NotEqual:
        return operand(0) != operand(1) ? 1 : 0;
      case K::Call:
        if (e.path == "abs") return std::abs(operand(0));
        if (e.path == "min") return std::min(operand(0), operand(1));
        return std::max(operand(0), operand(1));
    }
    return 0;
  }

  // The window [low, high] (grid units, relative) of a time bound; none: all of the future.
  std::pair<std::int64_t, std::int64_t> window(const monitors::Bound& b) const {
    if (b.kind != monitors::Bound::Kind::Time) return {0, kNever};
    return {static_cast<std::int64_t>(kPerUnit * b.low.number),
            static_cast<std::int64_t>(kPerUnit * b.high.number)};
  }

  /// Whether `p` lies within the bound of an operator evaluated at `from`: by time for time
  /// bounds, by steps for step bounds (the run's stutter after a deadlock counts as steps).
  bool within(const monitors::Bound& b, Point from, Point p, std::int64_t low2) const {
    if (b.kind == monitors::Bound::Kind::Steps) {
      return p.step - from.step <= static_cast<std::size_t>(b.high.number);
    }
    return p.t2 - from.t2 >= low2;
  }
  bool past(const monitors::Bound& b, Point from, Point p, std::int64_t high2) const {
    if (b.kind == monitors::Bound::Kind::Time) return p.t2 - from.t2 > high2;
    // Unbounded and step bounds: a deadlocked run's tail is one step, seen up to the horizon,
    // beyond which its points are all alike (one of them is seen).
    if (trace_.deadlocked && p.t2 >= std::max(unbounded_end2(), from.t2 + 1)) return true;
    if (b.kind == monitors::Bound::Kind::Steps) {
      return p.step - from.step > static_cast<std::size_t>(b.high.number);
    }
    return p.t2 - from.t2 > high2;
  }

  Tri eval(const monitors::Formula& f, Point at) const {
    using K = monitors::Formula::Kind;
    switch (f.kind) {
      case K::True:
        return Tri::True;
      case K::False:
        return Tri::False;
      case K::Atom: {
        const double dt = static_cast<double>(at.t2 - first2(at.step)) / kPerUnit;
        return tri(value(*f.atom, trace_.steps[at.step], dt) != 0);
      }
      case K::Not:
        return tri_not(eval(*f.operands[0], at));
      case K::And:
        return tri_and(eval(*f.operands[0], at), eval(*f.operands[1], at));
      case K::Or:
        return tri_or(eval(*f.operands[0], at), eval(*f.operands[1], at));
      case K::Implies:
        return tri_or(tri_not(eval(*f.operands[0], at)), eval(*f.operands[1], at));
      case K::Iff:
        return tri_iff(eval(*f.operands[0], at), eval(*f.operands[1], at));
      case K::Next:
        if (at.step < last()) return eval(*f.operands[0], {at.step + 1, first2(at.step + 1)});
        return trace_.deadlocked ? eval(*f.operands[0], at) : Tri::Unknown;
      case K::Finally:
        return until(nullptr, *f.operands[0], f.bound, at);
      case K::Globally:
        return tri_not(until(nullptr, *f.operands[0], f.bound, at, true));
      case K::Until:
        return until(f.operands[0].get(), *f.operands[1], f.bound, at);
      case K::Release: {
        // phi R psi = !(!phi U !psi)
        return tri_not(until(f.operands[0].get(), *f.operands[1], f.bound, at, true, true));
      }
    }
    return Tri::Unknown;
  }

  /// `hold U[bound] goal` from `at` (hold null: true, as for F). With `negate_goal`, the goal is
  /// !goal (G); with `negate_hold` too, the hold is !hold (R's dual).
  Tri until(const monitors::Formula* hold, const monitors::Formula& goal,
            const monitors::Bound& bound, Point at, bool negate_goal = false,
            bool negate_hold = false) const {
    // Plain copies: lambdas may not capture structured bindings before C++20's P1091 (clang 14).
    const auto window_ends = window(bound);
    const auto low2 = window_ends.first, high2 = window_ends.second;
    Tri result = Tri::False;  // OR over the candidate points
    Tri held = Tri::True;     // AND of the hold over the points before the candidate
    Point seen = at;          // the last point visited
    const bool ran_out = walk(at, [&](Point p) {
      if (past(bound, at, p, high2)) return false;
      seen = p;
      Tri h = Tri::True;
      if (hold != nullptr) {
        h = eval(*hold, p);
        if (negate_hold) h = tri_not(h);
      }
      if (within(bound, at, p, low2)) {
        Tri g = eval(goal, p);
        if (negate_goal) g = tri_not(g);
        // A witness inside an open interval (odd grid point) after `at` lies past part of
        // that interval, where the hold must hold too.
        const bool inside = p.t2 % 2 == 1 && (p.step != at.step || p.t2 != at.t2);
        result = tri_or(result, tri_and(inside ? tri_and(held, h) : held, g));
      }
      held = tri_and(held, h);
      return result != Tri::True && held != Tri::False;
    });
    // A cut run leaves the verdict open only if the bound reaches its unknown part: the steps
    // after its last, which may come at the last one's time.
    const bool covered = bound.kind == monitors::Bound::Kind::Steps
                             ? seen.step - at.step >= static_cast<std::size_t>(bound.high.number)
                             : bound.kind == monitors::Bound::Kind::Time && seen.t2 - at.t2 > high2;
    if (ran_out && !covered && result != Tri::True && held != Tri::False) {
      result = tri_or(result, Tri::Unknown);
    }
    return result;
  }

  const ReferenceTrace& trace_;
  std::int64_t horizon2_;
};

/// The pointwise reading (--pointwise), as plainly: the points are the steps; a window holds
/// the steps whose times fall in it; after a deadlock no step comes (X reads the last state
/// again); after a cut, steps may come at the last step's time or later, unknown.
class PointwiseReference {
 public:
  explicit PointwiseReference(const ReferenceTrace& trace) : trace_(trace) {}

  Tri verdict(const monitors::Formula& f) const { return eval(f, 0); }

 private:
  std::size_t last() const { return trace_.steps.size() - 1; }
  double time(std::size_t i) const { return static_cast<double>(trace_.steps[i].time); }

  Tri eval(const monitors::Formula& f, std::size_t i) const {
    using K = monitors::Formula::Kind;
    switch (f.kind) {
      case K::True:
        return Tri::True;
      case K::False:
        return Tri::False;
      case K::Atom: {
        // The continuous evaluator's arithmetic, at the step's state.
        ReferenceTrace one{{trace_.steps[i]}, true};
        return ReferenceEvaluator(one, 1).verdict(f);
      }
      case K::Not:
        return tri_not(eval(*f.operands[0], i));
      case K::And:
        return tri_and(eval(*f.operands[0], i), eval(*f.operands[1], i));
      case K::Or:
        return tri_or(eval(*f.operands[0], i), eval(*f.operands[1], i));
      case K::Implies:
        return tri_or(tri_not(eval(*f.operands[0], i)), eval(*f.operands[1], i));
      case K::Iff:
        return tri_iff(eval(*f.operands[0], i), eval(*f.operands[1], i));
      case K::Next:
        if (i < last()) return eval(*f.operands[0], i + 1);
        return trace_.deadlocked ? eval(*f.operands[0], i) : Tri::Unknown;
      case K::Finally:
        return until(nullptr, *f.operands[0], f.bound, i, false, false);
      case K::Globally:
        return tri_not(until(nullptr, *f.operands[0], f.bound, i, true, false));
      case K::Until:
        return until(f.operands[0].get(), *f.operands[1], f.bound, i, false, false);
      case K::Release:
        return tri_not(until(f.operands[0].get(), *f.operands[1], f.bound, i, true, true));
    }
    return Tri::Unknown;
  }

  Tri until(const monitors::Formula* hold, const monitors::Formula& goal, const monitors::Bound& b,
            std::size_t i, bool negate_goal, bool negate_hold) const {
    using BK = monitors::Bound::Kind;
    const double low = b.kind == BK::Time ? b.low.number : 0;
    const double high = b.kind == BK::Time ? b.high.number : 1e18;
    const std::size_t steps =
        b.kind == BK::Steps ? static_cast<std::size_t>(b.high.number) : SIZE_MAX;
    Tri result = Tri::False, held = Tri::True;
    for (std::size_t j = i; j <= last() && j - i <= steps; ++j) {
      const double d = time(j) - time(i);
      if (d > high) break;
      if (d >= low) {
        Tri g = eval(goal, j);
        if (negate_goal) g = tri_not(g);
        result = tri_or(result, tri_and(held, g));
      }
      if (hold != nullptr) {
        Tri h = eval(*hold, j);
        if (negate_hold) h = tri_not(h);
        held = tri_and(held, h);
      }
      if (result == Tri::True || held == Tri::False) return result;
    }
    // Steps after a cut come at the last step's time or later.
    const bool reaches = b.kind == BK::Steps ? last() - i < steps : time(last()) - time(i) <= high;
    if (!trace_.deadlocked && reaches) result = tri_or(result, tri_and(held, Tri::Unknown));
    return result;
  }

  const ReferenceTrace& trace_;
};

}  // namespace smcbip::tests
