// Atom priorities: the ports they name, wildcards, guards, and the compile-time rejection of
// unguarded priorities that form a cycle (language.rst, atom "Priorities").
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/strong_components.hpp>
#include <boost/graph/visitors.hpp>
#include <utility>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using Edge = std::pair<int, int>;  // low < high, as port indices
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;

int resolve_port(const std::optional<ast::Ident>& port, const ast::AtomTypeDecl& atom,
                 Diagnostics& diags) {
  if (!port) return -1;
  const int index = index_of(atom.ports, port->text);
  if (index < 0 && !port->text.empty()) {
    diags.error(port->loc, "undeclared port '" + port->text + "'");
  }
  return index;
}

Location name_loc(const ast::AtomPriorityDecl& priority) {
  return priority.name.text.empty() ? priority.loc : priority.name.loc;
}

/// The order pairs a priority stands for: `*` is every other port of the atom.
std::vector<Edge> expand(const ast::AtomPriorityDecl& priority, int ports) {
  std::vector<Edge> edges;
  if (priority.low && priority.high) {
    edges.emplace_back(priority.low_index, priority.high_index);
  } else if (priority.high) {
    for (int q = 0; q < ports; ++q) {
      if (q != priority.high_index) edges.emplace_back(q, priority.high_index);
    }
  } else if (priority.low) {
    for (int q = 0; q < ports; ++q) {
      if (q != priority.low_index) edges.emplace_back(priority.low_index, q);
    }
  }
  return edges;
}

/// The ports on a path from `from` to `to` in `graph` (both included), or empty.
std::vector<int> find_path(const Graph& graph, int from, int to) {
  const std::size_t n = boost::num_vertices(graph);
  std::vector<std::size_t> predecessor(n);
  for (std::size_t v = 0; v < n; ++v) predecessor[v] = v;
  auto recorder =
      boost::record_predecessors(boost::make_iterator_property_map(
                                     predecessor.begin(), boost::get(boost::vertex_index, graph)),
                                 boost::on_tree_edge());
  boost::breadth_first_search(graph, boost::vertex(from, graph),
                              boost::visitor(boost::make_bfs_visitor(recorder)));
  std::vector<int> path;
  if (from != to && predecessor[to] == static_cast<std::size_t>(to)) return path;
  for (std::size_t v = to; v != static_cast<std::size_t>(from); v = predecessor[v]) {
    path.insert(path.begin(), static_cast<int>(v));
  }
  path.insert(path.begin(), from);
  return path;
}

/// The unguarded priorities so far, as a graph on the ports with an edge low -> high.
class PriorityOrder {
 public:
  explicit PriorityOrder(std::size_t ports) : graph_(ports), component_(ports) {}

  /// Adds the pairs of one priority; when they close a cycle, takes them back and returns the
  /// cycle as `p < q < ... < p`, otherwise an empty string.
  std::string add(const std::vector<Edge>& pairs, const ast::AtomTypeDecl& atom) {
    std::vector<Edge> added;
    for (const Edge& e : pairs) {
      if (!boost::edge(e.first, e.second, graph_).second) {
        boost::add_edge(e.first, e.second, graph_);
        added.push_back(e);
      }
    }
    // One strong-components pass tells whether any new pair lies on a cycle.
    boost::strong_components(
        graph_, boost::make_iterator_property_map(component_.begin(),
                                                  boost::get(boost::vertex_index, graph_)));
    for (const auto& [low, high] : added) {
      if (component_[low] != component_[high] && low != high) continue;
      std::string text = atom.ports[low].name.text;  // then high < ... < low, closing the loop
      const std::vector<int> path =
          low == high ? std::vector<int>{low} : find_path(graph_, high, low);
      for (int port : path) text += " < " + atom.ports[port].name.text;
      for (const Edge& e : added) boost::remove_edge(e.first, e.second, graph_);
      return text;
    }
    return "";
  }

 private:
  Graph graph_;
  std::vector<int> component_;
};

}  // namespace

void check_atom_priorities(ast::AtomTypeDecl& atom, const ExprContext& base, const Symbols& symbols,
                           Diagnostics& diags) {
  ExprContext ctx = base;
  ctx.where = ExprContext::Where::AtomPriorityGuard;
  PriorityOrder order(atom.ports.size());
  NameScope names(diags);
  for (ast::AtomPriorityDecl& priority : atom.priorities) {
    names.declare(priority.name);
    priority.low_index = resolve_port(priority.low, atom, diags);
    priority.high_index = resolve_port(priority.high, atom, diags);
    if (priority.guard) check_condition(*priority.guard, ctx, symbols, diags, "a priority guard");
    if (!priority.low && !priority.high) {
      diags.error(name_loc(priority), "priority '" + priority.name.text +
                                          "' cannot use the wildcard '*' on both sides: expected "
                                          "a port on at least one side");
      continue;
    }
    const bool unresolved =
        (priority.low && priority.low_index < 0) || (priority.high && priority.high_index < 0);
    // Guarded priorities are only known at run time, where the engine checks them.
    if (unresolved || priority.guard) continue;
    const std::string cycle =
        order.add(expand(priority, static_cast<int>(atom.ports.size())), atom);
    if (!cycle.empty()) diags.error(name_loc(priority), "atom priorities form a cycle: " + cycle);
  }
}

}  // namespace smcbip::bipc::detail
