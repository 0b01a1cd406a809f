// Predicates over growing clocks: each expression is evaluated as a line in the time since the
// step, valid up to its next breakpoint (a comparison's crossing, a kink of abs, min or max), so
// the walk from breakpoint to breakpoint finds every change of truth.
#include "monitors/online/growing_truth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "monitors/online/online_monitor.h"

namespace smcbip::monitors {

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// A walk finds at most two changes per crossing; the bound only guards against a predicate
// whose breakpoints never end.
constexpr int kMaxEvaluations = 100000;

/// An expression near `at` ticks after the step: c0 + c1 * t for t from `at` up to `next` (a
/// breakpoint after which another line holds; `next == at` when one starts right after `at`).
struct Piece {
  double c0 = 0, c1 = 0;
  double next = kNone;

  double at(double t) const { return c1 == 0 ? c0 : c0 + c1 * t; }
};

/// Where the line c0 + c1 * t crosses zero (c1 != 0), snapped to the whole tick it lies on
/// within rounding, so that a crossing at a whole tick is decided exactly.
double crossing(double c0, double c1) {
  const double t = -c0 / c1;
  const double whole = std::round(t);
  const double slack = 1e-6 + 4 * std::numeric_limits<double>::epsilon() * std::abs(t);
  return std::abs(t - whole) <= slack ? whole : t;
}

/// The sign of c0 + c1 * t at `t` (-1, 0, 1), by where t lies against the crossing.
int sign_at(const Piece& p, double t) {
  if (p.c1 == 0) return p.c0 > 0 ? 1 : p.c0 < 0 ? -1 : 0;
  const double r = crossing(p.c0, p.c1);
  const int after = p.c1 > 0 ? 1 : -1;
  return t > r ? after : t < r ? -after : 0;
}

/// The sign of the line just after `t`.
int sign_after(const Piece& p, double t) {
  const int s = sign_at(p, t);
  return s != 0 ? s : p.c1 > 0 ? 1 : p.c1 < 0 ? -1 : 0;
}

/// The next breakpoint of a sign change of the line after `t`, or `t` itself when the line is
/// zero there and changes sign right after.
double next_crossing(const Piece& p, double t) {
  if (p.c1 == 0) return kNone;
  const double r = crossing(p.c0, p.c1);
  return r >= t ? r : kNone;
}

Piece constant(double value) { return {value, 0, kNone}; }

class LineEvaluator {
 public:
  LineEvaluator(const StateView& state, const Bindings& bindings)
      : state_(state), bindings_(bindings) {}

  Piece eval(const Expr& e, double t) const {
    using K = Expr::Kind;
    switch (e.kind) {
      case K::Number:
        return constant(e.value.number);
      case K::Bool:
        return constant(e.boolean ? 1 : 0);
      case K::Fired:
        return constant(state_.fired(e) ? 1 : 0);
      case K::Name:
        return name(e);
      case K::Negate: {
        Piece a = eval(*e.operands[0], t);
        return {-a.c0, -a.c1, a.next};
      }
      case K::Add:
      case K::Subtract: {
        const Piece a = eval(*e.operands[0], t), b = eval(*e.operands[1], t);
        const double s = e.kind == K::Add ? 1 : -1;
        return {a.c0 + s * b.c0, a.c1 + s * b.c1, std::min(a.next, b.next)};
      }
      case K::Multiply:
        return multiply(e, t);
      case K::Divide:
      case K::Modulo:
        return divide(e, t);
      case K::Call:
        return call(e, t);
      default:
        return compare(e, t);
    }
  }

 private:
  Piece name(const Expr& e) const {
    if (!bindings_.empty() && (e.reference.kind == Reference::Kind::Constant ||
                               e.reference.kind == Reference::Kind::Unresolved)) {
      const auto it = bindings_.find(e.path);
      if (it != bindings_.end()) return constant(it->second);
    }
    return {state_.value(e), state_.slope(e), kNone};
  }

  [[noreturn]] static void not_linear(const Expr& e, const char* what) {
    throw MonitorError(e.at, "'" + to_string(e) + "' " + what +
                                 " a value that grows with time; predicates over clocks must "
                                 "be linear in them");
  }

  Piece multiply(const Expr& e, double t) const {
    const Piece a = eval(*e.operands[0], t), b = eval(*e.operands[1], t);
    if (a.c1 != 0 && b.c1 != 0) not_linear(e, "multiplies two values that grow, or");
    const double next = std::min(a.next, b.next);
    if (a.c1 == 0) return {a.c0 * b.c0, a.c0 * b.c1, next};
    return {a.c0 * b.c0, a.c1 * b.c0, next};
  }

  Piece divide(const Expr& e, double t) const {
    const Piece a = eval(*e.operands[0], t), b = eval(*e.operands[1], t);
    if (b.c1 != 0) not_linear(e, "divides by");
    const double next = std::min(a.next, b.next);
    if (e.kind == Expr::Kind::Divide) return {monitors::divide(e, a.c0, b.c0), a.c1 / b.c0, next};
    if (a.c1 != 0) not_linear(e, "takes the remainder of");
    return {monitors::remainder(e, a.c0, b.c0), 0, next};
  }

