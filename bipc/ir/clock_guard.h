// The usual form of timing constraints, recognised in a guard's code: `c1 && c2 && ...`
// (left-associated, as written without parentheses) where each ci compares one clock of the
// atom with a literal, on either side. The engines find the dates of such guards without
// interpreting them, and bipc gen compiles them to straight C++.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// One comparison of a clock with a literal.
struct ClockComparison {
  Index clock = 0;
  Op op = Op::Ge;        // as written
  double literal = 0.0;  // read as the comparison's kind reads it (an int literal as a double)
  bool clock_on_left = true;
  /// The literal when it is a small integer (|literal| < 2^20).
  std::optional<std::int64_t> small_literal;
  Op clock_op = Op::Ge;  // `clock clock_op literal`, whichever side the clock was on
};

/// The comparison with its sides swapped (`a < b` is `b > a`).
inline Op turned_around(Op op) {
  return op == Op::Lt   ? Op::Gt
         : op == Op::Le ? Op::Ge
         : op == Op::Gt ? Op::Lt
         : op == Op::Ge ? Op::Le
                        : op;
}

/// Whether `code` reads a clock of its atom (a guard that does not holds at all dates or none).
bool reads_clock(const Code& code);

/// The comparisons of `guard`, in order, if it has the form above.
std::optional<std::vector<ClockComparison>> clock_comparisons(const Code& guard);

}  // namespace smcbip::bipc::ir
