// What the checks of one compound type share: resolved port references, the binding structure
// of its connectors, and the small directed-graph helpers (Boost.Graph) its cycle checks use.
#pragma once

#include <boost/graph/adjacency_list.hpp>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bipc/check/detail/check_context.h"

namespace smcbip::bipc::detail {

/// A reference `x.p` inside a compound, resolved to a port of component `x`'s interface or to
/// the exported port of connector `x`.
struct PortRef {
  enum class Owner : std::uint8_t { None, Component, Connector };
  Owner owner = Owner::None;  // None: the reference is wrong (already reported)
  int index = -1;             // component or connector index in the compound
  std::string port;
  const ast::PortTypeDecl* type = nullptr;  // null when unknown after an earlier error

  bool same_port(const PortRef& other) const {
    return owner == other.owner && index == other.index && port == other.port;
  }
};

/// The state shared by the checks of one compound type.
struct CompoundScope {
  ast::CompoundTypeDecl& type;
  const ast::Package& package;
  const Symbols& symbols;
  Diagnostics& diags;

  /// Components and connectors share one namespace (a reference `x.p` may name either).
  std::map<std::string, int> component_index;
  std::map<std::string, int> connector_index;
  /// Per component: its interface, or nullopt when its type is unknown or never ends.
  std::vector<std::optional<ComponentInterface>> interfaces;
  /// Per connector and argument: what the argument binds.
  std::vector<std::vector<PortRef>> bindings;
  /// Per connector: the connectors of this compound that bind its exported port.
  std::vector<std::vector<int>> bound_by;
  /// Per connector: whether it takes part in a cycle of bindings (already reported).
  std::vector<bool> in_binding_cycle;
};

/// Resolves `x.p`; reports what is wrong when `report` is set (then returns Owner::None).
PortRef resolve_port_ref(const ast::QualifiedName& name, const CompoundScope& scope, bool report);

/// The port type of a connector type's port parameter or exported port, read from the
/// resolved field or, when the connector type is not checked yet, looked up by name.
const ast::PortTypeDecl* parameter_port_type(const ast::ConnectorTypeDecl& type, std::size_t i,
                                             const CompoundScope& scope);
const ast::PortTypeDecl* exported_port_type(const ast::ConnectorTypeDecl& type,
                                            const CompoundScope& scope);

/// The package that declares a type, falling back to `fallback` when Symbols does not know it.
const ast::Package& owner_package(const void* type_decl, const ast::Package& fallback,
                                  const Symbols& symbols);

/// The value type of a declared parameter of a type declared in `owner`: the resolved field,
/// or, when that type is not checked yet, the native or extern type its name denotes.
ast::ValueType declared_type(const ast::TypeRef& type, const ast::Package& owner,
                             const Symbols& symbols);

/// Checks component or root arguments against the parameters of the instantiated type.
/// `what` names the instance in messages ("component 'a' of type 'T'"); a wrong count is
/// reported at `where`.
void check_arguments(std::vector<ast::ExprPtr>& args, const std::vector<ast::ParamDecl>& params,
                     const ast::Package& params_owner, const ExprContext& ctx,
                     const std::string& what, Location where, const Symbols& symbols,
                     Diagnostics& diags);

/// The compound types among those `type` contains (itself included) whose instantiation never
/// ends; interface_of must not be asked about them.
std::set<const ast::CompoundTypeDecl*> never_ending_parts(const ast::CompoundTypeDecl& type,
                                                          const ast::Package& package,
                                                          const Symbols& symbols);

/// Per-part checks of check_compound_type, in the order it runs them.
void check_compound_components(CompoundScope& scope);
void check_compound_connectors(CompoundScope& scope);
void check_compound_priorities(CompoundScope& scope);
void check_compound_exports(CompoundScope& scope);
void warn_unconnected(const CompoundScope& scope);

/// Reports a compound type that contains itself (directly or through other compound types),
/// once per cycle: at the component declaration that closes the cycle, from the cycle's first
/// type in source order.
void report_recursive_instantiation(const ast::CompoundTypeDecl& type, const ast::Package& package,
                                    const Symbols& symbols, Diagnostics& diags);

// ---------------------------------------------------------------------------------------------
// Directed graphs for the cycle checks (instantiation, connector bindings, priorities).

using Digraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;

/// Per vertex, whether it lies on a cycle of at least two vertices (self-loops do not count:
/// each cycle check treats them on its own).
std::vector<bool> on_long_cycle(const Digraph& graph);

/// The strongly connected component of each vertex (Tarjan, via boost::strong_components).
std::vector<int> strong_component_of(const Digraph& graph);

/// A shortest cycle through `start` as the vertex sequence start, v1, ..., vk (the edge vk ->
/// start closes it), ignoring self-loops; empty when there is none.
std::vector<int> shortest_cycle_through(const Digraph& graph, int start);

}  // namespace smcbip::bipc::detail
