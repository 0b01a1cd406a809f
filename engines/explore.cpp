// Breadth-first enumeration of reachable states.
#include "engines/explore.h"

#include <boost/container_hash/hash.hpp>
#include <deque>
#include <unordered_set>

#include "engines/trace/text_trace.h"

namespace smcbip::engines {

namespace {

/// The part of a run state that identifies it: markings and data, as raw bytes.
std::string state_key(const RunState& state) {
  std::string key(reinterpret_cast<const char*>(state.marking.data()), state.marking.size());
  key.append(reinterpret_cast<const char*>(state.data.data()), state.data.size() * sizeof(Val));
  key.append(reinterpret_cast<const char*>(state.resume_pending.data()),
             state.resume_pending.size());
  return key;
}

std::string plural(std::uint64_t n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

}  // namespace

ExplorationCounts explore_states(Runtime& runtime) {
  ExplorationCounts counts;
  std::unordered_set<std::string> seen;
  std::deque<RunState> frontier;
  seen.insert(state_key(runtime.state()));
  frontier.push_back(runtime.state());
  while (!frontier.empty()) {
    const RunState state = std::move(frontier.front());
    frontier.pop_front();
    ++counts.states;
    if (!runtime.restore(state) || !runtime.compute_items()) {
      ++counts.errors;
      ++counts.error_states;
      continue;
    }
    const std::vector<Item> items = runtime.items();
    if (items.empty()) {
      if (runtime.wait_interval().right == kPlusInfinity) {
        ++counts.deadlocks;
      } else {
        ++counts.timelocks;
      }
      continue;
    }
    bool failed = false;
    for (const Item& item : items) {
      if (!runtime.restore(state) || !runtime.compute_items() ||
          !runtime.execute(item, state.now) || !runtime.resume_atoms(state.now)) {
        ++counts.errors;
        failed = true;
        continue;
      }
      RunState next = runtime.state();
      next.now = state.now;
      if (seen.insert(state_key(next)).second) frontier.push_back(std::move(next));
    }
    if (failed) ++counts.error_states;
  }
  return counts;
}

void write_exploration(std::ostream& out, const ExplorationCounts& counts) {
  out << kEnginePrefix << "computing reachable states:... found "
      << plural(counts.states, "reachable state") << ", " << plural(counts.deadlocks, "deadlock")
      << ", " << plural(counts.timelocks, "timelock") << ", and "
      << plural(counts.errors, "error") << " in " << plural(counts.error_states, "state") << "\n";
}

}  // namespace smcbip::engines
