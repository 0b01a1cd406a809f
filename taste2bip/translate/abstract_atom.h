// The atom of a function whose behaviour the design does not give (no SDL, no C/C++ body found,
// an Ada or GUI function): each call of a provided interface may call each required interface once,
// in the view's order, or skip it, then returns. It over-approximates the calls any body could make
// per activation; the data it sends are its data's current values.
#pragma once

#include "taste2bip/translate/sdl_atom.h"

namespace smcbip::taste2bip {

AtomType abstract_atom(const FunctionSignature& function);

}  // namespace smcbip::taste2bip
