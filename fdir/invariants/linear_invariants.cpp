// The state equation of the net and a basis of its place invariants, for Z3.
#include "fdir/invariants/linear_invariants.h"

#include <algorithm>
#include <boost/multiprecision/cpp_int.hpp>
#include <map>
#include <set>
#include <stdexcept>

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

/// Row entries the elimination (and the back substitution) may update before giving up: the
/// nets of communicating state machines need a few per transition, a dense net far more.
constexpr std::size_t kEliminationWork = 20'000'000;

using Rational = boost::multiprecision::cpp_rational;
using Row = std::map<Index, Rational>;  // place -> coefficient

void add_to(Row& row, Index place, const Rational& value) {
  auto [it, fresh] = row.try_emplace(place, value);
  if (fresh) return;
  it->second += value;
  if (it->second == 0) row.erase(it);
}

/// Gaussian elimination of y.C = 0, one row per net transition over the kept places: each row
/// in turn gets a pivot, eliminated from the rows not yet pivoted. The pivots' rows are kept
/// (in pivot order) for the back substitution.
class Elimination {
 public:
  Elimination(std::size_t places, std::vector<Row> rows) : rows_(std::move(rows)), occ_(places) {
    for (Index r = 0; r < rows_.size(); ++r) {
      for (const auto& entry : rows_[r]) occ_[entry.first].insert(r);
    }
    pivot_.assign(places, 0);
    for (Index r = 0; r < rows_.size() && !gave_up(); ++r) eliminate(r);
  }

  bool is_pivot(Index place) const { return pivot_[place] != 0; }
  /// The fill-in exceeded kEliminationWork: no basis (the place invariants are optional).
  bool gave_up() const { return work_ > kEliminationWork; }

  /// Per pivot place, its value in terms of the free places (the others are 0).
  std::vector<Row> back_substitute() const {
    std::vector<Row> expr(pivot_.size());
    std::size_t work = 0;
    for (std::size_t k = pivots_.size(); k-- > 0 && work <= kEliminationWork;) {
      const auto [q, r] = pivots_[k];
      const Rational cq = rows_[r].at(q);
      Row e;
      for (const auto& [v, c] : rows_[r]) {
        if (v == q) continue;
        const Rational f = -c / cq;
        if (!pivot_[v]) {
          add_to(e, v, f);
        } else {
          for (const auto& [w, d] : expr[v]) add_to(e, w, f * d);
        }
      }
      work += e.size();
      expr[q] = std::move(e);
    }
    if (work > kEliminationWork) return {};
    return expr;
  }

  const std::vector<std::pair<Index, Index>>& pivots() const { return pivots_; }

 private:
  void eliminate(Index r) {
    const Row& row = rows_[r];
    for (const auto& entry : row) occ_[entry.first].erase(r);
    if (row.empty()) return;  // a combination of the rows before: no new constraint
    // The place in fewest other rows, preferring a unit coefficient: the least fill-in.
    Index q = row.begin()->first;
    for (const auto& [p, c] : row) {
      const auto key = [&](Index v, const Rational& cv) {
        return std::pair(occ_[v].size(), abs(cv) == 1 ? 0 : 1);
      };
      if (key(p, c) < key(q, row.at(q))) q = p;
    }
    pivot_[q] = 1;
    pivots_.emplace_back(q, r);
    const Rational cq = row.at(q);
    const std::vector<Index> others(occ_[q].begin(), occ_[q].end());
    work_ += others.size() * row.size();
    for (Index r2 : others) {
      Row& target = rows_[r2];
      const Rational factor = target.at(q) / cq;
      for (const auto& [p, c] : row) {
        auto it = target.find(p);
        if (it == target.end()) {
          target.emplace(p, -factor * c);
          occ_[p].insert(r2);
        } else if ((it->second -= factor * c) == 0) {
          target.erase(it);
          occ_[p].erase(r2);
        }
      }
    }
  }

  std::vector<Row> rows_;
  std::vector<std::set<Index>> occ_;  // per place, the rows not yet pivoted containing it
  std::vector<std::uint8_t> pivot_;
  std::vector<std::pair<Index, Index>> pivots_;  // (place, row) in pivot order
  std::size_t work_ = 0;                         // row entries updated
};

/// `y` scaled to coprime integers; nullopt when a weight does not fit comfortably in 64 bits.
std::optional<std::vector<std::pair<Index, std::int64_t>>> integral(const Row& y) {
  using boost::multiprecision::cpp_int;
  cpp_int scale = 1;
  for (const auto& entry : y) {
    const cpp_int d = denominator(entry.second);
    scale = scale / gcd(scale, d) * d;
  }
  cpp_int common = 0;
  for (const auto& entry : y)
    common = gcd(common, numerator(entry.second) * (scale / denominator(entry.second)));
  std::vector<std::pair<Index, std::int64_t>> out;
  const cpp_int limit = cpp_int(1) << 24;  // pseudo-Boolean weights are int
  for (const auto& [p, v] : y) {
    const cpp_int w = numerator(v) * (scale / denominator(v)) / common;
    if (abs(w) > limit) return std::nullopt;
    out.emplace_back(p, static_cast<std::int64_t>(w));
  }
  return out;
}

/// y.C = 0 on every transition: a failed check is a bug of the elimination, which must not
/// become an unsound invariant.
void check_invariant(const PlaceInvariant& y,
                     const std::vector<std::vector<std::pair<Index, int>>>& columns,
                     const std::vector<std::vector<Index>>& touching,
                     std::vector<std::int64_t>& weight) {
  for (const auto& [p, w] : y.weights) weight[p] = w;
  for (const auto& [p, w] : y.weights) {
    for (Index t : touching[p]) {
      std::int64_t sum = 0;  // weights below 2^24, small arc counts
      for (const auto& [q, c] : columns[t]) sum += weight[q] * c;
      if (sum != 0) throw std::logic_error("a computed place invariant is not one");
    }
  }
  for (const auto& [p, w] : y.weights) weight[p] = 0;
}

}  // namespace

