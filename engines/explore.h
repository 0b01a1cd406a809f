// Exhaustive exploration of the reachable states of an untimed model (`--explore`).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <unordered_set>

#include "engines/semantics/runtime.h"

namespace smcbip::engines {

struct ExplorationCounts {
  std::uint64_t states = 0, deadlocks = 0, timelocks = 0, errors = 0, error_states = 0;
  bool cut = false;  // states were left unexplored at the bound on their number
};

/// Breadth-first search from the initialised state: every enabled item of every reachable state
/// is executed once. A state is the marking and data of all atoms (time is ignored). Errors of
/// executing an item are counted, not reported one by one. With `max_steps`, only the states
/// reachable in at most that many steps (an unbounded state space then ends). At most
/// `max_states` states are kept (memory grows with them): beyond, the search explores those
/// found and sets `cut`.
ExplorationCounts explore_states(
    Runtime& runtime, std::optional<std::uint64_t> max_steps = std::nullopt,
    std::uint64_t max_states = std::numeric_limits<std::uint64_t>::max());

/// The part of a run state that identifies it in an exploration: markings, data and pending
/// resumes, as raw bytes (time is ignored).
std::string state_key(const RunState& state);

/// The keys of the states reachable from the runtime's current state in at most `max_steps`
/// steps, found breadth first as explore_states finds them (executions that fail add nothing).
/// Lets tests check that another scheduler only visits reachable states, also on models whose
/// state space is too large to enumerate whole.
std::unordered_set<std::string> reachable_state_keys(Runtime& runtime, std::uint64_t max_steps);

/// The reference engine's summary line (and, when the search was cut, a line saying so).
void write_exploration(std::ostream& out, const ExplorationCounts& counts);

}  // namespace smcbip::engines
