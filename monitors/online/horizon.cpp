#include "monitors/online/horizon.h"

#include <algorithm>

namespace smcbip::monitors {

Horizon horizon(const Formula& formula, const TimeScale& scale, const Bindings& bindings) {
  Horizon h;
  for (const auto& operand : formula.operands) {
    const Horizon o = horizon(*operand, scale, bindings);
    h.bounded = h.bounded && o.bounded;
    h.time = std::max(h.time, o.time);
    h.steps = std::max(h.steps, o.steps);
  }
  switch (formula.kind) {
    case Formula::Kind::Next:
      ++h.steps;
      break;
    case Formula::Kind::Finally:
    case Formula::Kind::Globally:
    case Formula::Kind::Until:
    case Formula::Kind::Release:
      if (formula.bound.kind == Bound::Kind::None) h.bounded = false;
      if (formula.bound.kind == Bound::Kind::Time) {
        h.time += bound_ticks(formula.bound.high, scale, bindings);
      }
      if (formula.bound.kind == Bound::Kind::Steps) {
        h.steps += bound_steps(formula.bound.high, bindings);
      }
      break;
    default:
      break;
  }
  return h;
}

}  // namespace smcbip::monitors
