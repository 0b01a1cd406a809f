// Parametric sweeps from one run: F[0,t] phi holds for every t from some critical value on,
// G[0,t] phi for every t up to one, so the first position that holds phi (F) or fails it (G)
// judges every value of t at once.
#pragma once

#include <string>

#include "monitors/online/online_monitor.h"

namespace smcbip::monitors {

/// Whether `formula` is F[0,t] phi or G[0,t] phi with `parameter` as t and phi not naming it:
/// monotone in t, so that CriticalBound judges it for every t from one run.
bool has_critical_bound(const Formula& formula, const std::string& parameter);

/// Judges a formula of has_critical_bound for every value of its parameter up to the largest,
/// from one run: it monitors the formula for the largest value and keeps the first position
/// deciding it (for sure, and possibly, which differ on runs cut short).
class CriticalBound {
 public:
  /// `run`: the query's run bound, which must not name the parameter.
  CriticalBound(const Formula& formula, const std::string& parameter, double largest,
                const TimeScale& scale, const Bindings& bindings, const Bound& run = {});

  /// Reads the next step; true once every value is judged.
  bool step(const StateView& state, online::Tick time) {
    return monitor_.step(state, time) != Verdict::Undecided;
  }
  void end(RunEnd how) { monitor_.end(how); }
  void reset() { monitor_.reset(); }

  /// The verdict for `value` of the parameter (at most the largest), once step returned true
  /// or the run ended; Undecided before.
  Verdict verdict(double value) const;

 private:
  OnlineMonitor monitor_;
  bool finally_;
  Value bound_;  // the parameter's place in the formula (its unit)
  TimeScale scale_;
};

}  // namespace smcbip::monitors
