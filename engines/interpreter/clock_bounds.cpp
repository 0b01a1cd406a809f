// Clock bounds: recognition of the guard form and its dates, as holds_when computes them.
#include "engines/interpreter/clock_bounds.h"

#include <cmath>

#include "engines/interpreter/detail/time_sets.h"

namespace smcbip::engines {

using bipc::ir::Instr;
using bipc::ir::Op;

namespace {

bool is_clock_load(const Instr& in) {
  return in.op == Op::Load && in.scope == bipc::ir::Scope::Clock;
}

/// A literal pushed from instruction `pc` (PushInt, PushFloat, or PushInt then IntToFloat), as
/// the value holds_when's stack would hold; `pc` then moves past it.
std::optional<Val> literal_at(const std::vector<Instr>& instrs, std::size_t& pc) {
  if (pc >= instrs.size()) return std::nullopt;
  const Instr& in = instrs[pc];
  if (in.op == Op::PushFloat) {
    ++pc;
    return make_float(in.imm.f);
  }
  if (in.op != Op::PushInt) return std::nullopt;
  ++pc;
  if (pc < instrs.size() && instrs[pc].op == Op::IntToFloat) {
    ++pc;
    return make_float(static_cast<double>(in.imm.i));
  }
  return make_int(in.imm.i);
}

}  // namespace

std::optional<ClockBounds::Bound> ClockBounds::bound_at(const std::vector<Instr>& instrs,
                                                        std::size_t& pc) {
  Bound bound;
  std::optional<Val> literal;
  if (pc < instrs.size() && is_clock_load(instrs[pc])) {
    bound.clock = instrs[pc++].index;
    literal = literal_at(instrs, pc);
  } else {
    literal = literal_at(instrs, pc);
    if (!literal || pc >= instrs.size() || !is_clock_load(instrs[pc])) return std::nullopt;
    bound.clock = instrs[pc++].index;
    bound.clock_on_left = false;
  }
  if (!literal || pc >= instrs.size() || !bipc::ir::is_comparison(instrs[pc].op))
    return std::nullopt;
  const Instr& compare = instrs[pc++];
  bound.op = compare.op;
  // holds_when reads a plain operand by the comparison's kind (its as_double).
  bound.literal = compare.kind == ValueKind::Float ? literal->f : static_cast<double>(literal->i);
  if (std::fabs(bound.literal) < 0x1p20 && bound.literal == std::floor(bound.literal)) {
    bound.small_literal = static_cast<std::int64_t>(bound.literal);
  }
  // `L op x` is `x op' L` with the comparison turned around.
  bound.clock_op = bound.clock_on_left ? bound.op : detail::turned_around(bound.op);
  return bound;
}

std::optional<ClockBounds> ClockBounds::of(const bipc::ir::Code& code) {
  const std::vector<Instr>& instrs = code.instrs;
  ClockBounds guard;
  std::size_t pc = 0;
  for (;;) {
    const std::optional<Bound> bound = bound_at(instrs, pc);
    if (!bound) return std::nullopt;
    guard.bounds_.push_back(*bound);
    if (pc == instrs.size()) return guard;
    // `a && b`: the left side's short-circuit jump lands right after the right side.
    const Instr& jump = instrs[pc++];
    std::size_t next = pc;
    if (jump.op != Op::JumpIfFalseKeep || !bound_at(instrs, next) || jump.index != next) {
      return std::nullopt;
    }
  }
}

inline bool ClockBounds::narrow_exactly(const Bound& bound, const ClockState& clock, TimeValue unit,
                                        TimeValue now, Interval& dates) {
  // A clock running at rate 1 from 0 since `since` reaches the literal L at the integer date
  // r = since + L*unit: the bound holds from (or until) r. holds_when solves for the delay
  // e = r - now in floating point, up to a rounding error below 4 * 2^-53 times the largest of
  // |now - since|, |L*unit| and |e|; under 2^30 ns that is below 1e-6, which solve() rounds to
  // e exactly (finding it "integral"), and then adds now back: the same dates.
  constexpr TimeValue kExact = TimeValue{1} << 30;
  if (!bound.small_literal || clock.rate != 1.0 || clock.value_at != 0.0) return false;
  const TimeValue elapsed = now - clock.since;
  const TimeValue reach = *bound.small_literal * unit;
  if (elapsed < 0 || elapsed >= kExact || reach <= -kExact || reach >= kExact) return false;
  const TimeValue r = clock.since + reach;
  Interval holds = Interval::all();
  switch (bound.clock_op) {
    case Op::Lt:
    case Op::Le:
      holds.right = r;
      holds.right_open = bound.clock_op == Op::Lt;
      break;
    case Op::Gt:
    case Op::Ge:
      holds.left = r;
      holds.left_open = bound.clock_op == Op::Gt;
      break;
    case Op::Eq:
      holds = Interval::point(r);
      break;
    default:
      return false;
  }
  narrow(dates, holds);
  return true;
}

Interval ClockBounds::holds_when(const Frame& frame) const {
  // holds_when joins the sides of `&&` by intersection, in this order; so does narrow, and
  // intersections commute with adding now to every date.
  Interval dates = Interval::all();
  for (const Bound& bound : bounds_) {
    const ClockState& clock = frame.clocks[bound.clock];
    if (!narrow_exactly(bound, clock, frame.clock_units[bound.clock], frame.now, dates)) {
      return solved(frame);
    }
  }
  return dates;
}

Interval ClockBounds::solved(const Frame& frame) const {
  Interval delays = Interval::all();
  for (const Bound& bound : bounds_) {
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
}

}  // namespace smcbip::engines
