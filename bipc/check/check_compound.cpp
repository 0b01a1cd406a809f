// Checks of a compound type: parameters, component declarations and the names they share with
// connectors; connectors, priorities and exports follow in check_compound_*.cpp.
#include "bipc/check/detail/check_compound.h"

#include <set>
#include <tuple>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

std::optional<ast::ValueType::Kind> native_kind(const ast::TypeRef& type) {
  if (type.name.parts.size() != 1) return std::nullopt;
  const std::string& name = type.name.parts.front().text;
  if (name == "bool") return ast::ValueType::Kind::Bool;
  if (name == "int") return ast::ValueType::Kind::Int;
  if (name == "float") return ast::ValueType::Kind::Float;
  if (name == "string") return ast::ValueType::Kind::String;
  return std::nullopt;
}

Location type_location(const ast::TypeRef& type) {
  return type.loc.line != 0 ? type.loc : type.name.loc();
}

/// Verimag allows only native parameter types on component types, so that roots and component
/// arguments are plain values.
void check_params(CompoundScope& scope) {
  std::set<std::string> seen;
  for (ast::ParamDecl& param : scope.type.params) {
    if (native_kind(param.type)) {
      resolve_type(param.type, scope.package, scope.symbols, scope.diags);
    } else {
      param.type.resolved = ast::ValueType{};
      const std::string written = param.type.name.text();
      scope.diags.error(type_location(param.type),
                        "component parameters must have a native type (bool, int, float or "
                        "string), got '" +
                            written + "'");
    }
    if (!seen.insert(param.name.text).second) {
      scope.diags.error(param.name.loc, "duplicate parameter '" + param.name.text + "'");
    }
  }
}

/// Names a written type that is not a component type, for a better message than "unknown".
std::string kind_of_other_type(const ast::QualifiedName& name, const ast::Package& package,
                               const Symbols& symbols) {
  if (symbols.connector_type(package, name) != nullptr) return "a connector type";
  if (symbols.port_type(package, name) != nullptr) return "a port type";
  if (symbols.extern_type(package, name) != nullptr) return "a data type";
  return "";
}

void resolve_component_type(
    ast::ComponentDecl& component, CompoundScope& scope,
    std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>>& reported) {
  if (component.type.parts.empty()) return;  // left by a syntax error, already reported
  component.atom_type = scope.symbols.atom_type(scope.package, component.type);
  if (component.atom_type == nullptr) {
    component.compound_type = scope.symbols.compound_type(scope.package, component.type);
  }
  if (component.atom_type != nullptr || component.compound_type != nullptr) return;
  // `component T a(), b()` repeats the type: report it once.
  const Location at = component.type.loc();
  if (!reported.insert({at.file, at.line, at.column}).second) return;
  const std::string name = component.type.text();
  const std::string other = kind_of_other_type(component.type, scope.package, scope.symbols);
  scope.diags.error(at, other.empty()
                            ? "unknown component type '" + name + "'"
                            : "'" + name + "' is " + other + ", expected an atom or compound type");
}

void check_component_arguments(ast::ComponentDecl& component, CompoundScope& scope) {
  const void* type = component.atom_type != nullptr
                         ? static_cast<const void*>(component.atom_type)
                         : static_cast<const void*>(component.compound_type);
  if (type == nullptr) return;
  const std::vector<ast::ParamDecl>& params = component.atom_type != nullptr
                                                  ? component.atom_type->params
                                                  : component.compound_type->params;
  ExprContext ctx;
  ctx.where = ExprContext::Where::ComponentArgument;
  ctx.package = &scope.package;
  ctx.compound = &scope.type;
  check_arguments(component.args, params, owner_package(type, scope.package, scope.symbols), ctx,
                  "component '" + component.name.text + "' of type '" + component.type.text() + "'",
                  component.name.loc, scope.symbols, scope.diags);
}

void declare_components(CompoundScope& scope) {
  for (std::size_t i = 0; i < scope.type.components.size(); ++i) {
    const ast::Ident& name = scope.type.components[i].name;
    if (name.text.empty()) continue;
    if (!scope.component_index.emplace(name.text, static_cast<int>(i)).second) {
      scope.diags.error(name.loc, "duplicate component '" + name.text + "'");
    }
  }
}

void compute_interfaces(CompoundScope& scope) {
  const std::set<const ast::CompoundTypeDecl*> never =
      never_ending_parts(scope.type, scope.package, scope.symbols);
  scope.interfaces.assign(scope.type.components.size(), std::nullopt);
  for (std::size_t i = 0; i < scope.type.components.size(); ++i) {
    const ast::ComponentDecl& component = scope.type.components[i];
    const bool known = component.atom_type != nullptr || (component.compound_type != nullptr &&
                                                          !never.count(component.compound_type));
    if (known) scope.interfaces[i] = interface_of_ending(component, scope.symbols);
  }
}

PortRef resolve_component_port(int index, const ast::Ident& port, const CompoundScope& scope,
                               bool report) {
  PortRef ref{PortRef::Owner::Component, index, port.text, nullptr};
  const std::optional<ComponentInterface>& interface = scope.interfaces[index];
  if (!interface) return ref;  // its type is wrong, already reported
  for (const ComponentInterface::PortEntry& entry : interface->ports) {
    if (entry.name == port.text) {
      ref.type = entry.type;
      return ref;
    }
  }
  if (report) {
    const ast::ComponentDecl& component = scope.type.components[index];
    scope.diags.error(port.loc, "component '" + component.name.text + "' (type '" +
                                    component.type.text() + "') has no exported port '" +
                                    port.text + "'");
  }
  return {};
}