std::vector<PlaceInvariant> place_invariants(const bipc::ir::System& system, const PetriNet& net,
                                             const std::vector<std::uint8_t>& kept) {
  const std::size_t places = net.places.size();
  std::vector<std::vector<std::pair<Index, int>>> columns;  // per transition, kept places only
  std::vector<std::vector<Index>> touching(places);
  std::vector<Row> rows;
  for (Index t = 0; t < net.transitions.size(); ++t) {
    auto& column = columns.emplace_back();
    Row row;
    for (const auto& [p, c] : incidence(system, net, t)) {
      if (!kept[p]) continue;
      column.emplace_back(p, c);
      touching[p].push_back(t);
      row.emplace(p, c);
    }
    if (!row.empty()) rows.push_back(std::move(row));
  }
  const Elimination elimination(places, std::move(rows));
  if (elimination.gave_up()) return {};
  // One basis vector per free place f: y_f = 1, the other free places 0.
  std::vector<Row> basis(places);
  for (Index p = 0; p < places; ++p) {
    if (kept[p] && !elimination.is_pivot(p)) basis[p].emplace(p, 1);
  }
  const std::vector<Row> expr = elimination.back_substitute();
  if (expr.empty()) return {};
  for (const auto& pivot : elimination.pivots()) {
    for (const auto& [f, a] : expr[pivot.first]) basis[f].emplace(pivot.first, a);
  }
  std::vector<PlaceInvariant> out;
  std::vector<std::int64_t> weight(places, 0);
  for (const Row& y : basis) {
    if (y.empty()) continue;
    auto weights = integral(y);
    if (!weights) continue;
    PlaceInvariant invariant{std::move(*weights), 0};
    for (const auto& [p, w] : invariant.weights) invariant.constant += net.initial[p] ? w : 0;
    check_invariant(invariant, columns, touching, weight);
    out.push_back(std::move(invariant));
  }
  return out;
}

StateEquation::StateEquation(const StateEncoding& state)
    : state_(state), equation_(state.context()), invariant_clauses_(state.context()) {
  z3::context& c = state.context();
  const PetriNet& net = state.net();
  const std::vector<std::uint8_t> twice = moved_twice(state.system(), net);
  const std::vector<Index> atom_of = place_atoms(net);
  std::vector<std::uint8_t> kept(net.places.size());
  for (Index p = 0; p < net.places.size(); ++p) kept[p] = twice[atom_of[p]] ? 0 : 1;
  // Per place, the firing terms changing its token count.
  std::vector<z3::expr_vector> terms;
  terms.reserve(net.places.size());
  for (std::size_t p = 0; p < net.places.size(); ++p) terms.emplace_back(c);
  for (Index t = 0; t < net.transitions.size(); ++t) {
    firings_.push_back(c.int_const(("#" + std::to_string(t)).c_str()));
    equation_.push_back(firings_.back() >= 0);
    for (const auto& [p, change] : incidence(state.system(), net, t)) {
      terms[p].push_back(change == 1 ? firings_.back() : change * firings_.back());
    }
  }
  const z3::expr one = c.int_val(1), zero = c.int_val(0);
  for (Index p = 0; p < net.places.size(); ++p) {
    if (!kept[p]) continue;
    terms[p].push_back(c.int_val(net.initial[p] ? 1 : 0));
    equation_.push_back(z3::ite(state.place(p), one, zero) == z3::sum(terms[p]));
    ++places_;
  }
  // A state machine's places sum to 1 (the component invariants say so), which spans, with
  // the invariants giving its initial place weight 0, every invariant. Those are what the
  // proofs use (a pump's token counts its customers), and elimination over the other places
  // finds them, where the full basis mixes them with the exactly-one constraints into long
  // vectors Z3 hardly propagates from.
  std::vector<std::uint8_t> unknowns = kept;
  for (Index a = 0; a < net.first_place.size(); ++a) {
    const bipc::ir::AtomType& type = state.system().atom_types[state.system().atoms[a].type];
    if (bipc::ir::is_state_machine(type)) {
      unknowns[net.first_place[a] + type.initial_places.front()] = 0;
    }
  }
  invariants_ = fdir::place_invariants(state.system(), net, unknowns);
  // Pseudo-Boolean constraints over the places: Z3 propagates them directly, while it reaches
  // the same facts through the firing counts only by search.
  for (const PlaceInvariant& y : invariants_) {
    z3::expr_vector places(c);
    std::vector<int> weights;
    for (const auto& [p, w] : y.weights) {
      places.push_back(state.place(p));
      weights.push_back(static_cast<int>(w));
    }
    invariant_clauses_.push_back(z3::pbeq(places, weights.data(), static_cast<int>(y.constant)));
  }
}

bool StateEquation::admits(const std::vector<std::uint8_t>& marking) const {
  if (!admits_) {
    admits_.emplace(state_.context());
    for (const z3::expr& clause : equation_) admits_->add(clause);
  }
  z3::expr_vector fixed(state_.context());
  for (Index p = 0; p < marking.size(); ++p) {
    fixed.push_back(marking[p] ? state_.place(p) : !state_.place(p));
  }
  // unknown (Z3 gave up) admits the marking: the equation excludes only what it proves absent.
  return admits_->check(fixed) != z3::unsat;
}

}  // namespace smcbip::fdir
