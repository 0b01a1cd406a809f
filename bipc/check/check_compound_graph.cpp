// Cycle search on small directed graphs for the compound checks, over Boost.Graph.
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/strong_components.hpp>
#include <limits>

#include "bipc/check/detail/check_compound.h"

namespace smcbip::bipc::detail {

namespace {

/// Records, for every vertex the search reaches, the tree edge it was reached by.
class PredecessorRecorder : public boost::default_bfs_visitor {
 public:
  PredecessorRecorder(std::vector<int>& predecessor, std::vector<int>& distance)
      : predecessor_(&predecessor), distance_(&distance) {}

  template <typename Edge, typename Graph>
  void tree_edge(Edge edge, const Graph& graph) const {
    const auto from = static_cast<int>(boost::source(edge, graph));
    const auto to = static_cast<int>(boost::target(edge, graph));
    (*predecessor_)[to] = from;
    (*distance_)[to] = (*distance_)[from] + 1;
  }

 private:
  std::vector<int>* predecessor_;
  std::vector<int>* distance_;
};

}  // namespace

std::vector<int> strong_component_of(const Digraph& graph) {
  std::vector<int> component(boost::num_vertices(graph), -1);
  if (!component.empty()) {
    boost::strong_components(graph, boost::make_iterator_property_map(
                                        component.begin(), boost::get(boost::vertex_index, graph)));
  }
  return component;
}

std::vector<bool> on_long_cycle(const Digraph& graph) {
  const std::vector<int> component = strong_component_of(graph);
  std::map<int, int> size;
  for (int c : component) ++size[c];
  std::vector<bool> result(component.size(), false);
  for (std::size_t v = 0; v < component.size(); ++v) result[v] = size[component[v]] > 1;
  return result;
}

std::vector<int> shortest_cycle_through(const Digraph& graph, int start) {
  const std::size_t n = boost::num_vertices(graph);
  constexpr int kUnreached = std::numeric_limits<int>::max();
  std::vector<int> predecessor(n, -1);
  std::vector<int> distance(n, kUnreached);
  distance[start] = 0;
  boost::breadth_first_search(graph, boost::vertex(start, graph),
                              boost::visitor(PredecessorRecorder(predecessor, distance)));
  // The closing edge comes from the nearest vertex that has an edge back to the start.
  int last = -1;
  for (auto [it, end] = boost::edges(graph); it != end; ++it) {
    const auto from = static_cast<int>(boost::source(*it, graph));
    if (static_cast<int>(boost::target(*it, graph)) != start || from == start) continue;
    if (distance[from] == kUnreached) continue;
    if (last < 0 || distance[from] < distance[last]) last = from;
  }
  if (last < 0) return {};
  std::vector<int> cycle;
  for (int v = last; v != start; v = predecessor[v]) cycle.push_back(v);
  cycle.push_back(start);
  return {cycle.rbegin(), cycle.rend()};
}

}  // namespace smcbip::bipc::detail