  // abs, min, max: the line of the side that holds just after t, up to where the sides cross.
  Piece call(const Expr& e, double t) const {
    const Piece a = eval(*e.operands[0], t);
    if (e.path == "abs") {
      const Piece flipped{-a.c0, -a.c1, a.next};
      Piece out = sign_after(a, t) >= 0 ? a : flipped;
      out.next = std::min(a.next, strictly_after(next_crossing(a, t), t));
      return out;
    }
    const Piece b = eval(*e.operands[1], t);
    const Piece difference{a.c0 - b.c0, a.c1 - b.c1, kNone};
    const bool a_larger = sign_after(difference, t) >= 0;
    Piece out = (e.path == "max") == a_larger ? a : b;
    out.next = std::min({a.next, b.next, strictly_after(next_crossing(difference, t), t)});
    return out;
  }

  // A kink at t itself changes nothing after t: the side chosen holds from t on.
  static double strictly_after(double r, double t) { return r > t ? r : kNone; }

  Piece compare(const Expr& e, double t) const {
    const Piece a = eval(*e.operands[0], t), b = eval(*e.operands[1], t);
    const Piece d{a.c0 - b.c0, a.c1 - b.c1, kNone};
    // Without growth, compare the values themselves, as the pointwise reading does.
    const int s = d.c1 == 0 ? (a.c0 > b.c0    ? 1
                               : a.c0 < b.c0  ? -1
                               : a.c0 == b.c0 ? 0
                                              : 2)
                            : sign_at(d, t);
    bool holds = false;
    switch (e.kind) {
      case Expr::Kind::Less:
        holds = s == -1;
        break;
      case Expr::Kind::LessEqual:
        holds = s == -1 || s == 0;
        break;
      case Expr::Kind::Greater:
        holds = s == 1;
        break;
      case Expr::Kind::GreaterEqual:
        holds = s == 1 || s == 0;
        break;
      case Expr::Kind::Equal:
        holds = s == 0;
        break;
      default:  // NotEqual; a NaN side (s == 2) compares unequal, as in C++
        holds = s != 0;
        break;
    }
    return {holds ? 1.0 : 0.0, 0, std::min({a.next, b.next, next_crossing(d, t)})};
  }

  const StateView& state_;
  const Bindings& bindings_;
};

}  // namespace

bool reads_growing(const Expr& e) {
  if (e.kind == Expr::Kind::Name) {
    return e.reference.kind == Reference::Kind::Clock ||
           e.reference.kind == Reference::Kind::Time ||
           e.reference.kind == Reference::Kind::Unresolved;
  }
  return std::any_of(e.operands.begin(), e.operands.end(),
                     [](const auto& operand) { return reads_growing(*operand); });
}

void truth_changes(const Expr& predicate, const StateView& state, const Bindings& bindings,
                   std::vector<TruthChange>& changes) {
  const LineEvaluator lines(state, bindings);
  changes.clear();
  online::Tick half = 0;  // the position evaluated: half ticks after the step
  Piece piece = lines.eval(predicate, 0);
  bool value = piece.c0 != 0;
  changes.push_back({0, value});
  for (int i = 0; i < kMaxEvaluations && piece.next != kNone; ++i) {
    // The first position whose time is at the breakpoint or after it.
    const double t = static_cast<double>(half) / 2;
    online::Tick next = half + 1;
    if (piece.next > t) {
      const double twice = std::ceil(2 * piece.next);
      if (!(twice < static_cast<double>(online::kNever))) break;
      next = std::max(next, static_cast<online::Tick>(twice));
    }
    half = next;
    piece = lines.eval(predicate, static_cast<double>(half) / 2);
    if ((piece.c0 != 0) != value) {
      value = !value;
      changes.push_back({half, value});
    }
  }
}

void Trajectory::compute(const Expr& expr, const StateView& state, const Bindings& bindings,
                         double horizon) {
  const LineEvaluator lines(state, bindings);
  lines_.clear();
  double t = 0;
  for (int i = 0; i < kMaxEvaluations; ++i) {
    const Piece piece = lines.eval(expr, t);
    lines_.push_back({t, piece.c0, piece.c1});
    if (!(piece.next > t) || !(piece.next < horizon)) break;
    t = piece.next;
  }
}

double Trajectory::at(double t) const {
  auto line = lines_.begin();
  while (line + 1 != lines_.end() && (line + 1)->from <= t) ++line;
  return line->c1 == 0 ? line->c0 : line->c0 + line->c1 * t;
}

double Trajectory::integral(double t) const {
  double sum = 0;
  for (std::size_t i = 0; i < lines_.size() && lines_[i].from < t; ++i) {
    const Line& line = lines_[i];
    const double end = i + 1 < lines_.size() ? std::min(lines_[i + 1].from, t) : t;
    // Exact on a line: the trapezoid.
    const double a = line.c0 + line.c1 * line.from, b = line.c0 + line.c1 * end;
    sum += (a + b) / 2 * (end - line.from);
  }
  return sum;
}

double Trajectory::extreme(double t, bool largest) const {
  double best = at(0);
  auto take = [&](double v) { best = largest ? std::max(best, v) : std::min(best, v); };
  // A line's extremes lie at its ends.
  for (std::size_t i = 0; i < lines_.size() && lines_[i].from <= t; ++i) {
    const Line& line = lines_[i];
    const double end = i + 1 < lines_.size() ? std::min(lines_[i + 1].from, t) : t;
    take(line.c0 + line.c1 * line.from);
    take(line.c0 + line.c1 * end);
  }
  return best;
}

}  // namespace smcbip::monitors
