// Answering `A[] phi` and `E<> phi` queries: the invariants of the system and the negated
// query to Z3, refined by traps against each candidate, and a candidate that survives searched
// for among the reachable states (D-Finder's method: Bensalem, Bozga, Nguyen, Sifakis, CAV 2009;
// Bensalem, Bozga, Sifakis, Nguyen, "Compositional verification for component-based systems",
// ATVA 2008).
#pragma once

#include <z3++.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "fdir/prove/assumptions.h"
#include "fdir/search/counterexample_search.h"
#include "monitors/online/online_monitor.h"
#include "monitors/property/ast.h"

namespace smcbip::fdir {

/// Which interaction invariants join the component invariants: the traps of the net, its
/// state equation (linear invariants), or both.
enum class Method : std::uint8_t { Traps, Linear, Both };

/// What the prover may spend, and with which invariants.
struct ProveOptions {
  Method method = Method::Both;
  /// Rounds of the post-condition iteration per atom type (each round's result is sound).
  unsigned component_iterations = 3;
  /// The search for a violating state stops at this many steps from the initial state...
  std::uint64_t explore_depth = 1000;
  /// ... and keeps at most this many states.
  std::uint64_t max_explored_states = 200'000;
  /// Traps added against candidates before a query is left open.
  std::size_t max_traps = 1'000'000;
};

enum class Verdict : std::uint8_t { Holds, Fails, Open };

/// The answer to one query, with what it rests on.
struct QueryOutcome {
  Verdict verdict = Verdict::Open;
  /// How the verdict was reached: `invariants` (Z3 found no state of the invariants violating
  /// the query), `trace` (a reachable state violating it, or the witness of E<>), `exploration`
  /// (every reachable state was examined), `none` (open).
  std::string method = "none";
  std::size_t traps = 0;  // trap invariants known when the query was decided (shared by queries)
  bool linear = false;    // the linear invariants were part of the invariants
  std::size_t place_invariants = 0;      // with linear: the place invariants stated
  bool state_equation = false;           // with linear: the state equation joined this query
  std::size_t component_invariants = 0;  // atoms with a data invariant
  std::size_t net_transitions = 0;
  /// The last candidate state Z3 gave (marked places and data), when the invariants did not
  /// exclude every state violating the query.
  std::vector<std::string> candidate;
  std::vector<TraceState> trace;  // counterexample (A[]) or witness (E<>)
  std::uint64_t explored_states = 0;
  std::string note;  // why a query is open, or what was dropped from the model
  /// The assumptions (checked inductive) a verdict by invariants rests on; empty otherwise.
  std::vector<AssumptionSite> assumptions;
  double seconds_invariants = 0, seconds_smt = 0, seconds_search = 0;
};

/// Proves queries over one system; invariants (component invariants, traps found so far) are
/// computed once and shared by the queries.
class Prover {
 public:
  /// Throws UnsupportedModel for models the Petri net abstraction does not cover.
  Prover(const bipc::ir::System& system, const ProveOptions& options);
  ~Prover();
  Prover(const Prover&) = delete;
  Prover& operator=(const Prover&) = delete;

  /// Answers `A[] phi` or `E<> phi` (names resolved against the system; constants bound in
  /// `constants`). E<> phi holds when A[] !phi does not. Throws UnsupportedModel for a
  /// predicate the encoding does not cover.
  QueryOutcome prove(const monitors::Query& query, const monitors::Bindings& constants);

  /// Adds the assertions of `sources` to the invariants of every later query, once shown to
  /// hold initially and to be inductive (together) relative to the invariants; throws
  /// AssumptionError, using none of them, when they are not.
  void assume(const std::vector<AssumptionSource>& sources);

 private:
  struct State;
  /// A state of the invariants violating the query: its marking (per place of the net, empty
  /// when Z3 gave up) and its text.
  struct Candidate {
    std::vector<std::uint8_t> marking;
    std::vector<std::string> text;
  };
  /// The SMT loop against `bad`: nullopt when no state of the invariants is bad (proved),
  /// otherwise the candidate.
  std::optional<Candidate> refute(const z3::expr& bad, QueryOutcome& outcome);
  /// Breadth first, then (when cut short) best first towards the candidate's marking.
  void search(const monitors::Query& query, const monitors::Bindings& constants,
              const Candidate& candidate, QueryOutcome& outcome);

  const bipc::ir::System& system_;
  ProveOptions options_;
  std::unique_ptr<State> state_;
};

}  // namespace smcbip::fdir
