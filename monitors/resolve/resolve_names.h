// Binding the names of a property file to a model: atomic predicates over the IR's atoms,
// places, data and clocks, and the connectors fired() names.
#pragma once

#include "bipc/diagnostics.h"
#include "bipc/ir/ir.h"
#include "monitors/property/ast.h"

namespace smcbip::monitors {

/// Resolves every name of `file`'s state expressions against `system` (Expr::reference) and
/// types them (Expr::is_bool), reporting at the name's position what does not resolve or fit.
/// A dotted path names an atom's data, place or clock (`Receiver.c2`, `Channel.id_channel`;
/// the root's name may lead, `ROOT.Channel.x`) or a compound's exported data; a plain name
/// names a constant or parameter of the file; fired() takes a connector or an `atom.port`.
/// A member that is both a place and a variable of its atom is ambiguous, hence an error.
/// Atomic predicates must be conditions, expectations numbers.
void resolve_names(PropertyFile& file, const bipc::ir::System& system,
                   bipc::Diagnostics& diagnostics);

}  // namespace smcbip::monitors
