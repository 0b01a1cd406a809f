// Breadth-first search over the engines' semantics, keeping each state's parent for the trace.
#include "fdir/search/counterexample_search.h"

#include <functional>
#include <memory>
#include <optional>
#include <queue>
#include <sstream>
#include <tuple>
#include <unordered_set>

#include "engines/api/model.h"
#include "engines/explore.h"
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
                            engines::format_value(runtime.strings(), v, type.data[d].type.kind));
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

/// The search: nodes kept with their parents, expanded breadth first or, with a guide, nearest
/// to the guide's goal first (ties: shallowest, then first found).
class Search {
 public:
  Search(Engine& engine, const StateTarget& target, const SearchLimits& limits)
      : engine_(engine), runtime_(*engine.runtime), target_(target), limits_(limits) {}

  SearchResult run() {
    SearchResult result;
    result.complete = true;
    add({runtime_.state(), 0, 0, ""});
    while (std::optional<std::size_t> k = next()) {
      ++result.states;
      if (visit(*k, result)) {
        result.found = true;
        result.trace = trace_to(runtime_, nodes_, *k);
        return result;
      }
    }
    result.complete = result.complete && result.errors == 0;
    return result;
  }

 private:
  using Rank = std::tuple<std::size_t, std::uint64_t, std::size_t>;  // distance, depth, node

  void add(Node node) {
    nodes_.push_back(std::move(node));
    if (limits_.guide) {
      const Node& n = nodes_.back();
      queue_.emplace(limits_.guide(n.state, engine_.layout), n.depth, nodes_.size() - 1);
    }
  }

  std::optional<std::size_t> next() {
    if (!limits_.guide) {
      if (breadth_ == nodes_.size()) return std::nullopt;
      return breadth_++;
    }
    if (queue_.empty()) return std::nullopt;
    const std::size_t k = std::get<2>(queue_.top());
    queue_.pop();
    return k;
  }

  /// Whether node `k` is a target; otherwise adds its successors not seen before.
  bool visit(std::size_t k, SearchResult& result) {
    const engines::RunState state = nodes_[k].state;
    if (!runtime_.restore(state) || !runtime_.compute_items()) {
      ++result.errors;
      return false;
    }
    const std::vector<engines::Item> items = runtime_.items();
    const bool deadlocked =
        items.empty() && runtime_.wait_interval().right == engines::kPlusInfinity;
    if (target_(runtime_, engine_.strings, deadlocked)) return true;
    if (nodes_[k].depth == limits_.max_depth) {
      result.complete = result.complete && items.empty();
      return false;
    }
    for (const engines::Item& item : items) {
      if (!runtime_.restore(state) || !runtime_.compute_items()) break;
      const std::string fired = engines::item_text(runtime_, item, false);
      if (!runtime_.execute(item, state.now) || !runtime_.resume_atoms(state.now)) {
        ++result.errors;
        continue;
      }
      engines::RunState next = runtime_.state();
      next.now = state.now;
      std::string key = engines::state_key(next);
      if (seen_.contains(key)) continue;
      if (seen_.size() >= limits_.max_states) {
        result.complete = false;
        continue;
      }
      seen_.insert(std::move(key));
      add({std::move(next), k, nodes_[k].depth + 1, fired});
    }
    return false;
  }

  Engine& engine_;
  engines::Runtime& runtime_;
  const StateTarget& target_;
  const SearchLimits& limits_;
  std::vector<Node> nodes_;
  std::size_t breadth_ = 0;
  std::priority_queue<Rank, std::vector<Rank>, std::greater<Rank>> queue_;
  std::unordered_set<std::string> seen_;
};

}  // namespace

SearchResult search_state(const bipc::ir::System& system, const StateTarget& target,
                          const SearchLimits& limits) {
  Engine engine(system);
  engines::Runtime& runtime = *engine.runtime;
  if (!runtime.initialize() || !runtime.resume_atoms(0)) {
    throw UnsupportedModel("the model's initialisation fails: " + runtime.error().message);
  }
  return Search(engine, target, limits).run();
}

}  // namespace smcbip::fdir
