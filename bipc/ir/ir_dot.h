// The architecture of a system as a Graphviz picture (`bipc dot`), and its rendering.
#pragma once

#include <string>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// Graphviz text of the instance tree: compounds as clusters, atoms as records listing their
/// exported ports, connectors as small ellipses with an edge to every port they may bind
/// (dashed for trigger ports of the define, bold to a connector bound hierarchically).
std::string to_dot(const System& system);

/// Writes `dot` text to `out_path` in the format its extension names: `.dot`/`.gv` as text,
/// `.svg`, `.png` or `.pdf` through the Graphviz `dot` program (run without a shell). The
/// result goes to a temporary file next to `out_path`, renamed into place only on success, so
/// a failure leaves nothing half-written. On failure returns false and explains in `error`.
bool render_svg(const std::string& dot, const std::string& out_path, std::string& error);

}  // namespace smcbip::bipc::ir
