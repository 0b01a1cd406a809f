// Breadth-first search over the engines' semantics, keeping each state's parent for the trace.
#include "fdir/search/counterexample_search.h"

#include <memory>
#include <sstream>
#include <unordered_set>

#include "engines/explore.h"
#include "engines/model.h"
#include "engines/trace/text_trace.h"
#include "fdir/errors.h"

namespace smcbip::fdir {

namespace {

using bipc::ir::Index;

/// A runtime over the interpreted model, with everything it refers to.
struct Engine {
  explicit Engine(const bipc::ir::System& system) : model(system), random(1, 0) {
    if (std::string error = engines::build_layout(system, layout); !error.empty()) {
      throw UnsupportedModel(error);
    }
    const engines::Externs externs = engines::Externs::with_builtins();
    if (std::string error = engines::bind_functions(system, externs, strings, functions);
        !error.empty()) {
      throw UnsupportedModel(error);
    }
    runtime = std::make_unique<engines::Runtime>(model, layout, functions, strings, out, random,
                                                 engines::RuntimeOptions{});
  }
  engines::InterpretedModel model;
  engines::Layout layout;
  engines::StringPool strings;
  engines::BoundFunctions functions;
  std::ostringstream out;
  engines::RandomStream random;
  std::unique_ptr<engines::Runtime> runtime;
};

struct Node {
  engines::RunState state;
  std::size_t parent = 0;
  std::uint64_t depth = 0;
  std::string fired;
};

TraceState describe(const engines::Runtime& runtime, const std::string& fired) {
  const bipc::ir::System& system = runtime.system();
  const engines::Layout& layout = runtime.layout();
  const engines::RunState& state = runtime.state();
  TraceState out{fired, {}, {}};
  for (Index a = 0; a < system.atoms.size(); ++a) {
    const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
    for (Index p = 0; p < type.places.size(); ++p) {
      if (state.marking[layout.atom_places[a] + p]) {
        out.places.push_back(layout.atom_names[a] + "." + type.places[p]);
      }
    }
    for (Index d = 0; d < type.data.size(); ++d) {
      const engines::Val v = state.data[layout.atom_data[a] + d];
      out.data.emplace_back(layout.atom_names[a] + "." + type.data[d].name,
                            runtime.format_value(v, type.data[d].type.kind));
    }
  }
  return out;
}

std::vector<TraceState> trace_to(engines::Runtime& runtime, const std::vector<Node>& nodes,
                                 std::size_t last) {
  std::vector<std::size_t> path;
  for (std::size_t k = last;; k = nodes[k].parent) {
    path.push_back(k);
    if (k == 0) break;
  }
  std::vector<TraceState> trace;
  for (auto k = path.rbegin(); k != path.rend(); ++k) {
    runtime.restore(nodes[*k].state);
    trace.push_back(describe(runtime, nodes[*k].fired));
  }
  return trace;
}

}  // namespace

SearchResult search_state(const bipc::ir::System& system, const StateTarget& target,
                          std::uint64_t max_depth, std::uint64_t max_states) {
  Engine engine(system);
  engines::Runtime& runtime = *engine.runtime;
  if (!runtime.initialize() || !runtime.resume_atoms(0)) {
    throw UnsupportedModel("the model's initialisation fails: " + runtime.error().message);
  }
  SearchResult result;
  result.complete = true;
  std::vector<Node> nodes{{runtime.state(), 0, 0, ""}};
  std::unordered_set<std::string> seen{engines::state_key(runtime.state())};
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    ++result.states;
    const engines::RunState state = nodes[k].state;
    if (!runtime.restore(state) || !runtime.compute_items()) {
      ++result.errors;
      continue;
    }
    const std::vector<engines::Item> items = runtime.items();
    const bool deadlocked =
        items.empty() && runtime.wait_interval().right == engines::kPlusInfinity;
    if (target(runtime, engine.strings, deadlocked)) {
      result.found = true;
      result.trace = trace_to(runtime, nodes, k);
      return result;
    }
    if (nodes[k].depth == max_depth) {
      result.complete = result.complete && items.empty();
      continue;
    }
    for (const engines::Item& item : items) {
      if (!runtime.restore(state) || !runtime.compute_items()) break;
      const std::string fired = engines::item_text(runtime, item, false);
      if (!runtime.execute(item, state.now) || !runtime.resume_atoms(state.now)) {
        ++result.errors;
        continue;
      }
      engines::RunState next = runtime.state();
      next.now = state.now;
      std::string key = engines::state_key(next);
      if (seen.contains(key)) continue;
      if (seen.size() >= max_states) {
        result.complete = false;
        continue;
      }
      seen.insert(std::move(key));
      nodes.push_back({std::move(next), k, nodes[k].depth + 1, fired});
    }
  }
  result.complete = result.complete && result.errors == 0;
  return result;
}

}  // namespace smcbip::fdir
