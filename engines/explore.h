// Exhaustive exploration of the reachable states of an untimed model (`--explore`).
#pragma once

#include <cstdint>
#include <ostream>

#include "engines/semantics/runtime.h"

namespace smcbip::engines {

struct ExplorationCounts {
  std::uint64_t states = 0, deadlocks = 0, timelocks = 0, errors = 0, error_states = 0;
};

/// Breadth-first search from the initialised state: every enabled item of every reachable state
/// is executed once. A state is the marking and data of all atoms (time is ignored). Errors of
/// executing an item are counted, not reported one by one.
ExplorationCounts explore_states(Runtime& runtime);

/// The reference engine's summary line.
void write_exploration(std::ostream& out, const ExplorationCounts& counts);

}  // namespace smcbip::engines
