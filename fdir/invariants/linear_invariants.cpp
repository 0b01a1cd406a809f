// The state equation of the net as linear integer arithmetic for Z3.
#include "fdir/invariants/linear_invariants.h"

#include <algorithm>
#include <map>

namespace smcbip::fdir {

std::vector<std::pair<Index, int>> incidence(const bipc::ir::System& system, const PetriNet& net,
                                             Index t) {
  std::map<Index, int> change;
  for (const AtomMove& move : net.transitions[t].moves) {
    const auto& tr = system.atom_types[system.atoms[move.atom].type].transitions[move.transition];
    for (Index p : tr.from) --change[net.first_place[move.atom] + p];
    for (Index p : tr.to) ++change[net.first_place[move.atom] + p];
  }
  std::vector<std::pair<Index, int>> out;
  for (const auto& [place, c] : change) {
    if (c != 0) out.emplace_back(place, c);
  }
  return out;
}

namespace {

/// Per atom: nonzero when some net transition moves it twice.
std::vector<std::uint8_t> moved_twice(const bipc::ir::System& system, const PetriNet& net) {
  std::vector<std::uint8_t> twice(system.atoms.size(), 0);
  std::vector<Index> atoms;
  for (const NetTransition& t : net.transitions) {
    atoms.clear();
    for (const AtomMove& m : t.moves) atoms.push_back(m.atom);
    std::sort(atoms.begin(), atoms.end());
    for (std::size_t k = 1; k < atoms.size(); ++k) {
      if (atoms[k] == atoms[k - 1]) twice[atoms[k]] = 1;
    }
  }
  return twice;
}

/// Per global place: its atom.
std::vector<Index> place_atoms(const PetriNet& net) {
  std::vector<Index> atom(net.places.size(), 0);
  for (Index a = 0; a < net.first_place.size(); ++a) {
    const Index end = a + 1 < net.first_place.size() ? net.first_place[a + 1]
                                                     : static_cast<Index>(net.places.size());
    for (Index p = net.first_place[a]; p < end; ++p) atom[p] = a;
  }
  return atom;
}

}  // namespace

StateEquation::StateEquation(const StateEncoding& state) : clauses_(state.context()) {
  z3::context& c = state.context();
  const PetriNet& net = state.net();
  const std::vector<std::uint8_t> twice = moved_twice(state.system(), net);
  const std::vector<Index> atom_of = place_atoms(net);
  // Per place, the firing terms changing its token count.
  std::vector<z3::expr_vector> terms;
  terms.reserve(net.places.size());
  for (std::size_t p = 0; p < net.places.size(); ++p) terms.emplace_back(c);
  for (Index t = 0; t < net.transitions.size(); ++t) {
    firings_.push_back(c.int_const(("#" + std::to_string(t)).c_str()));
    clauses_.push_back(firings_.back() >= 0);
    for (const auto& [p, change] : incidence(state.system(), net, t)) {
      terms[p].push_back(change == 1 ? firings_.back() : change * firings_.back());
    }
  }
  const z3::expr one = c.int_val(1), zero = c.int_val(0);
  for (Index p = 0; p < net.places.size(); ++p) {
    if (twice[atom_of[p]]) continue;
    terms[p].push_back(c.int_val(net.initial[p] ? 1 : 0));
    clauses_.push_back(z3::ite(state.place(p), one, zero) == z3::sum(terms[p]));
    ++places_;
  }
}

}  // namespace smcbip::fdir
