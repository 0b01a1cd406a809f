// Loading what a command works on: the model's system, with the front end's diagnostics on
// stderr, and the property file, read whole once it is known to be a file of bounded size.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "bipc/ir/ir.h"
#include "monitors/monitors.h"

namespace smcbip::tools {

/// Why a model could not be loaded: errors in it, or no root given and none to choose.
enum class LoadFailure : std::uint8_t { Errors, NoRoot };

/// The system of `frontend.file` instantiated at `frontend.root` (empty: the single top
/// compound). Its diagnostics (warnings too) go to stderr; nullopt with `failure` set when it
/// cannot be loaded. Throws smcbip::InputError when the file is a folder or a device.
std::optional<bipc::ir::System> load_model_system(const bipc::FrontendOptions& frontend,
                                                  LoadFailure& failure);

/// The queries of the property file `path` with the values of `parameters` (--param). Throws
/// smcbip::InputError when it is not a regular file or is larger than 4 MiB.
monitors::ParsedProperties load_property_file(const std::string& path,
                                              const std::vector<std::string>& parameters = {});

}  // namespace smcbip::tools
