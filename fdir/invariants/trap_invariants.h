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

/// A trap inside the trap `within` (per global place) containing `place`: grown from {place} by
/// adding, for each transition that takes from the set and puts nothing back, its output places
/// in `within` (there is one, `within` being a trap). Small traps make strong invariants.
std::vector<Index> trap_around(const PetriNet& net, const std::vector<std::uint8_t>& within,
                               Index place);

/// Traps initially marked and wholly unmarked in `marking` (per global place), each of which
/// excludes that marking from the reachable ones: one small trap around each initially marked
/// place of the largest trap of the unmarked places, at most `limit`, without repetition. Empty
/// when no initially marked trap excludes the marking.
std::vector<std::vector<Index>> excluding_traps(const PetriNet& net,
                                                const std::vector<std::uint8_t>& marking,
                                                std::size_t limit);

}  // namespace smcbip::fdir
