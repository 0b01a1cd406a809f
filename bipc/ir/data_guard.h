// A common shape of guards over data: comparisons `a op b` joined by `&&`, possibly followed by
// `&& rest`, where a and b are integer data or parameters of the atom, or integer literals
// (`s == 3`, `n > 0 && ph == 1`, `n < max && f(n)`). The engines test those leading comparisons
// straight from the atom's slots before they interpret the guard: when one is false the guard is
// false (the `&&` never reads what follows), and when they are the whole guard their conjunction
// is its value.
#pragma once

#include <array>
#include <cstddef>
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

/// One comparison of two integer operands.
struct IntComparison {
  IntOperand left, right;
  Op op = Op::Eq;  // Eq..Ge
};

/// The comparisons leading a guard of the shape above: `c1 && c2 && ... && rest`, each ci a
/// comparison, `rest` any code (none when `whole`).
struct LeadingComparison {
  static constexpr std::size_t kMax = 4;
  std::array<IntComparison, kMax> tests{};
  std::uint8_t count = 0;
  bool whole = false;  // the guard is the conjunction of the tests alone
};

/// The leading comparisons of `guard`, if it has the shape above.
std::optional<LeadingComparison> leading_comparison(const Code& guard);

}  // namespace smcbip::bipc::ir
