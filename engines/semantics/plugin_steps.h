// The flat step path (flat_steps.h) over generated code: the atoms' steps called through the
// table the code exports (ModelCode::compiled_atoms), its guards and actions through its
// interface, so that the path is compiled here, in the engines, and a model's plugin compiles
// against the public API alone.
#pragma once

#include <memory>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/semantics/compiled_steps.h"
#include "engines/semantics/layout.h"

namespace smcbip::engines {

/// The flat step path over `code` whose atom steps are `atoms`, when flat_tables covers the
/// system; nullptr otherwise. `code` (and the context of `atoms`) must outlive it.
std::unique_ptr<CompiledSteps> make_plugin_steps(ModelCode& code, const CompiledAtoms& atoms,
                                                 const bipc::ir::System& system,
                                                 const Layout& layout);

}  // namespace smcbip::engines
