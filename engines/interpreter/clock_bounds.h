// Guards that bound clocks by literals (`x >= 1 && x <= 5`), recognised once so that the dates
// at which they hold are found without interpreting their code.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/interpreter/code_eval.h"
#include "engines/time_value.h"

namespace smcbip::engines {

/// A guard of the form `c1 && c2 && ...` (left-associated, as written without parentheses) in
/// which each ci compares one clock of the atom with a literal, on either side: the usual form
/// of timing constraints.
class ClockBounds {
 public:
  /// The bounds of `code`, if it has that form.
  static std::optional<ClockBounds> of(const bipc::ir::Code& code);

  /// The same dates as CodeEvaluator::holds_when(code, frame) for the code this was made of,
  /// found with the same arithmetic.
  Interval holds_when(const Frame& frame) const;

 private:
  struct Bound {
    bipc::ir::Index clock = 0;
    bipc::ir::Op op = bipc::ir::Op::Ge;
    double literal = 0.0;  // as holds_when reads it for the comparison's kind
    bool clock_on_left = true;
    /// The literal when it is a small integer (|literal| < 2^20), for narrow_exactly.
    std::optional<std::int64_t> small_literal;
    bipc::ir::Op clock_op = bipc::ir::Op::Ge;  // `clock clock_op literal`, whichever side
  };
  /// Narrows `dates` to the dates at which the bound holds, in integers, when the floating-
  /// point solution of holds_when is sure to be the exact one (see the definition); false,
  /// leaving `dates` unspecified, otherwise.
  [[gnu::always_inline]] static inline bool narrow_exactly(const Bound& bound,
                                                           const ClockState& clock, TimeValue unit,
                                                           TimeValue now, Interval& dates);
  /// holds_when by holds_when's own floating-point arithmetic.
  Interval solved(const Frame& frame) const;
  /// The comparison starting at instruction `pc`, if it is one of a clock and a literal; `pc`
  /// then moves past it.
  static std::optional<Bound> bound_at(const std::vector<bipc::ir::Instr>& instrs, std::size_t& pc);

  std::vector<Bound> bounds_;
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

 private:
  // Per Code::id: the guard (null when it has no bounds) and its bounds.
  std::vector<const bipc::ir::Code*> codes_;
  std::vector<std::optional<ClockBounds>> bounds_;
};

}  // namespace smcbip::engines
