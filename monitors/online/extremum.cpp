// The observed value of an expectation query on one run (see extremum.h).
#include "monitors/online/extremum.h"

#include <algorithm>

namespace smcbip::monitors {

Extremum::Extremum(const Query& q, const TimeScale& scale, const Bindings& bindings)
    : expr_(*q.observed), observe_(q.observe), bindings_(bindings), scale_(scale) {
  if (q.run.kind == Bound::Kind::Time) until_ = bound_ticks(q.run.high, scale, bindings);
  if (q.run.kind == Bound::Kind::Steps) steps_ = bound_steps(q.run.high, bindings);
}

void Extremum::reset() {
  started_ = over_ = false;
  total_ = 0;
  last_time_ = 0;
  value_.reset();
}

bool Extremum::step(const StateView& state, online::Tick time, std::int64_t index) {
  if (over_) return false;
  if (index > steps_) {
    over_ = true;
    finish();
    return false;
  }
  if (started_ && time > until_) {
    // The last state held up to this step, past the bound.
    account(static_cast<double>(until_ - last_time_));
    over_ = true;
    finish();
    return false;
  }
  if (started_) account(static_cast<double>(time - last_time_));
  const Moment moment(state, time, scale_, index == 0);
  if (observe_ == Observation::Count) {
    if (index > 0 && evaluate(expr_, moment, bindings_) != 0) total_ += 1;
  } else {
    const double horizon = until_ == std::numeric_limits<online::Tick>::max()
                               ? std::numeric_limits<double>::infinity()
                               : static_cast<double>(until_ - time);
    last_.compute(expr_, moment, bindings_, horizon);
    const double now = last_.at(0);
    if (observe_ == Observation::Last || !started_) {
      if (observe_ != Observation::Integral) total_ = now;
    } else if (observe_ == Observation::Max) {
      total_ = std::max(total_, now);
    } else if (observe_ == Observation::Min) {
      total_ = std::min(total_, now);
    }
  }
  started_ = true;
  last_time_ = time;
  if (index == steps_) {
    over_ = true;
    finish();
    return false;
  }
  return true;
}

void Extremum::account(double ticks) {
  switch (observe_) {
    case Observation::Max:
    case Observation::Min: {
      const bool largest = observe_ == Observation::Max;
      const double extreme = last_.extreme(ticks, largest);
      total_ = largest ? std::max(total_, extreme) : std::min(total_, extreme);
      break;
    }
    case Observation::Last:
      total_ = last_.at(ticks);
      break;
    case Observation::Integral:
      total_ += last_.integral(ticks);
      break;
    case Observation::Count:
      break;
  }
}

void Extremum::end(RunEnd how) {
  if (over_ || !started_) return;
  over_ = true;
  // What a run cut short or time-locked would have shown up to its bound is unknown.
  if (how != RunEnd::Deadlock) return;
  // A deadlocked run keeps its last state (its clocks grow) up to the bound.
  if (until_ != std::numeric_limits<online::Tick>::max()) {
    account(static_cast<double>(until_ - last_time_));
  }
  finish();
}

}  // namespace smcbip::monitors
