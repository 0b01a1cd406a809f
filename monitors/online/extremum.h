// The observed value of an expectation query (E[<=T; N](max: e), min:, last:, int:,
// count: fired(c); E=? [ max: e ]) on one run, under the continuous reading: between steps,
// clocks grow and the expression follows them, so a maximum may lie between steps, the value
// at T is the value at T, and the integral is that of the trajectory.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

#include "monitors/online/growing_truth.h"
#include "monitors/online/online_monitor.h"

namespace smcbip::monitors {

class Extremum {
 public:
  /// The query's observed expression (which must outlive this) and run bound.
  Extremum(const Query& q, const TimeScale& scale, const Bindings& bindings);

  /// Reads step `index` of the run, at `time` (ticks from the run's start); false once the
  /// run has passed its bound (the value is then known).
  bool step(const StateView& state, online::Tick time, std::int64_t index);
  /// The run ended after the last step read.
  void end(RunEnd how);
  /// The run's value once known: the run reached its bound, or deadlocked (its last state
  /// holds from then on). Empty for a run cut short before its bound, whose value is unknown.
  std::optional<double> value() const { return value_; }
  void reset();

 private:
  /// Accounts the last state read over `ticks` after its step.
  void account(double ticks);
  void finish() {
    value_ = observe_ == Observation::Integral ? total_ / scale_.ticks_per_unit : total_;
  }

  const Expr& expr_;
  Observation observe_;
  Bindings bindings_;
  TimeScale scale_;
  online::Tick until_ = std::numeric_limits<online::Tick>::max();
  std::int64_t steps_ = std::numeric_limits<std::int64_t>::max();

  Trajectory last_;  // of the last state read, from its step on
  online::Tick last_time_ = 0;
  bool started_ = false, over_ = false;
  double total_ = 0;  // the maximum, minimum, integral (value x ticks), count or last value
  std::optional<double> value_;
};

}  // namespace smcbip::monitors
