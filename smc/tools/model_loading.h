// Loading the model a command works on: its system, or its diagnostics on stderr.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::tools {

/// The system of `file` instantiated at `root` (empty: the single top compound); nullopt
/// after reporting why not on stderr.
std::optional<bipc::ir::System> load_model_system(const std::string& file, const std::string& root,
                                                  const std::vector<std::string>& include_dirs);

}  // namespace smcbip::tools
