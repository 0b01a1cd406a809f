// The multithread engine: the optimised engine's incremental cache, with the atoms of one
// interaction fired on a thread pool.
#pragma once

#include "engines/engine.h"

namespace smcbip::engines {

/// The incremental cache, and the atoms of an interaction fired on `--threads` threads (all
/// cores for 0) when that is observably the same as in sequence (multithread/pool_firing.h).
/// Every step is decided by the Scheduler.
const Engine& multithread_engine();

}  // namespace smcbip::engines
