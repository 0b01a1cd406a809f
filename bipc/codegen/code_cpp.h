// Translation of the IR's stack code into straight C++: one function per Code, its stack held in
// a local array with constant indices (which compilers keep in registers), its jumps as gotos.
#pragma once

#include <string>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::codegen {

/// Thrown on code the translator cannot follow (a backward jump, or stacks of different depths
/// meeting at one instruction): checked code never has either.
struct UntranslatableCode {
  std::string message;
};

/// A C++ function named `name` computing `code` the way the engines' interpreter does, over
/// `const smcbip::engines::Frame& f` and a context `c` with members `system`, `functions` and
/// `call` (the model's System, its BoundFunctions and the run's CallContext). With `returns_value`
/// it returns the value the code leaves on top of its stack (`true` when none), otherwise
/// nothing. Each instruction's semantics is a call of engines/api/code_ops.h with
/// constant arguments. The text uses the aliases `se` (smcbip::engines), `ops`
/// (smcbip::engines::code_ops) and `ir` (smcbip::bipc::ir), and the context type `Context`.
std::string code_function(const ir::System& system, const ir::Code& code, const std::string& name,
                          bool returns_value);

}  // namespace smcbip::bipc::codegen
