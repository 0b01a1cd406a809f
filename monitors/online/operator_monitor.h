// The online monitor of the formulas statistical model checking asks most: one temporal
// operator, F, G, U or R, time-bounded or not, possibly negated, over state formulas that read
// places and data only (`F (s == 7 && d == 1)`, `G[0,100] !err`, `!a U[2,5] b`). Each step
// costs one evaluation of each operand's compiled program and a few comparisons; nothing is
// allocated per step or per run. It gives the verdicts of OnlineMonitor (continuous reading,
// run bounds, run ends), at the same steps, and the same first hits of F and G.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>

#include "monitors/online/online_monitor.h"
#include "monitors/online/state_program.h"

namespace smcbip::monitors {

/// Reads the programs' loads from a StateView, as OnlineMonitor reads names.
class ViewReader {
 public:
  explicit ViewReader(const StateView& state) : state_(state) {}
  double load(online::StateProgram::Code, const online::StateProgram::Op& op) const {
    return state_.value(*op.expr);
  }

 private:
  const StateView& state_;
};

class OperatorMonitor {
 public:
  /// Whether `formula` has the shape this monitor takes: negations of one F, G, U or R
  /// without a step bound over state formulas (StateProgram::accepts). Any run bound is.
  static bool accepts(const Formula& formula);

  /// The monitor of `formula` (accepts(formula); it must outlive the monitor) on runs observed
  /// for `run`, as OnlineMonitor's constructor. Throws MonitorError as it does.
  OperatorMonitor(const Formula& formula, const TimeScale& scale, const Bindings& bindings,
                  const Bound& run = {});

  /// Reads the next step at `time` (ticks), as OnlineMonitor::step; `read` gives the values
  /// of the programs' loads in its state (StateProgram::holds).
  template <class Reader>
  Verdict step_with(const Reader& read, online::Tick time);
  /// The same, reading a StateView (names as OnlineMonitor reads them).
  Verdict step(const StateView& state, online::Tick time) {
    return step_with(ViewReader(state), time);
  }
  /// As OnlineMonitor::end.
  Verdict end(RunEnd how);
  Verdict verdict() const { return verdict_; }
  bool over() const { return decided_; }
  /// Every formula this monitor takes reads places and data only.
  bool decided_by_absorbing() const { return true; }
  void reset();

  /// As OnlineMonitor's, for F and G; kForever for U and R.
  online::Pos first_hit_for_sure() const { return sure_hit_; }
  online::Pos first_hit_possibly() const { return possible_hit_; }

  /// The operands' programs, for binding their data loads (StateProgram::bind_data).
  online::StateProgram& hold_program() { return hold_; }
  online::StateProgram& goal_program() { return goal_; }

 private:
  /// The run so far, as the operator sees it: no witness yet, whether the hold held on every
  /// position read, the first position where the goal held.
  struct Progress {
    bool found = false;
    bool alive = true;
    online::Pos first_hit = online::kForever;
  };

  /// Whether a new step at `time` is read (false: the verdict is known, or the observation
  /// ended before it); it judges the positions of the step before.
  bool begin(online::Tick time);
  /// The new step's operands (in the operator's own reading: see the .cpp); decides.
  Verdict finish_step(bool hold, bool goal) {
    hold_now_ = hold;
    goal_now_ = goal;
    ++steps_;
    if (progress_.found || !progress_.alive || last_.t > high_) decide(progress_.found);
    return verdict_;
  }
  /// The positions from..to hold `hold` and `goal`.
  void span(Progress& p, online::Pos from, online::Pos to, bool hold, bool goal) const;
  void finish_observation(online::Pos end);
  void decide(bool found);

  // The formula: `until_` (U, R) or not (F, G, whose hold is always true); `dual_`: the
  // verdict is the negation of the operator's own (G, R, and the negations of F, U).
  online::StateProgram hold_, goal_;
  bool until_ = false, dual_ = false;
  online::Tick low_ = 0, high_ = online::kNever;  // the window, in half ticks
  online::Tick time_bound_ = online::kNever;      // in half ticks
  std::int64_t step_bound_ = std::numeric_limits<std::int64_t>::max();
  online::Pos closed_ = online::kForever;  // the end of the observation given by `run`

  // The run.
  bool started_ = false, decided_ = false;
  std::int64_t steps_ = 0;
  online::Tick origin_ = 0;
  online::Pos last_{}, end_ = online::kForever;
  bool hold_now_ = false, goal_now_ = false;  // the operands in the last step read
  Progress progress_;
  Verdict verdict_ = Verdict::Undecided;
  online::Pos sure_hit_ = online::kForever, possible_hit_ = online::kForever;
};

template <class Reader>
Verdict OperatorMonitor::step_with(const Reader& read, online::Tick time) {
  // Inline, the most frequent step: at a later date, within the bounds, after a step that
  // neither held the goal nor failed the hold.
  const online::Tick t = 2 * (time - origin_);
  if (started_ && !decided_ && t > last_.t && t <= time_bound_ && steps_ <= step_bound_ &&
      !goal_now_ && hold_now_) {
    last_ = {t, 0};
  } else if (!begin(time)) {
    return verdict_;
  }
  const bool initial = steps_ == 0;
  const bool hold = !until_ || hold_.holds(read, initial);
  return finish_step(hold, goal_.holds(read, initial));
}

}  // namespace smcbip::monitors
