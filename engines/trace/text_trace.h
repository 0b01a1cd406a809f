// The reference engine's text trace: state headers, listings, choices and error lines.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "engines/semantics/runtime.h"

namespace smcbip::engines {

inline constexpr const char* kEnginePrefix = "[BIP ENGINE]: ";

/// `<k> interaction[s] and <m> internal port[s] and <e> external port[s]:`
std::string enabled_summary(std::size_t interactions, std::size_t internals, std::size_t externals);

/// The listing entry of an item (without index): `ROOT.c: a.p() b.q() [ 0, +INFTY ]`.
std::string item_text(const Runtime& runtime, const Item& item, bool with_interval);

/// Writes the header and listing of a state.
void write_state(std::ostream& out, const Runtime& runtime, std::uint64_t step);

}  // namespace smcbip::engines
