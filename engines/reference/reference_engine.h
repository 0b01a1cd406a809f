// The reference engine: the semantics as stated, with nothing added.
#pragma once

#include "engines/engine.h"

namespace smcbip::engines {

/// Every interaction computed again at every step, the atoms of an interaction fired in
/// sequence, every step decided by the Scheduler: the oracle the other engines are tested
/// against.
const Engine& reference_engine();

}  // namespace smcbip::engines
