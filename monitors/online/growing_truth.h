// The truth of a state predicate between two steps, under the continuous reading: clocks (and
// the global time) grow linearly at their rates while everything else keeps its value, so a
// predicate linear in them changes truth only where one of its comparisons crosses zero.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "monitors/online/signal.h"
#include "monitors/property/ast.h"

namespace smcbip::monitors {

class StateView;
using Bindings = std::map<std::string, double>;

/// A change of a predicate's truth: from `offset` half ticks after its step on, it is `value`.
struct TruthChange {
  online::Tick offset = 0;
  bool value = false;
};

/// The truth of `predicate` from the step of `state` on, as its clocks grow at their slopes
/// (StateView::slope, per tick): the first change at offset 0, then each change of value, in
/// order. A crossing at a whole tick is exact (to rounding of the crossing time, which is
/// snapped to the tick); one between two ticks is read on the open interval that holds it,
/// which takes the value after the crossing. Throws MonitorError where the predicate is not
/// linear in what grows (a product of two clocks, a division by one).
void truth_changes(const Expr& predicate, const StateView& state, const Bindings& bindings,
                   std::vector<TruthChange>& changes);

/// A numeric expression's value after a step, as its clocks grow: lines c0 + c1 * t (t in
/// ticks after the step), each from its `from` on up to the next one's.
class Trajectory {
 public:
  struct Line {
    double from = 0, c0 = 0, c1 = 0;
  };

  /// The trajectory of `expr` from the step of `state` up to `horizon` ticks after it.
  /// Throws MonitorError where the expression is not linear in what grows.
  void compute(const Expr& expr, const StateView& state, const Bindings& bindings, double horizon);
  /// The value `t` ticks after the step.
  double at(double t) const;
  /// The integral over [0, t], in value times ticks.
  double integral(double t) const;
  /// The largest (or smallest) value over [0, t].
  double extreme(double t, bool largest) const;

 private:
  std::vector<Line> lines_;
};

/// Whether `e` reads something that grows between steps: a clock or the global time.
bool reads_growing(const Expr& e);

}  // namespace smcbip::monitors
