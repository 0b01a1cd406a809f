// Loading the model a command works on: its system, with the front end's diagnostics on stderr.
#pragma once

#include <cstdint>
#include <optional>

#include "bipc/bipc.h"
#include "bipc/ir/ir.h"

namespace smcbip::tools {

/// Why a model could not be loaded: errors in it, or no root given and none to choose.
enum class LoadFailure : std::uint8_t { Errors, NoRoot };

/// The system of `frontend.file` instantiated at `frontend.root` (empty: the single top
/// compound). Its diagnostics (warnings too) go to stderr; nullopt with `failure` set when it
/// cannot be loaded.
std::optional<bipc::ir::System> load_model_system(const bipc::FrontendOptions& frontend,
                                                  LoadFailure& failure);

}  // namespace smcbip::tools
