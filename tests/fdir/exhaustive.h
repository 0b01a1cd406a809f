// The reference verdicts of the tests: every reachable state of a model enumerated with the
// engines' runtime, independently of the prover's own search.
#pragma once

#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_set>
#include <utility>

#include "engines/engines.h"
#include "engines/explore.h"
#include "engines/semantics/runtime.h"

namespace smcbip::tests {

/// What the tests ask of a reachable state: the state, and whether nothing is enabled there.
using StatePredicate = std::function<bool(const engines::RunState& state,
                                          const engines::Layout& layout, bool deadlocked)>;

/// The fewest steps from the initial state to a state satisfying `predicate` (breadth first
/// over every reachable state), or -1 when none does.
inline int shortest_distance(const bipc::ir::System& system, const StatePredicate& predicate) {
  engines::InterpretedModel model(system);
  engines::Layout layout;
  EXPECT_EQ(engines::build_layout(system, layout), "");
  engines::StringPool strings;
  engines::BoundFunctions functions;
  engines::bind_functions(system, engines::Externs::with_builtins(), strings, functions);
  std::ostringstream out;
  engines::RandomStream random(1, 0);
  engines::Runtime runtime(model, layout, functions, strings, out, random, {});
  EXPECT_TRUE(runtime.initialize() && runtime.resume_atoms(0));
  std::deque<std::pair<engines::RunState, int>> frontier{{runtime.state(), 0}};
  std::unordered_set<std::string> seen{engines::state_key(runtime.state())};
  while (!frontier.empty()) {
    const auto [state, depth] = frontier.front();
    frontier.pop_front();
    EXPECT_TRUE(runtime.restore(state) && runtime.compute_items());
    const std::vector<engines::Item> items = runtime.items();
    if (predicate(state, layout, items.empty())) return depth;
    for (const engines::Item& item : items) {
      runtime.restore(state);
      runtime.compute_items();
      EXPECT_TRUE(runtime.execute(item, state.now));
      if (seen.insert(engines::state_key(runtime.state())).second) {
        frontier.emplace_back(runtime.state(), depth + 1);
      }
    }
  }
  return -1;
}

/// Whether some reachable state of `system` satisfies `predicate` (breadth first, every state).
inline bool some_reachable(const bipc::ir::System& system, const StatePredicate& predicate) {
  return shortest_distance(system, predicate) >= 0;
}

/// The number of reachable deadlocks, as `smcbip simulate --explore` counts them.
inline std::uint64_t reachable_deadlocks(const bipc::ir::System& system) {
  engines::SimulateOptions options;
  options.explore = true;
  options.silent = true;
  std::ostringstream out;
  engines::simulate(system, options, engines::Externs::with_builtins(), out);
  const std::string text = out.str();
  const std::size_t found = text.find("reachable states, ");
  EXPECT_NE(found, std::string::npos) << text;
  if (found == std::string::npos) return 0;
  return std::stoull(text.substr(found + std::string("reachable states, ").size()));
}

}  // namespace smcbip::tests
