// Interaction invariants from the traps of the Petri net, computed lazily against a candidate
// marking (D-Finder, CAV 2009, section 3.2: an initially marked trap stays marked).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "fdir/net/petri_net.h"

namespace smcbip::fdir {

/// The largest trap of `net` inside the places `allowed` (per global place, nonzero when the
/// place may belong to it): the places from which some transition takes a token without putting
/// one back into the set are removed until none is (Starke's fixpoint). Every trap inside
/// `allowed` is inside the result.
std::vector<Index> largest_trap(const PetriNet& net, const std::vector<std::uint8_t>& allowed);

/// A trap initially marked and wholly unmarked in `marking` (per global place), which excludes
/// that marking from the reachable ones; nullopt when there is none (no initially marked trap
/// excludes it).
std::optional<std::vector<Index>> excluding_trap(const PetriNet& net,
                                                 const std::vector<std::uint8_t>& marking);

}  // namespace smcbip::fdir
