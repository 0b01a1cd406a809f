#include "monitors/online/critical_bound.h"

namespace smcbip::monitors {
namespace {

bool names(const Expr& e, const std::string& name) {
  if (e.kind == Expr::Kind::Name && e.path == name) return true;
  for (const auto& operand : e.operands) {
    if (names(*operand, name)) return true;
  }
  return false;
}

bool names(const Formula& f, const std::string& name) {
  if (f.bound.low.name == name || f.bound.high.name == name) return true;
  if (f.atom && names(*f.atom, name)) return true;
  for (const auto& operand : f.operands) {
    if (names(*operand, name)) return true;
  }
  return false;
}

Bindings with(Bindings bindings, const std::string& name, double value) {
  bindings[name] = value;
  return bindings;
}

}  // namespace

bool has_critical_bound(const Formula& formula, const std::string& parameter) {
  const Bound& b = formula.bound;
  return (formula.kind == Formula::Kind::Finally || formula.kind == Formula::Kind::Globally) &&
         b.kind == Bound::Kind::Time && !b.low.is_name() && b.low.number == 0 &&
         b.high.name == parameter && !names(*formula.operands[0], parameter);
}

CriticalBound::CriticalBound(const Formula& formula, const std::string& parameter, double largest,
                             const TimeScale& scale, const Bindings& bindings, const Bound& run)
    : monitor_(formula, scale, with(bindings, parameter, largest), run),
      finally_(formula.kind == Formula::Kind::Finally),
      bound_(formula.bound.high),
      scale_(scale) {}

Verdict CriticalBound::verdict(double value) const {
  if (!monitor_.over()) return Verdict::Undecided;
  Value v = bound_;
  v.name.clear();
  v.number = value;
  const online::Tick t = bound_ticks(v, scale_, {});
  // A first hit at half tick h lies in [0, t] when 2t >= h.
  const auto reaches = [&](online::Pos hit) { return hit != online::kForever && 2 * t >= hit.t; };
  const bool sure = reaches(monitor_.first_hit_for_sure());
  const bool possible = reaches(monitor_.first_hit_possibly());
  // F: a hit holds phi; G: a hit fails it.
  if (finally_) return sure ? Verdict::True : possible ? Verdict::Undecided : Verdict::False;
  return !sure ? Verdict::True : possible ? Verdict::False : Verdict::Undecided;
}

}  // namespace smcbip::monitors
