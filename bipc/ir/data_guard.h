// A common shape of guards over data: `a op b` or `a op b && rest`, where a and b are integer
// data or parameters of the atom, or integer literals (`s == 3`, `n < max && ...`). The engines
// test that leading comparison straight from the atom's slots before they interpret the guard:
// when it is false the guard is false (the `&&` never reads `rest`), and when it is the whole
// guard its value is the guard's.
#pragma once

#include <cstdint>
#include <optional>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// An integer operand read without the interpreter.
struct IntOperand {
  enum class Kind : std::uint8_t { Literal, AtomData, AtomParam } kind = Kind::Literal;
  Index index = 0;           // AtomData, AtomParam: the slot
  std::int64_t literal = 0;  // Literal
};

/// The first comparison of a guard of the shape above.
struct LeadingComparison {
  IntOperand left, right;
  Op op = Op::Eq;      // Eq..Ge
  bool whole = false;  // the guard is this comparison alone
};

/// The leading comparison of `guard`, if it has the shape above.
std::optional<LeadingComparison> leading_comparison(const Code& guard);

}  // namespace smcbip::bipc::ir
