// Linear invariants of the Petri net: the state equation M = M0 + C.x (x >= 0 integer, the
// number of firings of each net transition), which every reachable marking satisfies (Esparza,
// Melzer, "Verification of safety properties using integer programming: beyond the state
// equation", FMSD 2000; Silva, Teruel, Colom, "Linear algebraic and linear programming
// techniques for the analysis of place/transition net systems", 1998).
#pragma once

#include <z3++.h>

#include <cstddef>
#include <vector>

#include "fdir/smt/state_encoding.h"

namespace smcbip::fdir {

/// The state equation as Z3 clauses over the state's place variables and one integer
/// variable per net transition. The engines stop a run whose transition would put a token on a
/// marked place (atoms are 1-safe nets), so along every run a place's token count is its
/// marking, and it changes by (tokens put) - (tokens taken) at each firing: the equation holds
/// in every reachable state of the net, hence (priorities and guards only removing firings) of
/// the model. Places of an atom that takes part twice in some net transition are left out (the
/// engines' effect of two transitions of one atom in one step is not a sum of arcs).
class StateEquation {
 public:
  explicit StateEquation(const StateEncoding& state);

  /// x_t >= 0 per net transition and, per place kept, [p] = M0(p) + sum_t C(p, t) x_t.
  const z3::expr_vector& clauses() const { return clauses_; }
  /// The firing count variable of net transition `t`.
  const z3::expr& firings(Index t) const { return firings_[t]; }
  /// How many places have an equation.
  std::size_t places() const { return places_; }

 private:
  z3::expr_vector clauses_;
  std::vector<z3::expr> firings_;
  std::size_t places_ = 0;
};

/// The incidence of net transition `t` on each place (tokens put minus tokens taken, one per
/// atom transition and place), as (place, change) pairs without zero changes, in place order.
std::vector<std::pair<Index, int>> incidence(const bipc::ir::System& system, const PetriNet& net,
                                             Index t);

}  // namespace smcbip::fdir
