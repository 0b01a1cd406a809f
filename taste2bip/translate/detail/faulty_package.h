// The packages of the FDIR workflow beside the nominal one (ESROCOS D3.1, 5.2.5): the faulty
// package replicates each function's atom (its interface, data and places) with no behaviour,
// for the user to write the faulty transitions in; the requirements package is where the
// observers of the requirements go.
#pragma once

#include <string>
#include <vector>

#include "taste2bip/translate/sdl_atom.h"
#include "taste2bip/translate/signature.h"

namespace smcbip::taste2bip::detail {

/// `declarations` are the nominal package's extern and port types, copied so that the faulty
/// package stands alone. An SDL function's faulty atom is given (`faulty`, sdl_fault_atom: its
/// fault signals as fault transitions); the others repeat their nominal atom's declarations.
std::string faulty_package(const std::string& name, const std::string& declarations,
                           const std::vector<AtomType>& atoms, const std::vector<AtomType>& faulty);

std::string requirements_package(const std::string& name);

}  // namespace smcbip::taste2bip::detail
