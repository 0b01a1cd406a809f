// State predicates of the property language (resolved against the model) as Z3 formulas over
// a global state's variables, and as truth values of a concrete engine state.
#pragma once

#include <z3++.h>

#include "engines/semantics/runtime.h"
#include "fdir/smt/state_encoding.h"
#include "monitors/online/online_monitor.h"
#include "monitors/property/ast.h"

namespace smcbip::fdir {

/// `formula` (a state formula: no temporal operator) over the state's variables; `deadlock`
/// stands for `deadlock_states`. Names of constants read their value in `constants`. Throws
/// UnsupportedModel (in the property) for clocks, `time`, `init`, `timelock`, `fired`, `%`.
z3::expr encode_formula(const monitors::Formula& formula, const StateEncoding& state,
                        const monitors::Bindings& constants, const z3::expr& deadlock_states);

/// The truth of `formula` in the runtime's current state, `deadlocked` telling whether nothing
/// is enabled there.
bool holds_in(const monitors::Formula& formula, const engines::Runtime& runtime,
              const engines::StringPool& strings, const monitors::Bindings& constants,
              bool deadlocked);

}  // namespace smcbip::fdir
