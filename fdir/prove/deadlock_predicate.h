// DIS, the states of the Petri net abstraction where no interaction is enabled (D-Finder, CAV
// 2009, section 4): for each interaction, some port offers no enabled transition or the
// connector's guard is false.
#pragma once

#include <z3++.h>

#include "fdir/smt/code_encoding.h"
#include "fdir/smt/state_encoding.h"

namespace smcbip::fdir {

/// Whether interaction `k` of the net is enabled in the state: every port offers a transition
/// whose places are marked and whose guard holds, and the connector's guard holds. Guards the
/// encoding cannot state exactly (clocks, floats, extern calls) are unknown booleans, so that
/// the negation over-approximates "not enabled".
z3::expr interaction_enabled(const StateEncoding& state, CodeEncoder& encoder, Index k);

/// The conjunction of the negations of every interaction's enabledness. Priorities are
/// ignored: when some interaction is enabled, one of highest priority is too (no cycles), so
/// the real deadlocks are among these states.
z3::expr deadlock_predicate(const StateEncoding& state, CodeEncoder& encoder);

}  // namespace smcbip::fdir
