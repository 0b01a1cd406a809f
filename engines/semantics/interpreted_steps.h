// The flat step path (flat_steps.h) over an interpreted model: the optimised engine's lean
// steps for the systems flat_tables covers, with the atoms' transitions interpreted as the
// Runtime interprets them (atom_steps.h).
#pragma once

#include <memory>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/semantics/compiled_steps.h"
#include "engines/semantics/layout.h"

namespace smcbip::engines {

/// The flat step path over `code` when it is the interpreter (CodeEvaluator) and flat_tables
/// covers the system; nullptr otherwise. `code` must outlive it.
std::unique_ptr<CompiledSteps> make_interpreted_steps(ModelCode& code,
                                                      const bipc::ir::System& system,
                                                      const Layout& layout);

}  // namespace smcbip::engines
