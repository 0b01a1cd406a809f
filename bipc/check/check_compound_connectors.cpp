// Checks of the connector declarations of a compound type: their types, the ports they bind,
// and the hierarchy formed by connectors that bind other connectors' exported ports.
#include <set>
#include <tuple>

#include "bipc/check/detail/check_compound.h"

namespace smcbip::bipc::detail {

namespace {

using LocationKey = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;

bool located_before(Location a, Location b) {
  return std::tie(a.file, a.line, a.column) < std::tie(b.file, b.line, b.column);
}

void resolve_connector_type(ast::ConnectorDecl& connector, CompoundScope& scope,
                            std::set<LocationKey>& reported) {
  connector.connector_type = scope.symbols.connector_type(scope.package, connector.type);
  if (connector.connector_type != nullptr || connector.type.parts.empty()) return;
  // `connector T a(...), b(...)` repeats the type: report it once.
  const Location at = connector.type.loc();
  if (!reported.insert({at.file, at.line, at.column}).second) return;
  const std::string name = connector.type.text();
  const bool is_component = scope.symbols.atom_type(scope.package, connector.type) != nullptr ||
                            scope.symbols.compound_type(scope.package, connector.type) != nullptr;
  scope.diags.error(at, is_component
                            ? "'" + name + "' is a component type, expected a connector type"
                            : "unknown connector type '" + name + "'");
}

/// Components and connectors share a namespace, because `x.p` may name either.
void declare_connector(CompoundScope& scope, int index) {
  const ast::Ident& name = scope.type.connectors[index].name;
  if (name.text.empty()) return;
  if (auto it = scope.component_index.find(name.text); it != scope.component_index.end()) {
    const ast::Ident& component = scope.type.components[it->second].name;
    const ast::Ident& later = located_before(component.loc, name.loc) ? name : component;
    scope.diags.error(later.loc, "'" + name.text + "' names both a component and a connector");
  }
  if (!scope.connector_index.emplace(name.text, index).second) {
    scope.diags.error(name.loc, "duplicate connector '" + name.text + "'");
  }
}

void bind_arguments(CompoundScope& scope, int index) {
  const ast::ConnectorDecl& connector = scope.type.connectors[index];
  const ast::ConnectorTypeDecl* type = connector.connector_type;
  std::vector<PortRef>& bindings = scope.bindings[index];
  for (std::size_t i = 0; i < connector.ports.size(); ++i) {
    bindings.push_back(resolve_port_ref(connector.ports[i], scope, true));
    if (type == nullptr || bindings.back().type == nullptr) continue;
    const ast::PortTypeDecl* expected = parameter_port_type(*type, i, scope);
    if (expected == nullptr || expected == bindings.back().type) continue;
    scope.diags.error(connector.ports[i].loc(),
                      "expected a port of type '" + expected->name.text + "', got '" +
                          bindings.back().type->name.text + "' ('" + connector.ports[i].text() +
                          "' for parameter '" + type->ports[i].name.text + "' of connector type '" +
                          type->name.text + "')");
  }
  if (type != nullptr && connector.ports.size() != type->ports.size()) {
    scope.diags.error(connector.name.loc, "connector '" + connector.name.text + "' of type '" +
                                              connector.type.text() + "' expects " +
                                              std::to_string(type->ports.size()) +
                                              (type->ports.size() == 1 ? " port" : " ports") +
                                              ", got " + std::to_string(connector.ports.size()));
  }
}

void collect_bound_by(CompoundScope& scope) {
  scope.bound_by.assign(scope.type.connectors.size(), {});
  for (std::size_t k = 0; k < scope.bindings.size(); ++k) {
    for (const PortRef& ref : scope.bindings[k]) {
      if (ref.owner != PortRef::Owner::Connector) continue;
      std::vector<int>& parents = scope.bound_by[ref.index];
      if (parents.empty() || parents.back() != static_cast<int>(k)) {
        parents.push_back(static_cast<int>(k));
      }
    }
  }
}

/// The argument of connector `from` that binds connector `to`.
const ast::QualifiedName& binding_argument(const CompoundScope& scope, int from, int to) {
  const std::vector<PortRef>& bindings = scope.bindings[from];
  for (std::size_t i = 0; i < bindings.size(); ++i) {
    if (bindings[i].owner == PortRef::Owner::Connector && bindings[i].index == to) {
      return scope.type.connectors[from].ports[i];
    }
  }
  return scope.type.connectors[from].ports.front();  // unreachable: the binding exists
}

/// A connector that (transitively) binds itself would be an infinite interaction tree.
void report_binding_cycles(CompoundScope& scope) {
  const std::size_t n = scope.type.connectors.size();
  scope.in_binding_cycle.assign(n, false);
  Digraph graph(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (const PortRef& ref : scope.bindings[k]) {
      if (ref.owner != PortRef::Owner::Connector) continue;
      if (ref.index == static_cast<int>(k)) {
        scope.in_binding_cycle[k] = true;
        scope.diags.error(
            binding_argument(scope, k, k).loc(),
            "connector '" + scope.type.connectors[k].name.text + "' binds its own exported port");
      } else {
        boost::add_edge(k, ref.index, graph);
      }
    }
  }
  const std::vector<bool> cyclic = on_long_cycle(graph);
  std::set<int> reported_components;
  const std::vector<int> component = strong_component_of(graph);
  for (std::size_t k = 0; k < n; ++k) {
    if (!cyclic[k]) continue;
    scope.in_binding_cycle[k] = true;
    // Connectors are visited in declaration order: the first of each cycle reports it.
    if (!reported_components.insert(component[k]).second) continue;
    const std::vector<int> cycle = shortest_cycle_through(graph, static_cast<int>(k));
    std::string message = "connectors bind each other in a cycle: ";
    for (int c : cycle) message += scope.type.connectors[c].name.text + " binds ";
    message += scope.type.connectors[k].name.text;
    scope.diags.error(binding_argument(scope, cycle.back(), cycle.front()).loc(), message);
  }
}

/// The components whose ports a connector binds, directly or through the connectors it binds.
void components_reached(const CompoundScope& scope, int connector, std::set<int>& reached) {
  for (const PortRef& ref : scope.bindings[connector]) {
    if (ref.owner == PortRef::Owner::Component) reached.insert(ref.index);
    if (ref.owner == PortRef::Owner::Connector && !scope.in_binding_cycle[ref.index]) {
      components_reached(scope, ref.index, reached);
    }
  }
}

/// A component takes part in an interaction through one port at most: a connector binding it
/// twice (directly or through sub-connectors) describes interactions that can never happen.
void check_bound_once(CompoundScope& scope, int index) {
  if (scope.in_binding_cycle[index]) return;
  const ast::ConnectorDecl& connector = scope.type.connectors[index];
  std::set<int> components, connectors, reported;
  for (std::size_t i = 0; i < scope.bindings[index].size(); ++i) {
    const PortRef& ref = scope.bindings[index][i];
    std::set<int> reached;
    if (ref.owner == PortRef::Owner::Component) reached.insert(ref.index);
    if (ref.owner == PortRef::Owner::Connector) {
      if (!connectors.insert(ref.index).second) {
        scope.diags.error(connector.ports[i].loc(),
                          "connector '" + connector.name.text + "' binds connector '" +
                              scope.type.connectors[ref.index].name.text + "' more than once");
        continue;
      }
      if (!scope.in_binding_cycle[ref.index]) components_reached(scope, ref.index, reached);
    }
    for (int c : reached) {
      if (components.insert(c).second || !reported.insert(c).second) continue;
      scope.diags.error(connector.ports[i].loc(),
                        "connector '" + connector.name.text + "' binds component '" +
                            scope.type.components[c].name.text + "' more than once");
    }
  }
}

}  // namespace

void check_compound_connectors(CompoundScope& scope) {
  std::set<LocationKey> reported;
  for (std::size_t k = 0; k < scope.type.connectors.size(); ++k) {
    resolve_connector_type(scope.type.connectors[k], scope, reported);
    declare_connector(scope, static_cast<int>(k));
  }
  scope.bindings.assign(scope.type.connectors.size(), {});
  for (std::size_t k = 0; k < scope.type.connectors.size(); ++k) {
    bind_arguments(scope, static_cast<int>(k));
  }
  collect_bound_by(scope);
  report_binding_cycles(scope);
  for (std::size_t k = 0; k < scope.type.connectors.size(); ++k) {
    check_bound_once(scope, static_cast<int>(k));
  }
}

}  // namespace smcbip::bipc::detail
