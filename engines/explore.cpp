// Breadth-first enumeration of reachable states.
#include "engines/explore.h"

#include <boost/container_hash/hash.hpp>
#include <deque>
#include <limits>
#include <unordered_set>
#include <utility>

#include "engines/trace/text_trace.h"

namespace smcbip::engines {

namespace {

std::string plural(std::uint64_t n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

/// Breadth-first search to depth `max_steps`, keeping at most `max_states` states; `seen`
/// receives the keys of the states found.
ExplorationCounts breadth_first(Runtime& runtime, std::uint64_t max_steps, std::uint64_t max_states,
                                std::unordered_set<std::string>& seen) {
  ExplorationCounts counts;
  std::deque<std::pair<RunState, std::uint64_t>> frontier;  // with its depth
  seen.insert(state_key(runtime.state()));
  frontier.emplace_back(runtime.state(), 0);
  while (!frontier.empty()) {
    const RunState state = std::move(frontier.front().first);
    const std::uint64_t depth = frontier.front().second;
    frontier.pop_front();
    ++counts.states;
    if (depth == max_steps) continue;
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
      std::string key = state_key(next);
      if (seen.contains(key)) continue;
      if (seen.size() >= max_states) {
        counts.cut = true;
        continue;
      }
      seen.insert(std::move(key));
      frontier.emplace_back(std::move(next), depth + 1);
    }
    if (failed) ++counts.error_states;
  }
  return counts;
}

}  // namespace

std::string state_key(const RunState& state) {
  std::string key(reinterpret_cast<const char*>(state.marking.data()), state.marking.size());
  key.append(reinterpret_cast<const char*>(state.data.data()), state.data.size() * sizeof(Val));
  key.append(reinterpret_cast<const char*>(state.resume_pending.data()),
             state.resume_pending.size());
  return key;
}

ExplorationCounts explore_states(Runtime& runtime, std::optional<std::uint64_t> max_steps,
                                 std::uint64_t max_states) {
  std::unordered_set<std::string> seen;
  return breadth_first(runtime, max_steps.value_or(std::numeric_limits<std::uint64_t>::max()),
                       max_states, seen);
}

std::unordered_set<std::string> reachable_state_keys(Runtime& runtime, std::uint64_t max_steps) {
  std::unordered_set<std::string> seen;
  breadth_first(runtime, max_steps, std::numeric_limits<std::uint64_t>::max(), seen);
  return seen;
}

void write_exploration(std::ostream& out, const ExplorationCounts& counts) {
  out << kEnginePrefix << "computing reachable states:... found "
      << plural(counts.states, "reachable state") << ", " << plural(counts.deadlocks, "deadlock")
      << ", " << plural(counts.timelocks, "timelock") << ", and " << plural(counts.errors, "error")
      << " in " << plural(counts.error_states, "state") << "\n";
  if (counts.cut) {
    out << kEnginePrefix << "exploration cut at " << plural(counts.states, "state")
        << " (--max-states): the counts are those of the states found\n";
  }
}

}  // namespace smcbip::engines
