// Time sets of clock comparisons, shared by the interpreter's holds_when and ClockBounds so that
// both find exactly the same dates.
#pragma once

#include <algorithm>
#include <cmath>

#include "bipc/ir/clock_guard.h"
#include "bipc/ir/ir.h"
#include "engines/api/time_value.h"

namespace smcbip::engines::detail {

using bipc::ir::Op;

inline Interval relative_set(bool holds) { return holds ? Interval::all() : Interval::none(); }

using bipc::ir::turned_around;

/// {d | a + b*d op c}, on integer nanoseconds.
inline Interval solve(Op op, double a, double b, double c) {
  if (b == 0.0) {
    const bool holds = op == Op::Lt   ? a < c
                       : op == Op::Le ? a <= c
                       : op == Op::Gt ? a > c
                       : op == Op::Ge ? a >= c
                       : op == Op::Eq ? a == c
                                      : a != c;
    return relative_set(holds);
  }
  const double x = (c - a) / b;
  // Dividing by a negative slope turns the comparison around.
  if (b < 0.0) op = turned_around(op);
  const double limit = 9.0e18;
  if (x > limit) return op == Op::Lt || op == Op::Le ? Interval::all() : Interval::none();
  if (x < -limit) return op == Op::Gt || op == Op::Ge ? Interval::all() : Interval::none();
  const double nearest = std::nearbyint(x);
  const bool integral = std::fabs(x - nearest) <= 1e-6 * std::max(1.0, std::fabs(x));
  const auto at = static_cast<TimeValue>(nearest);
  Interval result = Interval::all();
  switch (op) {
    case Op::Lt:
      if (integral) return {kMinusInfinity, at, false, true};
      result.right = static_cast<TimeValue>(std::floor(x));
      return result;
    case Op::Le:
      result.right = integral ? at : static_cast<TimeValue>(std::floor(x));
      return result;
    case Op::Gt:
      if (integral) return {at, kPlusInfinity, true, false};
      result.left = static_cast<TimeValue>(std::ceil(x));
      return result;
    case Op::Ge:
      result.left = integral ? at : static_cast<TimeValue>(std::ceil(x));
      return result;
    case Op::Eq:
      return integral ? Interval::point(at) : Interval::none();
    default:
      // `!=` over clocks is refused by the checker; keep the dates where it holds now.
      return Interval::all();
  }
}

/// A set of delays from `now` as a set of dates.
inline Interval shift(const Interval& set, TimeValue now) {
  Interval r = set;
  if (r.left != kMinusInfinity) r.left += now;
  if (r.right != kPlusInfinity) r.right += now;
  return r;
}

}  // namespace smcbip::engines::detail
