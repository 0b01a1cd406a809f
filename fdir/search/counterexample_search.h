// Confirming a failed proof: breadth-first search of the engines' reachable states for one
// violating the property, with the trace that reaches it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/semantics/runtime.h"

namespace smcbip::fdir {

/// One state of a trace: what was fired to reach it (empty for the initial state), its marked
/// places and its data (`ROOT.atom.name` and the value as the engines print it).
struct TraceState {
  std::string fired;
  std::vector<std::string> places;
  std::vector<std::pair<std::string, std::string>> data;
};

struct SearchResult {
  bool found = false;
  std::vector<TraceState> trace;  // the initial state first, when found
  std::uint64_t states = 0;       // states examined
  /// Every reachable state was examined (no depth or state bound cut the search, and no step
  /// failed): when nothing was found, no reachable state is a target.
  bool complete = false;
  std::uint64_t errors = 0;  // executions that failed with a model error
};

/// Whether the runtime's current state is one searched for (`deadlocked`: nothing is enabled).
using StateTarget = std::function<bool(const engines::Runtime& runtime,
                                       const engines::StringPool& strings, bool deadlocked)>;

/// How far a search goes, and where it heads.
struct SearchLimits {
  std::uint64_t max_depth = 1000;     // steps from the initial state
  std::uint64_t max_states = 200000;  // states kept
  /// Without a guide the search is breadth first (the shortest trace); with one, the state of
  /// least guide value is expanded first (shallowest among equals): a best-first search towards
  /// a goal such as the prover's candidate.
  std::function<std::size_t(const engines::RunState& state, const engines::Layout& layout)> guide;
};

/// Searches from the initial state, with the engines' semantics as their exploration
/// (explore.h) follows it, for a state that is a target. Throws UnsupportedModel when the model
/// cannot be run (e.g. its initialisation fails).
SearchResult search_state(const bipc::ir::System& system, const StateTarget& target,
                          const SearchLimits& limits);

}  // namespace smcbip::fdir
