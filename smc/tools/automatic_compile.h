// `smcbip check --compile auto|always|never`: the model's generated code, built once into the
// cache of compiled models, runs the check when it pays (or always, or never).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "engines/api/plugin.h"
#include "monitors/monitors.h"
#include "smc/check/check.h"
#include "smc/tools/plugin_cache.h"

namespace smcbip::tools {

enum class CompileMode : std::uint8_t { Auto, Always, Never };

/// The plugin the check runs, or null to run the model interpreted. A plugin in the cache is
/// always used (Never aside). On a miss, Always builds it; Auto builds it when the runs are
/// expected to take longer interpreted (estimate_run_time) than the last build took (or
/// kDefaultBuildSeconds), and stays silent otherwise. What is used or built is said on `err`;
/// a build that fails, or that Always cannot make for want of a tool, is a one-line warning
/// there, and the check runs interpreted all the same.
const engines::PluginEntry* compiled_model(CompileMode mode, const ModelToCompile& model,
                                           const monitors::PropertyFile& file,
                                           const smc::CheckOptions& options, bool explore,
                                           std::ostream& err);

}  // namespace smcbip::tools
