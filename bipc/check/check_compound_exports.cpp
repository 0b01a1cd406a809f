// Checks of a compound type's interface (exported ports and data), and warnings for ports that
// nothing binds or exports.
#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "bipc/check/detail/check_compound.h"
#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

/// Port and data exports share one namespace, as in the Verimag compiler; a clash is reported
/// at the later declaration.
void declare_exports(const ast::CompoundTypeDecl& type, Diagnostics& diags) {
  std::vector<const ast::Ident*> names;
  for (const ast::PortExportDecl& decl : type.port_exports) names.push_back(&decl.name);
  for (const ast::DataExportDecl& decl : type.data_exports) names.push_back(&decl.name);
  std::stable_sort(names.begin(), names.end(), [](const ast::Ident* a, const ast::Ident* b) {
    return std::tie(a->loc.file, a->loc.line, a->loc.column) <
           std::tie(b->loc.file, b->loc.line, b->loc.column);
  });
  std::set<std::string> seen;
  for (const ast::Ident* name : names) {
    if (!name->text.empty() && !seen.insert(name->text).second) {
      diags.error(name->loc, "duplicate export '" + name->text + "'");
    }
  }
}

void check_port_export(const ast::PortExportDecl& decl, const CompoundScope& scope) {
  std::vector<PortRef> refs;
  const ast::PortTypeDecl* first_type = nullptr;  // of the first reference with a known type
  std::string first_name;
  for (const ast::QualifiedName& name : decl.ports) {
    PortRef ref = resolve_port_ref(name, scope, true);
    if (ref.owner == PortRef::Owner::None) continue;
    const bool twice = std::any_of(refs.begin(), refs.end(),
                                   [&](const PortRef& seen) { return seen.same_port(ref); });
    refs.push_back(ref);
    if (twice) {
      scope.diags.error(name.loc(), "'" + name.text() + "' is referenced twice in export '" +
                                        decl.name.text + "'");
    } else if (ref.type != nullptr && first_type == nullptr) {
      first_type = ref.type;
      first_name = name.text();
    } else if (ref.type != nullptr && ref.type != first_type) {
      scope.diags.error(name.loc(), "merged ports must have the same type: '" + name.text() +
                                        "' has type '" + ref.type->name.text + "', '" + first_name +
                                        "' has type '" + first_type->name.text + "'");
    }
  }
}

void check_data_export(const ast::DataExportDecl& decl, const CompoundScope& scope) {
  const ast::QualifiedName& name = decl.data;
  if (name.parts.size() != 2) {
    if (!name.parts.empty()) {
      scope.diags.error(name.loc(), "expected 'component.data', got '" + name.text() + "'");
    }
    return;
  }
  const ast::Ident& owner = name.parts[0];
  const ast::Ident& data = name.parts[1];
  auto it = scope.component_index.find(owner.text);
  if (it == scope.component_index.end()) {
    scope.diags.error(owner.loc, scope.connector_index.count(owner.text)
                                     ? "'" + owner.text +
                                           "' is a connector: only data of "
                                           "components can be exported"
                                     : "unknown component '" + owner.text + "'");
    return;
  }
  const std::optional<ComponentInterface>& interface = scope.interfaces[it->second];
  if (!interface) return;
  for (const ComponentInterface::DataEntry& entry : interface->data) {
    if (entry.name == data.text) return;
  }
  scope.diags.error(data.loc, "component '" + owner.text + "' (type '" +
                                  scope.type.components[it->second].type.text() +
                                  "') has no exported data '" + data.text + "'");
}

/// Every component port and connector export bound by a connector or exported, per owner.
std::set<std::pair<int, std::string>> used_ports(const CompoundScope& scope, PortRef::Owner owner) {
  std::set<std::pair<int, std::string>> used;
  auto note = [&](const PortRef& ref) {
    if (ref.owner == owner) used.insert({ref.index, ref.port});
  };
  for (const std::vector<PortRef>& bindings : scope.bindings) {
    for (const PortRef& ref : bindings) note(ref);
  }
  for (const ast::PortExportDecl& decl : scope.type.port_exports) {
    for (const ast::QualifiedName& name : decl.ports) note(resolve_port_ref(name, scope, false));
  }
  return used;
}

}  // namespace

void check_compound_exports(CompoundScope& scope) {
  for (const ast::PortExportDecl& decl : scope.type.port_exports) check_port_export(decl, scope);
  for (const ast::DataExportDecl& decl : scope.type.data_exports) check_data_export(decl, scope);
  declare_exports(scope.type, scope.diags);
}

// Verimag warns about these too: whatever depends on such a port can never happen. A model that
// means it (the ends of a chain) says so with @SuppressWarning on the element or a container.
void warn_unconnected(const CompoundScope& scope) {
  auto silenced = [&scope](const ast::Annotations& element, const std::string& warning) {
    return suppresses(element, warning) || suppresses(scope.type.annotations, warning) ||
           suppresses(scope.package.annotations, warning);
  };
  const auto used_components = used_ports(scope, PortRef::Owner::Component);
  for (std::size_t c = 0; c < scope.interfaces.size(); ++c) {
    if (!scope.interfaces[c]) continue;
    if (silenced(scope.type.components[c].annotations, "unboundcomponentport")) continue;
    std::string unused;
    for (const ComponentInterface::PortEntry& port : scope.interfaces[c]->ports) {
      if (used_components.count({static_cast<int>(c), port.name})) continue;
      unused += (unused.empty() ? "'" : ", '") + port.name + "'";
    }
    if (unused.empty()) continue;
    const ast::Ident& name = scope.type.components[c].name;
    scope.diags.warning(name.loc, "component '" + name.text + "' has ports that no connector " +
                                      "binds and no export names: " + unused);
  }
  const auto used_connectors = used_ports(scope, PortRef::Owner::Connector);
  for (std::size_t k = 0; k < scope.type.connectors.size(); ++k) {
    const ast::ConnectorDecl& connector = scope.type.connectors[k];
    if (connector.connector_type == nullptr || !connector.connector_type->export_port) continue;
    if (silenced(connector.annotations, "unboundconnectorport")) continue;
    const std::string& port = connector.connector_type->export_port->name.text;
    if (used_connectors.count({static_cast<int>(k), port})) continue;
    scope.diags.warning(connector.name.loc, "the exported port '" + port + "' of connector '" +
                                                connector.name.text +
                                                "' is neither bound by a connector nor exported");
  }
}

}  // namespace smcbip::bipc::detail
