// The optimised engine: the reference semantics with the incremental cache and the compiled
// step path.
#pragma once

#include "engines/engine.h"

namespace smcbip::engines {

/// Each connector's interactions kept between steps and computed again only when an execution
/// touched its atoms (semantics/connector_cache.h; on untimed layouts the items counted rather
/// than listed, semantics/item_index.h), and runs on the model's compiled step path
/// (semantics/flat_steps.h) wherever they can take it: no text trace, no prompt, simulated
/// time, maximal progress.
const Engine& optimised_engine();

}  // namespace smcbip::engines
