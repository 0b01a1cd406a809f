// What a property file must satisfy beyond its grammar, before any model is known.
#pragma once

#include "bipc/diagnostics.h"
#include "monitors/property/ast.h"

namespace smcbip::monitors::detail {

/// Reports: constants and parameters declared twice or used before their declaration (in
/// bounds, thresholds and run counts); thresholds outside [0, 1]; step bounds and run counts
/// that are not whole numbers; negative or reversed time bounds; time units where no time is
/// meant; empty parameter ranges.
void check_properties(const PropertyFile& file, bipc::Diagnostics& diagnostics);

}  // namespace smcbip::monitors::detail
