// A short human-readable outline of the IR (`bipc ir` without --json).
#pragma once

#include <string>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// Instances of the system, one per line: compounds, atoms with their type and parameters,
/// connectors with the ports they bind, and priorities. Deterministic.
std::string to_text(const System& system);

}  // namespace smcbip::bipc::ir
