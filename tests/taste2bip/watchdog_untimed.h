// The untimed abstraction of a BIP system, as an IR transform: the engines' explorer keeps time
// (an item enabled later, or cut by an urgent one, is not listed now), so the abstraction that
// takes every clock constraint as true is made on the model before it is explored.
#pragma once

#include <string>

#include "bipc/ir/ir.h"

namespace smcbip::taste2bip::test {

/// Rewrites `system` in place into its untimed abstraction: every comparison that reads a clock
/// (directly or through arithmetic) becomes `true` (guards, resume conditions, priorities,
/// invariants), invariants are dropped, every transition is lazy, and @stochastic dates are
/// dropped. Clock resets are kept (they change nothing the abstraction reads). The rewrite keeps
/// each code's length: the instructions of a replaced comparison become jumps to the next
/// instruction, its last one `true`, so jump targets stay valid. Returns an empty string, or
/// why a code reads a clock in a way this cannot abstract (a clock passed to a function,
/// stored in data, or a comparison whose operands contain jumps).
std::string make_untimed(bipc::ir::System& system);

}  // namespace smcbip::taste2bip::test
