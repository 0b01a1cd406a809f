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

/// Breadth-first search from the initial state, as the engines' exploration (explore.h)
/// visits states, for the first state that is a target: the shortest trace to one. Explores at
/// most `max_depth` steps and keeps at most `max_states` states. Throws UnsupportedModel when
/// the model cannot be run (e.g. its initialisation fails).
SearchResult search_state(const bipc::ir::System& system, const StateTarget& target,
                          std::uint64_t max_depth, std::uint64_t max_states);

}  // namespace smcbip::fdir
