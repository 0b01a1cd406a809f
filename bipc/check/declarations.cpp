// Declarations checked alike in several kinds of types: native parameters and constants, the data
// of atoms and connectors, and the ports that bind data (an atom's ports, a connector's exported
// port).
#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

bool require_native_type(const ast::TypeRef& type, const std::string& what, Diagnostics& diags) {
  if (type.resolved.kind == ast::ValueType::Kind::Error || is_native(type.resolved)) return true;
  diags.error(type.name.loc(), what +
                                   " must have a native type (bool, int, float or string), not " +
                                   type_name(type.resolved));
  return false;
}

void check_data_declarations(std::vector<ast::DataDecl>& data, const ExprContext& ctx,
                             const Symbols& symbols, Diagnostics& diags) {
  for (ast::DataDecl& decl : data) resolve_type(decl.type, *ctx.package, symbols, diags);
  for (ast::DataDecl& decl : data) {
    if (!decl.initial_value) {
      if (decl.type.is_const) {
        diags.error(decl.name.loc, "constant data '" + decl.name.text + "' must be initialised");
      }
      continue;
    }
    const ast::ValueType value = check_expression(*decl.initial_value, ctx, symbols, diags);
    if (!assignable(value, decl.type.resolved)) {
      diags.error(start_of(*decl.initial_value),
                  "type mismatch: cannot assign " + type_name(value) + " to " +
                      type_name(decl.type.resolved) + " '" + decl.name.text + "'");
    }
  }
}

const ast::PortTypeDecl* resolve_port_type(const ast::QualifiedName& type,
                                           const ast::Package& package, const Symbols& symbols,
                                           Diagnostics& diags) {
  const ast::PortTypeDecl* port_type = symbols.port_type(package, type);
  if (port_type == nullptr && !type.parts.empty()) {
    diags.error(type.loc(), "unknown port type '" + type.text() + "'");
  }
  return port_type;
}

void check_bound_count(const std::string& what, const ast::Ident& port,
                       const ast::QualifiedName& type, const ast::PortTypeDecl* port_type,
                       std::size_t bound_count, Diagnostics& diags) {
  if (port_type == nullptr || bound_count == port_type->params.size()) return;
  diags.error(port.loc, "wrong number of arguments: " + what + " '" + port.text + "' of type '" +
                            type.text() + "' expects " + std::to_string(port_type->params.size()) +
                            " data, got " + std::to_string(bound_count));
}

void report_bound_constant(const ast::Ident& bound, const std::string& kind,
                           const std::string& binder, Diagnostics& diags) {
  diags.error(bound.loc, "'" + bound.text + "' is a constant " + kind + ", " + binder +
                             " can only bind variables");
}

void check_bound_type(const std::string& what, const ast::Ident& port,
                      const ast::PortTypeDecl* port_type, std::size_t k, const ast::Ident& bound,
                      const ast::ValueType& actual, Diagnostics& diags) {
  if (port_type == nullptr || k >= port_type->params.size()) return;
  const ast::ValueType& expected = port_type->params[k].type.resolved;
  if (expected.kind == ast::ValueType::Kind::Error || actual.kind == ast::ValueType::Kind::Error ||
      expected == actual) {
    return;
  }
  diags.error(bound.loc, "type mismatch: " + what + " '" + port.text + "' binds '" + bound.text +
                             "' of type " + type_name(actual) + " to parameter '" +
                             port_type->params[k].name.text + "' of type " + type_name(expected) +
                             ": the types must be equal");
}

}  // namespace smcbip::bipc::detail
