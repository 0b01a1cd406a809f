// Clock bounds: recognition of the guard form and its dates, as holds_when computes them.
#include "engines/interpreter/clock_bounds.h"

#include <algorithm>
#include <cmath>

#include "engines/interpreter/code_eval.h"
#include "engines/interpreter/detail/time_sets.h"

namespace smcbip::engines {

std::optional<ClockBounds> ClockBounds::of(const bipc::ir::Code& code) {
  std::optional<std::vector<bipc::ir::ClockComparison>> comparisons =
      bipc::ir::clock_comparisons(code);
  if (!comparisons) return std::nullopt;
  ClockBounds bounds;
  bounds.bounds_ = std::move(*comparisons);
  return bounds;
}

Interval ClockBounds::holds_when(const Frame& frame) const {
  // holds_when joins the sides of `&&` by intersection, in this order; so does narrow, and
  // intersections commute with adding now to every date.
  Interval dates = Interval::all();
  for (const bipc::ir::ClockComparison& bound : bounds_) {
    const ClockState& clock = frame.clocks[bound.clock];
    if (!bound.small_literal ||
        !narrow_to_clock_bound(bound.clock_op, *bound.small_literal, clock,
                               frame.clock_units[bound.clock], frame.now, dates)) {
      return solved(frame);
    }
  }
  return dates;
}

Interval ClockBounds::solved(const Frame& frame) const {
  Interval delays = Interval::all();
  for (const bipc::ir::ClockComparison& bound : bounds_) {
    const ClockState& clock = frame.clocks[bound.clock];
    const TimeValue unit = frame.clock_units[bound.clock];
    // The clock is a + b*d at a delay d from now.
    const double a = CodeEvaluator::clock_value(clock, unit, frame.now);
    const double b = clock.rate / static_cast<double>(unit);
    // (la + lb d) op (ra + rb d)  <=>  (la - ra) + (lb - rb) d op 0, the literal's slope 0.
    const Interval set = bound.clock_on_left
                             ? detail::solve(bound.op, a - bound.literal, b - 0.0, 0.0)
                             : detail::solve(bound.op, bound.literal - a, 0.0 - b, 0.0);
    delays = delays.intersect(set);
  }
  return detail::shift(delays, frame.now);
}

GuardBounds::GuardBounds(const bipc::ir::System& system)
    : codes_(system.code_count, nullptr), bounds_(system.code_count) {
  for (const bipc::ir::AtomType& type : system.atom_types) {
    for (const bipc::ir::Transition& transition : type.transitions) {
      const bipc::ir::Code& guard = transition.guard;
      if (guard.id >= codes_.size()) continue;  // a system whose code is not numbered
      bounds_[guard.id] = ClockBounds::of(guard);
      if (bounds_[guard.id]) codes_[guard.id] = &guard;
    }
  }
  clock_free_.assign(system.code_count, nullptr);
  bipc::ir::for_each_code(system, [&](const bipc::ir::Code& code, bipc::ir::CodeUse use) {
    if (use != bipc::ir::CodeUse::Guard || code.id >= clock_free_.size()) return;
    if (!bipc::ir::reads_clock(code)) clock_free_[code.id] = &code;
  });
}

}  // namespace smcbip::engines
