// The Z3 variables of one global state of a system: a boolean per place of each atom and a
// term per datum (integers and booleans; other data are left unconstrained).
#pragma once

#include <z3++.h>

#include <vector>

#include "bipc/ir/ir.h"
#include "fdir/net/petri_net.h"

namespace smcbip::fdir {

class StateEncoding {
 public:
  /// Variables named after the net's places and `root.atom.datum`.
  StateEncoding(z3::context& context, const bipc::ir::System& system, const PetriNet& net);

  /// Whether a place (global number) is marked.
  const z3::expr& place(Index global) const { return places_[global]; }
  const z3::expr& place(Index atom, Index local) const {
    return places_[net_.first_place[atom] + local];
  }
  /// The data terms of an atom, one per slot of its type.
  const std::vector<z3::expr>& data(Index atom) const { return data_[atom]; }
  const bipc::ir::System& system() const { return system_; }
  const PetriNet& net() const { return net_; }
  z3::context& context() const { return context_; }

 private:
  z3::context& context_;
  const bipc::ir::System& system_;
  const PetriNet& net_;
  std::vector<z3::expr> places_;
  std::vector<std::vector<z3::expr>> data_;
};

/// A constant of the sort of a data type (Bool, Int; Real for what is not followed).
z3::expr data_constant(z3::context& context, const std::string& name, bipc::ir::ValueKind kind);

}  // namespace smcbip::fdir