PortRef resolve_connector_port(int index, const ast::Ident& port, const CompoundScope& scope,
                               bool report) {
  PortRef ref{PortRef::Owner::Connector, index, port.text, nullptr};
  const ast::ConnectorDecl& connector = scope.type.connectors[index];
  const ast::ConnectorTypeDecl* type = connector.connector_type;
  if (type == nullptr) return ref;
  if (type->export_port && type->export_port->name.text == port.text) {
    ref.type = exported_port_type(*type, scope);
    return ref;
  }
  if (report) {
    const std::string prefix =
        "connector '" + connector.name.text + "' (type '" + connector.type.text() + "') ";
    scope.diags.error(port.loc, type->export_port
                                    ? prefix + "exports port '" + type->export_port->name.text +
                                          "', not '" + port.text + "'"
                                    : prefix + "exports no port");
  }
  return {};
}

}  // namespace

const ast::PortTypeDecl* parameter_port_type(const ast::ConnectorTypeDecl& type, std::size_t i,
                                             const CompoundScope& scope) {
  if (i >= type.ports.size()) return nullptr;
  if (type.ports[i].port_type != nullptr) return type.ports[i].port_type;
  return scope.symbols.port_type(owner_package(&type, scope.package, scope.symbols),
                                 type.ports[i].type);
}

const ast::PortTypeDecl* exported_port_type(const ast::ConnectorTypeDecl& type,
                                            const CompoundScope& scope) {
  if (!type.export_port) return nullptr;
  if (type.export_port->port_type != nullptr) return type.export_port->port_type;
  return scope.symbols.port_type(owner_package(&type, scope.package, scope.symbols),
                                 type.export_port->type);
}

ast::ValueType declared_type(const ast::TypeRef& type, const ast::Package& owner,
                             const Symbols& symbols) {
  if (type.resolved.kind != ast::ValueType::Kind::Error) return type.resolved;
  if (auto kind = native_kind(type)) return ast::ValueType{*kind, nullptr};
  if (type.name.parts.empty()) return {};
  const ast::ExternTypeDecl* extern_type = symbols.extern_type(owner, type.name);
  if (extern_type == nullptr) return {};
  return ast::ValueType{ast::ValueType::Kind::Extern, extern_type};
}

void check_arguments(std::vector<ast::ExprPtr>& args, const std::vector<ast::ParamDecl>& params,
                     const ast::Package& params_owner, const ExprContext& ctx,
                     const std::string& what, Location where, const Symbols& symbols,
                     Diagnostics& diags) {
  if (args.size() != params.size()) {
    diags.error(where, what + " expects " + std::to_string(params.size()) +
                           (params.size() == 1 ? " argument" : " arguments") + ", got " +
                           std::to_string(args.size()));
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (!args[i]) continue;
    const ast::ValueType actual = check_expression(*args[i], ctx, symbols, diags);
    if (i >= params.size() || actual.kind == ast::ValueType::Kind::Error) continue;
    const ast::ValueType expected = declared_type(params[i].type, params_owner, symbols);
    if (expected.kind == ast::ValueType::Kind::Error || assignable(actual, expected)) continue;
    diags.error(args[i]->loc, "argument " + std::to_string(i + 1) + " of " + what +
                                  " must be of type '" + type_name(expected) + "' (parameter '" +
                                  params[i].name.text + "'), got '" + type_name(actual) + "'");
  }
}

namespace {

/// A connector argument that is not `x.p`: a constant written where a port goes gets its own
/// message, since a reader would otherwise look for a missing declaration.
void report_malformed_port_ref(const ast::QualifiedName& name, const CompoundScope& scope) {
  std::string kind;
  if (name.parts.size() == 1 && index_of(scope.type.params, name.text()) >= 0) {
    kind = "parameter";
  } else if (name.parts.size() == 1 && scope.symbols.constant(scope.package, name) != nullptr) {
    kind = "data";
  }
  scope.diags.error(name.loc(),
                    kind.empty()
                        ? "expected 'component.port' or 'connector.port', got '" + name.text() + "'"
                        : "'" + name.text() + "' is a constant " + kind +
                              ", a connector binds ports ('component.port')");
}

}  // namespace

PortRef resolve_port_ref(const ast::QualifiedName& name, const CompoundScope& scope, bool report) {
  if (name.parts.size() != 2) {
    if (report && !name.parts.empty()) report_malformed_port_ref(name, scope);
    return {};
  }
  const ast::Ident& owner = name.parts[0];
  if (auto it = scope.component_index.find(owner.text); it != scope.component_index.end()) {
    return resolve_component_port(it->second, name.parts[1], scope, report);
  }
  if (auto it = scope.connector_index.find(owner.text); it != scope.connector_index.end()) {
    return resolve_connector_port(it->second, name.parts[1], scope, report);
  }
  if (report) scope.diags.error(owner.loc, "unknown component or connector '" + owner.text + "'");
  return {};
}

void check_compound_components(CompoundScope& scope) {
  std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> reported;
  for (ast::ComponentDecl& component : scope.type.components) {
    resolve_component_type(component, scope, reported);
    check_component_arguments(component, scope);
  }
  declare_components(scope);
  compute_interfaces(scope);
}

void check_compound_type(ast::CompoundTypeDecl& type, const ast::Package& package,
                         const Symbols& symbols, Diagnostics& diags) {
  CompoundScope scope{type, package, symbols, diags, {}, {}, {}, {}, {}, {}};
  check_params(scope);
  report_recursive_instantiation(type, package, symbols, diags);
  check_compound_components(scope);
  check_compound_connectors(scope);
  check_compound_priorities(scope);
  check_compound_exports(scope);
  warn_unconnected(scope);
}

}  // namespace smcbip::bipc::detail
