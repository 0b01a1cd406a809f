// Compound types that contain themselves: an instantiation that never ends.
#include <algorithm>
#include <set>
#include <tuple>

#include "bipc/check/detail/check_compound.h"

namespace smcbip::bipc::detail {

namespace {

/// The compound types reachable from one type through component declarations.
struct InstantiationGraph {
  std::vector<const ast::CompoundTypeDecl*> types;
  std::vector<const ast::Package*> packages;
  std::map<const ast::CompoundTypeDecl*, int> index;
  struct Containment {
    int from = -1, to = -1;
    int component = -1;  // index in types[from]->components
  };
  std::vector<Containment> containments;
  Digraph graph;
};

const ast::CompoundTypeDecl* compound_of(const ast::ComponentDecl& component,
                                         const ast::Package& package, const Symbols& symbols) {
  if (component.compound_type != nullptr) return component.compound_type;
  if (component.atom_type != nullptr || component.type.parts.empty()) return nullptr;
  return symbols.compound_type(package, component.type);
}

int add_type(InstantiationGraph& g, const ast::CompoundTypeDecl* type, const ast::Package* pkg) {
  auto [it, inserted] = g.index.emplace(type, static_cast<int>(g.types.size()));
  if (inserted) {
    g.types.push_back(type);
    g.packages.push_back(pkg);
  }
  return it->second;
}

InstantiationGraph reachable_from(const ast::CompoundTypeDecl& start, const ast::Package& package,
                                  const Symbols& symbols) {
  InstantiationGraph g;
  add_type(g, &start, &package);
  for (std::size_t next = 0; next < g.types.size(); ++next) {
    const ast::CompoundTypeDecl& type = *g.types[next];
    const ast::Package& pkg = *g.packages[next];
    for (std::size_t c = 0; c < type.components.size(); ++c) {
      const ast::CompoundTypeDecl* sub = compound_of(type.components[c], pkg, symbols);
      if (sub == nullptr) continue;
      const int to = add_type(g, sub, &owner_package(sub, pkg, symbols));
      g.containments.push_back({static_cast<int>(next), to, static_cast<int>(c)});
    }
  }
  // Vertices are added in place: assigning a fresh adjacency_list trips a GCC
  // -Wmaybe-uninitialized false positive inside Boost's copy.
  for (std::size_t v = 0; v < g.types.size(); ++v) boost::add_vertex(g.graph);
  for (const auto& edge : g.containments) boost::add_edge(edge.from, edge.to, g.graph);
  return g;
}

bool contains_itself_directly(const InstantiationGraph& g, int v) {
  return std::any_of(g.containments.begin(), g.containments.end(),
                     [v](const auto& e) { return e.from == v && e.to == v; });
}

/// Per vertex: whether its instantiation never ends (it is on a cycle or contains such a type).
/// Linear in the graph: a chain of thousands of nested types is checked once per compound.
std::vector<bool> never_ending(const InstantiationGraph& g) {
  std::vector<bool> result = on_long_cycle(g.graph);
  std::vector<std::vector<int>> containers(g.types.size());
  for (const auto& e : g.containments) {
    if (e.from == e.to) result[e.from] = true;
    containers[e.to].push_back(e.from);
  }
  std::vector<int> pending;
  for (std::size_t v = 0; v < result.size(); ++v) {
    if (result[v]) pending.push_back(static_cast<int>(v));
  }
  while (!pending.empty()) {
    const int v = pending.back();
    pending.pop_back();
    for (int from : containers[v]) {
      if (!result[from]) {
        result[from] = true;
        pending.push_back(from);
      }
    }
  }
  return result;
}

/// A total order on types (source position, then name), so that exactly one member of a cycle
/// reports it.
bool declared_before(const ast::CompoundTypeDecl& a, const ast::CompoundTypeDecl& b) {
  return std::tie(a.loc.file, a.loc.line, a.loc.column, a.name.text) <
         std::tie(b.loc.file, b.loc.line, b.loc.column, b.name.text);
}

bool first_of_its_cycle(const InstantiationGraph& g, const std::vector<int>& component, int v) {
  for (std::size_t u = 0; u < g.types.size(); ++u) {
    if (static_cast<int>(u) != v && component[u] == component[v] &&
        declared_before(*g.types[u], *g.types[v])) {
      return false;
    }
  }
  return true;
}

const ast::ComponentDecl& closing_component(const InstantiationGraph& g, int from, int to) {
  for (const auto& e : g.containments) {
    if (e.from == from && e.to == to) return g.types[from]->components[e.component];
  }
  return g.types[from]->components.front();  // unreachable: the edge exists
}

void report_cycle(const InstantiationGraph& g, const std::vector<int>& cycle, Diagnostics& diags) {
  std::string message = "recursive instantiation: ";
  for (int v : cycle) message += g.types[v]->name.text + " contains ";
  message += g.types[cycle.front()]->name.text;
  const ast::ComponentDecl& closing = closing_component(g, cycle.back(), cycle.front());
  diags.error(closing.type.loc(), message);
}

}  // namespace

const ast::Package& owner_package(const void* type_decl, const ast::Package& fallback,
                                  const Symbols& symbols) {
  const ast::Package* owner = symbols.package_of(type_decl);
  return owner != nullptr ? *owner : fallback;
}

void report_recursive_instantiation(const ast::CompoundTypeDecl& type, const ast::Package& package,
                                    const Symbols& symbols, Diagnostics& diags) {
  const InstantiationGraph g = reachable_from(type, package, symbols);
  if (contains_itself_directly(g, 0)) report_cycle(g, {0}, diags);
  if (!on_long_cycle(g.graph)[0]) return;
  if (!first_of_its_cycle(g, strong_component_of(g.graph), 0)) return;
  const std::vector<int> cycle = shortest_cycle_through(g.graph, 0);
  if (!cycle.empty()) report_cycle(g, cycle, diags);
}

bool instantiation_never_ends(const ast::CompoundTypeDecl& type, const Symbols& symbols) {
  const ast::Package* package = symbols.package_of(&type);
  if (package == nullptr) return false;
  return never_ending(reachable_from(type, *package, symbols))[0];
}

/// The compound types, among those `type` contains, whose instantiation never ends.
std::set<const ast::CompoundTypeDecl*> never_ending_parts(const ast::CompoundTypeDecl& type,
                                                          const ast::Package& package,
                                                          const Symbols& symbols) {
  const InstantiationGraph g = reachable_from(type, package, symbols);
  const std::vector<bool> never = never_ending(g);
  std::set<const ast::CompoundTypeDecl*> result;
  for (std::size_t v = 0; v < never.size(); ++v) {
    if (never[v]) result.insert(g.types[v]);
  }
  return result;
}

}  // namespace smcbip::bipc::detail
