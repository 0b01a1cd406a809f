// The proof loop: CI && II && bad to Z3; each satisfying state refined by a trap or handed to
// the search.
#include "fdir/prove/prover.h"

#include <algorithm>
#include <chrono>

#include "engines/semantics/layout.h"
#include "fdir/errors.h"
#include "fdir/invariants/component_invariants.h"
#include "fdir/invariants/linear_invariants.h"
#include "fdir/invariants/trap_invariants.h"
#include "fdir/net/petri_net.h"
#include "fdir/prove/deadlock_predicate.h"
#include "fdir/prove/property_encoding.h"
#include "fdir/smt/state_encoding.h"

namespace smcbip::fdir {

namespace {

using Clock = std::chrono::steady_clock;

/// Traps added against one candidate (each excludes it; several make fewer rounds).
constexpr std::size_t kTrapsPerCandidate = 4096;

/// States the breadth-first search keeps before the search heads for the candidate instead,
/// at most; fewer on large models, where expanding a state costs as many engine steps as there
/// are interactions: the breadth-first budget is then kBreadthWork interactions.
constexpr std::uint64_t kBreadthStates = 20'000;
constexpr std::uint64_t kBreadthWork = 200'000;

std::uint64_t breadth_states(const PetriNet& net) {
  const std::uint64_t interactions = std::max<std::uint64_t>(1, net.interactions.size());
  return std::clamp<std::uint64_t>(kBreadthWork / interactions, 10, kBreadthStates);
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

struct Prover::State {
  State(const bipc::ir::System& system, unsigned iterations)
      : net(build_petri_net(system)),
        variables(context, system, net),
        encoder(context),
        components(variables, encoder, iterations),
        invariant(context) {}
  z3::context context;
  PetriNet net;
  StateEncoding variables;
  CodeEncoder encoder;
  ComponentInvariants components;
  /// CI and the traps found so far, as a list: a conjunction built clause by clause nests
  /// as deep as it is long, which Z3 is slow to free.
  z3::expr_vector invariant;
  std::optional<z3::expr> deadlock;     // DIS, once a query reads it
  std::optional<StateEquation> linear;  // with Method::Linear and Method::Both
  std::size_t traps = 0;
  bool untimed = true;
  std::vector<AssumptionSite> assumptions;  // in the invariant
};

Prover::Prover(const bipc::ir::System& system, const ProveOptions& options)
    : system_(system), options_(options) {
  state_ = std::make_unique<State>(system, options.component_iterations);
  for (Index a = 0; a < system.atoms.size(); ++a) {
    state_->invariant.push_back(state_->components.of_atom(a));
    for (const z3::expr& d : state_->variables.data(a)) {
      state_->invariant.push_back(int64_bounds(d));
    }
  }
  if (options.method != Method::Traps) {
    state_->linear.emplace(state_->variables);
    for (const z3::expr& clause : state_->linear->invariant_clauses()) {
      state_->invariant.push_back(clause);
    }
  }
  engines::Layout layout;
  engines::build_layout(system, layout);
  state_->untimed = layout.clock_count == 0;
}

Prover::~Prover() = default;

void Prover::assume(const std::vector<AssumptionSource>& sources) {
  State& s = *state_;
  std::vector<Assumption> all;
  for (const AssumptionSource& source : sources) {
    for (Assumption& a : parse_assumptions(source, s.variables)) all.push_back(std::move(a));
  }
  check_inductive(all, s.variables, s.encoder, s.invariant, s.traps);
  for (const Assumption& a : all) {
    s.invariant.push_back(a.formula);
    s.assumptions.push_back(a.site);
  }
}

std::optional<Prover::Candidate> Prover::refute(const z3::expr& bad, QueryOutcome& out) {
  State& s = *state_;
  z3::solver solver(s.context);
  for (const z3::expr& clause : s.invariant) solver.add(clause);
  solver.add(bad);
  bool equation = false;  // the state equation is in the solver
  for (std::size_t added = 0;;) {
    const z3::check_result r = solver.check();
    if (r == z3::unsat) return std::nullopt;
    if (r == z3::unknown) {
      out.note = "Z3 gave up: " + solver.reason_unknown();
      return Candidate{};
    }
    const z3::model model = solver.get_model();
    std::vector<std::uint8_t> marking(s.net.places.size());
    std::vector<std::string> candidate;
    for (Index p = 0; p < marking.size(); ++p) {
      marking[p] = model.eval(s.variables.place(p), true).is_true() ? 1 : 0;
      if (marking[p]) candidate.push_back(s.net.places[p]);
    }
    // The place invariants did not exclude the candidate; the state equation, slower to
    // refute, joins only when it excludes the candidate.
    if (s.linear && !equation && !s.linear->admits(marking)) {
      for (const z3::expr& clause : s.linear->equation()) solver.add(clause);
      equation = true;
      out.state_equation = true;
      continue;
    }
    // With the linear invariants alone (Method::Linear), a candidate is final.
    const std::vector<std::vector<Index>> traps =
        options_.method == Method::Linear ? std::vector<std::vector<Index>>{}
                                          : excluding_traps(s.net, marking, kTrapsPerCandidate);
    if (traps.empty() || added >= options_.max_traps) {
      for (Index a = 0; a < system_.atoms.size(); ++a) {
        for (const z3::expr& d : s.variables.data(a)) {
          if (!d.is_int() && !d.is_bool()) continue;
          candidate.push_back(d.decl().name().str() + " = " + model.eval(d, true).to_string());
        }
      }
      if (!traps.empty()) out.note = "the limit on traps was reached";
      return Candidate{marking, candidate};
    }
    for (const std::vector<Index>& trap : traps) {
      z3::expr_vector places(s.context);
      for (Index p : trap) places.push_back(s.variables.place(p));
      const z3::expr clause = z3::mk_or(places);
      solver.add(clause);
      s.invariant.push_back(clause);
      ++added;
      ++s.traps;
    }
  }
}

void Prover::search(const monitors::Query& query, const monitors::Bindings& constants,
                    const Candidate& candidate, QueryOutcome& out) {
  const bool all = query.kind == monitors::Query::Kind::Invariant;
  const monitors::Formula& phi = *query.formula;
  const StateTarget target = [&](const engines::Runtime& runtime,
                                 const engines::StringPool& strings, bool deadlocked) {
    return holds_in(phi, runtime, strings, constants, deadlocked) != all;
  };
  SearchLimits limits{
      options_.explore_depth,
      std::min<std::uint64_t>(options_.max_explored_states, breadth_states(state_->net)),
      {}};
  SearchResult found = search_state(system_, target, limits);
  out.explored_states = found.states;
  if (!found.found && !found.complete && !candidate.marking.empty()) {
    // Breadth first was cut short: head for the candidate, counting the places it differs in.
    const PetriNet& net = state_->net;
    limits.max_states = options_.max_explored_states;
    limits.guide = [&](const engines::RunState& state, const engines::Layout& layout) {
      std::size_t distance = 0;
      for (Index a = 0; a < net.first_place.size(); ++a) {
        const Index end = a + 1 < net.first_place.size() ? net.first_place[a + 1]
                                                         : static_cast<Index>(net.places.size());
        for (Index p = net.first_place[a]; p < end; ++p) {
          const bool marked = state.marking[layout.atom_places[a] + (p - net.first_place[a])];
          distance += marked != (candidate.marking[p] != 0) ? 1 : 0;
        }
      }
      return distance;
    };
    found = search_state(system_, target, limits);
    out.explored_states += found.states;
  }
  if (found.found) {
    out.verdict = all ? Verdict::Fails : Verdict::Holds;
    out.method = "trace";
    out.trace = found.trace;
  } else if (found.complete) {
    out.verdict = all ? Verdict::Holds : Verdict::Fails;
    out.method = "exploration";
  } else {
    out.note += std::string(out.note.empty() ? "" : "; ") +
                "the candidate was not reached within " + std::to_string(options_.explore_depth) +
                " steps (" + std::to_string(out.explored_states) +
                " states explored): it may be spurious; stronger invariants or a deeper "
                "--explore-depth may decide";
  }
}

QueryOutcome Prover::prove(const monitors::Query& query, const monitors::Bindings& constants) {
  State& s = *state_;
  QueryOutcome out;
  out.net_transitions = s.net.transitions.size();
  out.component_invariants = s.components.data_invariants();
  out.linear = s.linear.has_value();
  out.place_invariants = s.linear ? s.linear->place_invariants().size() : 0;
  auto start = Clock::now();
  if (!s.deadlock) s.deadlock = deadlock_predicate(s.variables, s.encoder);
  const z3::expr phi = encode_formula(*query.formula, s.variables, constants, *s.deadlock);
  const bool all = query.kind == monitors::Query::Kind::Invariant;
  const z3::expr bad = all ? !phi : phi;
  out.seconds_invariants = seconds_since(start);
  start = Clock::now();
  const std::optional<Candidate> candidate = refute(bad, out);
  out.seconds_smt = seconds_since(start);
  out.traps = s.traps;
  if (!candidate) {
    out.verdict = all ? Verdict::Holds : Verdict::Fails;
    out.method = "invariants";
    out.assumptions = s.assumptions;
    return out;
  }
  out.candidate = candidate->text;
  if (!s.untimed) {
    out.note =
        "the model has clocks: its invariants ignore them (sound) but the search for a "
        "violating state, which would ignore time, is not made";
    return out;
  }
  start = Clock::now();
  search(query, constants, *candidate, out);
  out.seconds_search = seconds_since(start);
  return out;
}

}  // namespace smcbip::fdir
