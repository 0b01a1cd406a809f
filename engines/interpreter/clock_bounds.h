// Guards that bound clocks by literals (`x >= 1 && x <= 5`), recognised once so that the dates
// at which they hold are found without interpreting their code.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/clock_guard.h"
#include "bipc/ir/ir.h"
#include "engines/api/compiled_model.h"
#include "engines/api/time_value.h"

namespace smcbip::engines {

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
