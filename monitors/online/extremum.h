// The observed value of an expectation query (E[<=T; N](max: e), E=? [ min: e ]): the maximum
// or minimum of an expression over the states a run shows within the query's run bound.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

#include "monitors/online/online_monitor.h"

namespace smcbip::monitors {

class Extremum {
 public:
  /// The query's observed expression (which must outlive this) and run bound.
  Extremum(const Query& q, const TimeScale& scale, const Bindings& bindings)
      : expr_(*q.observed), maximum_(q.maximum), bindings_(bindings) {
    if (q.run.kind == Bound::Kind::Time) until_ = bound_ticks(q.run.high, scale, bindings);
    if (q.run.kind == Bound::Kind::Steps) steps_ = bound_steps(q.run.high, bindings);
  }

  /// Reads step `index` of the run, at `time` (ticks from the run's start); false once the
  /// step lies beyond the run bound (it is not read).
  bool step(const StateView& state, online::Tick time, std::int64_t index) {
    if (time > until_ || index > steps_) return false;
    const double v = evaluate(expr_, state, bindings_);
    if (!value_ || (maximum_ ? v > *value_ : v < *value_)) value_ = v;
    return true;
  }
  std::optional<double> value() const { return value_; }
  void reset() { value_.reset(); }

 private:
  const Expr& expr_;
  bool maximum_;
  Bindings bindings_;
  online::Tick until_ = std::numeric_limits<online::Tick>::max();
  std::int64_t steps_ = std::numeric_limits<std::int64_t>::max();
  std::optional<double> value_;
};

}  // namespace smcbip::monitors
