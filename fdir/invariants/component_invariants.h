// Component invariants of atoms: for an atom whose net is a state machine, exactly one place is
// marked, and at each place its data satisfy a formula computed by forward post-condition
// iteration from `true` (Bensalem, Bozga, Nguyen, Sifakis, "D-Finder", CAV 2009, section 3.1).
#pragma once

#include <z3++.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "fdir/smt/code_encoding.h"
#include "fdir/smt/state_encoding.h"

namespace smcbip::fdir {

/// Existentially quantifies `vars` in `body` and eliminates them with Z3's `qe` tactic; `true`
/// (a sound weakening) when Z3 cannot eliminate them.
z3::expr eliminate(z3::context& context, const z3::expr_vector& vars, const z3::expr& body);

/// The component invariants of a system's atoms. The iteration is the greatest-fixpoint one:
/// phi_l^0 = true at every place l, and phi_l^(k+1) = init_l || OR over the transitions t from
/// l' to l of post_t(phi_l'^k). Each iterate contains the reachable data at l (the reachable
/// set is below the greatest fixpoint), so stopping after any number of iterations is sound.
/// A transition's post-condition havocs the data a connector's `down` may write through its
/// port before the action (data transfer is not followed), and reads clocks and floats as unknown.
class ComponentInvariants {
 public:
  ComponentInvariants(const StateEncoding& state, CodeEncoder& encoder, unsigned iterations);

  /// The invariant of one atom instance over the state's variables (computed once per atom
  /// type and parameter values).
  z3::expr of_atom(Index atom);
  /// The conjunction over all atoms.
  z3::expr all();
  /// How many atom instances got a data invariant other than `true`.
  std::size_t data_invariants() const { return data_invariants_; }

 private:
  struct Template;
  Template compute(Index atom);
  std::vector<z3::expr> iterate(const Template& t, Index atom, const std::vector<z3::expr>& init);
  z3::expr post(const Template& t, Index atom, const bipc::ir::Transition& tr,
                const z3::expr& before);
  std::vector<z3::expr> initial_data(const Template& t, Index atom);

  const StateEncoding& state_;
  CodeEncoder& encoder_;
  unsigned iterations_;
  /// Per atom and port: some connector's `down` writes the port's data.
  std::vector<std::vector<std::uint8_t>> written_;
  std::map<std::string, z3::expr> cache_;  // by type and parameters, over template variables
  std::size_t data_invariants_ = 0;
};

/// Exactly one of `places` holds.
z3::expr exactly_one(z3::context& context, const std::vector<z3::expr>& places);

}  // namespace smcbip::fdir
