// The compiled atom steps of a generated model: per atom type, its offers, internal transitions
// and firing as straight C++ (the engines' ModelCode::atom_offers, atom_internal, atom_fire).
#pragma once

#include <string>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::codegen {

/// The functions of every atom type (taking the generated Context as `void* context`), the
/// switch cases (on the atom type) that call them with the code's context `c_`, and the entries
/// of the engines::CompiledAtomSteps table, one per type in order. The text uses what
/// code_function's does, the code functions `code_<id>` of every Code, and a context member
/// `timed` (the evaluator of guards over clocks).
struct AtomStepFunctions {
  std::string definitions;
  std::string offers_cases, internal_cases, fire_cases;
  std::string table_entries;
};

AtomStepFunctions atom_step_functions(const ir::System& system);

}  // namespace smcbip::bipc::codegen
