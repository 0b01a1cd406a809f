// A common shape of transition actions: a sequence of assignments of an atom's data or clocks,
// each from a literal or from a datum plus or minus a literal (`n = n + 1; ph = 2; x = 0;`).
// The engines run such an action straight on the atom's slots instead of interpreting its code:
// the same stores of the same values, without the stack machine.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// One assignment of an action of the shape above.
struct SimpleAssignment {
  enum class Kind : std::uint8_t {
    Int,       // data[target] = literal (int)
    Float,     // data[target] = real (float)
    AddInt,    // data[target] = data[source] + literal, wrapping as the interpreter's Add
    ClockSet,  // clocks[target] reset to real
  } kind = Kind::Int;
  Index target = 0;
  Index source = 0;          // AddInt
  std::int64_t literal = 0;  // Int, AddInt (a Sub is the Add of the literal's wrapped negation)
  double real = 0.0;         // Float, ClockSet
};

/// The assignments of `action` in order, if it has the shape above (empty for an empty action).
std::optional<std::vector<SimpleAssignment>> simple_action(const Code& action);

}  // namespace smcbip::bipc::ir
