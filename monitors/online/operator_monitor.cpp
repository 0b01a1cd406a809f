#include "monitors/online/operator_monitor.h"

#include <algorithm>

namespace smcbip::monitors {

using online::kForever;
using online::kLastRank;
using online::Pos;
using online::StateProgram;
using online::Tick;

// How the operator reads a run. Positions are OnlineMonitor's (signal.h): half ticks, and ranks
// among the steps of one date. Step i holds on the positions from its own, P_i, up to the one
// before P_{i+1}. The operator is read as `hold U[a,b] goal` (non-strict; F: hold is true),
// with OnlineMonitor's duality: G phi = !(true U !phi), R = !(!hold U !goal); `dual_` says
// the verdict is the negation of that until, whose operands are then read negated. A witness
// is a position of the window holding goal, every position before it holding hold. Read step
// by step, the until is found once a witness is read, and fails once hold failed (no witness
// lies beyond) or the steps read went past the window; OnlineMonitor decides at exactly those
// steps, since it decides as soon as the positions it has read decide.

namespace {

/// The temporal operator under the negations at the root of `f`; `negated`: an odd number.
const Formula& operator_of(const Formula& f, bool& negated) {
  const Formula* at = &f;
  negated = false;
  while (at->kind == Formula::Kind::Not) {
    negated = !negated;
    at = at->operands[0].get();
  }
  return *at;
}

bool is_until(Formula::Kind k) { return k == Formula::Kind::Until || k == Formula::Kind::Release; }
bool is_dual(Formula::Kind k) {
  return k == Formula::Kind::Globally || k == Formula::Kind::Release;
}

}  // namespace

bool OperatorMonitor::accepts(const Formula& formula) {
  bool negated = false;
  const Formula& op = operator_of(formula, negated);
  if (op.kind != Formula::Kind::Finally && op.kind != Formula::Kind::Globally &&
      !is_until(op.kind)) {
    return false;
  }
  if (op.bound.kind == Bound::Kind::Steps) return false;
  return std::all_of(op.operands.begin(), op.operands.end(),
                     [](const auto& operand) { return StateProgram::accepts(*operand); });
}

OperatorMonitor::OperatorMonitor(const Formula& formula, const TimeScale& scale,
                                 const Bindings& bindings, const Bound& run) {
  bool negated = false;
  const Formula& op = operator_of(formula, negated);
  until_ = is_until(op.kind);
  dual_ = negated != is_dual(op.kind);
  // The bounds in OnlineMonitor's order, for the same error on a formula with two bad ones.
  if (op.bound.kind == Bound::Kind::Time) {
    low_ = 2 * bound_ticks(op.bound.low, scale, bindings);
    high_ = 2 * bound_ticks(op.bound.high, scale, bindings);
  }
  if (until_) hold_ = StateProgram(*op.operands[0], is_dual(op.kind), bindings);
  goal_ = StateProgram(*op.operands[until_ ? 1 : 0], is_dual(op.kind), bindings);
  if (run.kind == Bound::Kind::Time) {
    time_bound_ = 2 * bound_ticks(run.high, scale, bindings);
    closed_ = {time_bound_, kLastRank};
  } else if (run.kind == Bound::Kind::Steps) {
    step_bound_ = bound_steps(run.high, bindings);
  }
  reset();
}

void OperatorMonitor::reset() {
  started_ = decided_ = false;
  steps_ = 0;
  origin_ = 0;
  last_ = {};
  end_ = closed_;
  hold_now_ = goal_now_ = false;
  progress_ = {};
  verdict_ = Verdict::Undecided;
  sure_hit_ = possible_hit_ = kForever;
}

bool OperatorMonitor::begin(Tick time) {
  if (decided_) return false;
  Pos at = online::kFirst;
  if (!started_) {
    started_ = true;
    origin_ = time;
  } else {
    const Tick t = 2 * (time - origin_);
    if (t < last_.t) throw std::invalid_argument("online monitor: a step earlier than the last");
    at = t == last_.t ? Pos{t, last_.n + 1} : Pos{t, 0};
    if (t > time_bound_) {
      finish_observation({time_bound_, kLastRank});
      return false;
    }
    if (steps_ > step_bound_) {
      finish_observation(online::before(at));
      return false;
    }
    // Most steps neither hold the goal nor fail the hold: nothing to read in them.
    if (goal_now_ || !hold_now_) span(progress_, last_, online::before(at), hold_now_, goal_now_);
  }
  last_ = at;
  return true;
}

void OperatorMonitor::span(Progress& p, Pos from, Pos to, bool hold, bool goal) const {
  if (p.found || !p.alive) return;
  if (goal && from <= end_) p.first_hit = std::min(p.first_hit, from);
  // The window's first position in from..to needs hold before it, on this span's positions
  // too when it is not the span's first.
  const Pos last = std::min({to, end_, Pos{high_, kLastRank}});
  const Pos first = std::max(from, Pos{low_, 0});
  if (goal && first <= last && (first == from || hold)) p.found = true;
  if (!hold) p.alive = false;
}

Verdict OperatorMonitor::end(RunEnd how) {
  if (decided_ || !started_) return verdict_;
  if (how == RunEnd::Deadlock || how == RunEnd::Absorbing) {
    // The last state holds forever (an absorbing one as a deadlock's: places and data only).
    span(progress_, last_, kForever, hold_now_, goal_now_);
    decide(progress_.found);
    return verdict_;
  }
  // A time-lock or a cut: the last state holds at its instant, and what follows is unknown.
  span(progress_, last_, last_, hold_now_, goal_now_);
  if (progress_.found || !progress_.alive) {
    decide(progress_.found);
    return verdict_;
  }
  // Kleene's value, as OnlineMonitor reads it: the unknown leaves read false for the sure
  // verdict, true for the possible one; the operator reads them through its duality.
  Progress sure = progress_, maybe = progress_;
  span(sure, online::after(last_), kForever, dual_, dual_);
  span(maybe, online::after(last_), kForever, !dual_, !dual_);
  verdict_ = sure.found != dual_    ? Verdict::True
             : maybe.found == dual_ ? Verdict::False
                                    : Verdict::Undecided;
  decided_ = true;
  sure_hit_ = until_ ? kForever : sure.first_hit;
  possible_hit_ = until_ ? kForever : maybe.first_hit;
  return verdict_;
}

void OperatorMonitor::finish_observation(Pos end) {
  // Nothing exists past `end`: the last state read holds up to it.
  end_ = end;
  span(progress_, last_, kForever, hold_now_, goal_now_);
  decide(progress_.found);
}

void OperatorMonitor::decide(bool found) {
  verdict_ = found != dual_ ? Verdict::True : Verdict::False;
  decided_ = true;
  sure_hit_ = possible_hit_ = until_ ? kForever : progress_.first_hit;
}

}  // namespace smcbip::monitors
