// Transitions whose firing always changes their atom's places or data, told from their code:
// a step that fires one cannot have kept the state, so the engines' absorbing-state check need
// not compare the state before and after it.
#pragma once

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// Whether firing `transition` always leaves its atom's places or data different from before:
/// its `from` and `to` places differ as sets (a 1-safe atom loses a place), or its action
/// (bipc/ir/simple_action.h) leaves a datum at a literal other than the one a leading `==` of
/// its guard (bipc/ir/data_guard.h) pinned it to, or at itself plus a literal other than 0.
/// `written_before`: a connector's `down` may have written the atom's data before the action
/// runs; then only the first two count, since `n = n + 1` may undo such a write.
/// False whenever the code has another shape: the answer errs only towards "may keep".
bool always_changes_state(const Transition& transition, bool written_before);

}  // namespace smcbip::bipc::ir
