// Linear invariants of the Petri net: the state equation M = M0 + C.x (x >= 0 integer, the
// number of firings of each net transition), which every reachable marking satisfies (Esparza,
// Melzer, "Verification of safety properties using integer programming: beyond the state
// equation", FMSD 2000; Silva, Teruel, Colom, "Linear algebraic and linear programming
// techniques for the analysis of place/transition net systems", 1998).
#pragma once

#include <z3++.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "fdir/smt/state_encoding.h"

namespace smcbip::fdir {

/// A place invariant (P-invariant): sum_p weight_p * M(p) = constant in every marking M the
/// state equation allows, because y.C = 0 for the weights y.
struct PlaceInvariant {
  std::vector<std::pair<Index, std::int64_t>> weights;  // (global place, nonzero weight)
  std::int64_t constant = 0;                            // y.M0
};

/// A basis of the place invariants with weight 0 outside the places `kept` (per global place,
/// nonzero when kept): the rational left null space of the incidence matrix restricted to them,
/// computed by sparse Gaussian elimination (one equation per net transition, a pivot of fewest
/// occurrences first, which keeps the rows of nets of communicating state machines short), each
/// vector scaled to coprime integers and checked against the incidence before it is returned.
/// Vectors with a weight beyond 2^24 are left out (the basis is then partial, which is still
/// sound).
std::vector<PlaceInvariant> place_invariants(const bipc::ir::System& system, const PetriNet& net,
                                             const std::vector<std::uint8_t>& kept);

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

  /// The place invariants giving the initial place of each state machine atom weight 0, as
  /// pseudo-Boolean equalities over the places. With the state machines' exactly-one
  /// constraints (component invariants), they span every place invariant: the state equation
  /// with firing counts of any sign (rational), which Z3 decides fast.
  const z3::expr_vector& invariant_clauses() const { return invariant_clauses_; }
  /// The equation itself: x_t >= 0 integer per net transition and, per place kept,
  /// [p] = M0(p) + sum_t C(p, t) x_t. Stronger than the place invariants (no firing count is
  /// negative or fractional), slower for Z3 to refute.
  const z3::expr_vector& equation() const { return equation_; }
  /// Whether the equation has a solution with the places marked as `marking` (per place).
  bool admits(const std::vector<std::uint8_t>& marking) const;
  /// The firing count variable of net transition `t`.
  const z3::expr& firings(Index t) const { return firings_[t]; }
  /// How many places have an equation.
  std::size_t places() const { return places_; }
  /// The place invariants of invariant_clauses().
  const std::vector<PlaceInvariant>& place_invariants() const { return invariants_; }

 private:
  const StateEncoding& state_;
  z3::expr_vector equation_, invariant_clauses_;
  std::vector<z3::expr> firings_;
  std::size_t places_ = 0;
  std::vector<PlaceInvariant> invariants_;
  mutable std::optional<z3::solver> admits_;  // the equation, checked under assumptions
};

/// The incidence of net transition `t` on each place (tokens put minus tokens taken, one per
/// atom transition and place), as (place, change) pairs without zero changes, in place order.
std::vector<std::pair<Index, int>> incidence(const bipc::ir::System& system, const PetriNet& net,
                                             Index t);

}  // namespace smcbip::fdir
