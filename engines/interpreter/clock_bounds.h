// Guards that bound clocks by literals (`x >= 1 && x <= 5`), recognised once so that the dates
// at which they hold are found without interpreting their code.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/clock_guard.h"
#include "bipc/ir/ir.h"
#include "engines/interpreter/code_eval.h"
#include "engines/time_value.h"

namespace smcbip::engines {

/// Narrows `dates` to the dates at which `clock clock_op literal` holds (clock_op one of < <= >
/// >= ==), in integers, when the floating-point solution of CodeEvaluator::holds_when is sure to
/// be that exact one: a clock running at rate 1 from 0, dates and literal*unit within 2^30 ns of
/// it, |literal| < 2^20. False otherwise, leaving `dates` unspecified: holds_when then answers.
[[gnu::always_inline]] inline bool narrow_to_clock_bound(bipc::ir::Op clock_op,
                                                         std::int64_t literal,
                                                         const ClockState& clock, TimeValue unit,
                                                         TimeValue now, Interval& dates) {
  // A clock running at rate 1 from 0 since `since` reaches the literal L at the integer date
  // r = since + L*unit: the bound holds from (or until) r. holds_when solves for the delay
  // e = r - now in floating point, up to a rounding error below 4 * 2^-53 times the largest of
  // |now - since|, |L*unit| and |e|; under 2^30 ns that is below 1e-6, which solve() rounds to
  // e exactly (finding it "integral"), and then adds now back: the same dates.
  constexpr TimeValue kExact = TimeValue{1} << 30;
  if (clock.rate != 1.0 || clock.value_at != 0.0) return false;
  const TimeValue elapsed = now - clock.since;
  const TimeValue reach = literal * unit;
  if (elapsed < 0 || elapsed >= kExact || reach <= -kExact || reach >= kExact) return false;
  const TimeValue r = clock.since + reach;
  Interval holds = Interval::all();
  switch (clock_op) {
    case bipc::ir::Op::Lt:
    case bipc::ir::Op::Le:
      holds.right = r;
      holds.right_open = clock_op == bipc::ir::Op::Lt;
      break;
    case bipc::ir::Op::Gt:
    case bipc::ir::Op::Ge:
      holds.left = r;
      holds.left_open = clock_op == bipc::ir::Op::Gt;
      break;
    case bipc::ir::Op::Eq:
      holds = Interval::point(r);
      break;
    default:
      return false;
  }
  narrow(dates, holds);
  return true;
}

/// A guard of the form bipc/ir/clock_guard.h recognises: the usual form of timing constraints.
class ClockBounds {
 public:
  /// The bounds of `code`, if it has that form.
  static std::optional<ClockBounds> of(const bipc::ir::Code& code);

  /// The same dates as CodeEvaluator::holds_when(code, frame) for the code this was made of,
  /// found with the same arithmetic.
  Interval holds_when(const Frame& frame) const;

 private:
  /// holds_when by holds_when's own floating-point arithmetic.
  Interval solved(const Frame& frame) const;

  std::vector<bipc::ir::ClockComparison> bounds_;
};

/// The clock bounds of every transition guard of a system that has that form, found by the
/// guard's Code::id: the interpreter answers holds_when for them without running their code.
class GuardBounds {
 public:
  explicit GuardBounds(const bipc::ir::System& system);
  /// The bounds of `code`, if it is a guard of the system with that form.
  const ClockBounds* find(const bipc::ir::Code& code) const {
    if (code.id >= codes_.size() || codes_[code.id] != &code) return nullptr;
    return &*bounds_[code.id];
  }
  /// Whether `code` is a guard of the system that reads no clock: it holds at all dates or at
  /// none, so the plain evaluator answers for it.
  bool clock_free(const bipc::ir::Code& code) const {
    return code.id < clock_free_.size() && clock_free_[code.id] == &code;
  }

 private:
  // Per Code::id: the guard (null when it has no bounds) and its bounds.
  std::vector<const bipc::ir::Code*> codes_;
  std::vector<std::optional<ClockBounds>> bounds_;
  std::vector<const bipc::ir::Code*> clock_free_;  // per Code::id: the guard, if clock-free
};

}  // namespace smcbip::engines
