// Resolution of the names an expression reads or writes, according to where it occurs (atom,
// connector interaction, compound priority, package constant).
#include <algorithm>
#include <optional>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using Kind = ast::ValueType::Kind;
using Where = ExprContext::Where;

ast::ValueType error_type() { return {}; }

void set_ref(ast::Expr& expr, ast::RefKind kind, int index, int sub = -1) {
  expr.ref.kind = kind;
  expr.ref.index = index;
  expr.ref.sub = sub;
}

std::string clock_message(const std::string& name, Where where) {
  std::string text = "clock '" + name +
                     "' can only be compared with a clock-free int or float expression in "
                     "transition guards, invariants and resume conditions";
  if (where == Where::AtomAction || where == Where::AtomInit) {
    text +=
        "; an action may only reset it ('" + name + " = e') or set its rate ('" + name + "' = e')";
  }
  return text;
}

std::optional<ast::ValueType> atom_name(ast::Expr& expr, const ExprContext& ctx, Diagnostics& diags,
                                        NameUse use) {
  const ast::AtomTypeDecl& atom = *ctx.atom;
  const ast::Ident& ident = expr.name.parts.front();
  if (int i = index_of(atom.data, ident.text); i >= 0) {
    set_ref(expr, ast::RefKind::AtomData, i);
    return atom.data[i].type.resolved;
  }
  if (int i = index_of(atom.params, ident.text); i >= 0) {
    set_ref(expr, ast::RefKind::AtomParam, i);
    return atom.params[i].type.resolved;
  }
  if (int i = index_of(atom.clocks, ident.text); i >= 0) {
    set_ref(expr, ast::RefKind::AtomClock, i);
    if (use == NameUse::Read && !clocks_comparable(ctx.where)) {
      diags.error(ident.loc, clock_message(ident.text, ctx.where));
      return error_type();
    }
    return ast::ValueType{Kind::Float, nullptr};
  }
  return std::nullopt;
}

std::optional<ast::ValueType> connector_name(ast::Expr& expr, const ExprContext& ctx,
                                             Diagnostics& diags, NameUse use) {
  const ast::ConnectorTypeDecl& connector = *ctx.connector;
  const ast::Ident& ident = expr.name.parts.front();
  if (int i = index_of(connector.data, ident.text); i >= 0) {
    set_ref(expr, ast::RefKind::ConnectorData, i);
    if (ctx.where == Where::ConnectorGuard && use == NameUse::Read) {
      diags.error(ident.loc, "guard cannot read connector data '" + ident.text +
                                 "': local data is computed by 'up' after the guard holds; a "
                                 "guard may read the data of its ports (port.data)");
      return error_type();
    }
    return connector.data[i].type.resolved;
  }
  if (index_of(connector.ports, ident.text) >= 0) {
    diags.error(ident.loc, "port '" + ident.text + "' is not a value: read its data as '" +
                               ident.text + ".<data>'");
    return error_type();
  }
  return std::nullopt;
}

bool involved(const ExprContext& ctx, int port) {
  if (ctx.interaction == nullptr) return false;
  const std::vector<int>& ports = ctx.interaction->port_index;
  return std::find(ports.begin(), ports.end(), port) != ports.end();
}

std::optional<ast::ValueType> port_data(ast::Expr& expr, const ExprContext& ctx,
                                        Diagnostics& diags) {
  const ast::ConnectorTypeDecl& connector = *ctx.connector;
  const ast::Ident& port = expr.name.parts[0];
  const ast::Ident& member = expr.name.parts[1];
  const int p = index_of(connector.ports, port.text);
  if (p < 0) return std::nullopt;
  const ast::PortTypeDecl* type = connector.ports[p].port_type;
  if (type == nullptr) return error_type();  // unknown port type, reported with the parameter
  const int sub = index_of(type->params, member.text);
  if (sub < 0) {
    diags.error(member.loc, "port '" + port.text + "' of type '" + type->name.text +
                                "' has no data '" + member.text + "'");
    return error_type();
  }
  set_ref(expr, ast::RefKind::PortParam, p, sub);
  if (!involved(ctx, p)) {
    diags.error(port.loc, "port '" + port.text +
                              "' is not involved in this interaction: only the data of its "
                              "ports can be used");
    return error_type();
  }
  return type->params[sub].type.resolved;
}

std::optional<ast::ValueType> compound_name(ast::Expr& expr, const ExprContext& ctx) {
  const ast::Ident& ident = expr.name.parts.front();
  if (int i = index_of(ctx.compound->params, ident.text); i >= 0) {
    set_ref(expr, ast::RefKind::CompoundParam, i);
    return ctx.compound->params[i].type.resolved;
  }
  return std::nullopt;
}

std::optional<ast::ValueType> component_data(ast::Expr& expr, const ExprContext& ctx,
                                             const Symbols& symbols, Diagnostics& diags) {
  const ast::Ident& component = expr.name.parts[0];
  const ast::Ident& member = expr.name.parts[1];
  const int c = index_of(ctx.compound->components, component.text);
  if (c < 0) return std::nullopt;
  const ast::ComponentDecl& decl = ctx.compound->components[c];
  if (decl.atom_type == nullptr && decl.compound_type == nullptr) return error_type();
  for (const ComponentInterface::DataEntry& entry : interface_of(decl, symbols).data) {
    if (entry.name == member.text) {
      set_ref(expr, ast::RefKind::ComponentData, c);
      expr.ref.member = member.text;
      return entry.type;
    }
  }
  diags.error(member.loc,
              "component '" + component.text + "' has no exported data '" + member.text + "'");
  return error_type();
}

/// A constant of the package may only use the constants declared before it.
bool declared_before(const ast::ConstDataDecl* used, const ExprContext& ctx) {
  if (ctx.constant == nullptr || ctx.package == nullptr) return true;
  for (const ast::ConstDataDecl& decl : ctx.package->consts) {
    if (&decl == ctx.constant) return false;  // reached the one being initialised first
    if (&decl == used) return true;
  }
  return true;  // declared in another package
}

std::optional<ast::ValueType> constant_name(ast::Expr& expr, const ExprContext& ctx,
                                            const Symbols& symbols, Diagnostics& diags) {
  if (ctx.package == nullptr) return std::nullopt;
  const ast::ConstDataDecl* decl = symbols.constant(*ctx.package, expr.name);
  if (decl == nullptr) return std::nullopt;
  expr.ref.kind = ast::RefKind::ConstData;
  expr.ref.const_data = decl;
  if (!declared_before(decl, ctx)) {
    diags.error(expr.name.loc(),
                "constant '" + expr.name.text() + "' is used before its declaration is complete");
    return error_type();
  }
  return decl->type.resolved;
}

}  // namespace

ast::ValueType resolve_name(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                            Diagnostics& diags, NameUse use) {
  expr.ref = {};
  const std::vector<ast::Ident>& parts = expr.name.parts;
  if (parts.empty()) return error_type();
  std::optional<ast::ValueType> found;
  if (parts.size() == 1) {
    if (ctx.atom != nullptr) found = atom_name(expr, ctx, diags, use);
    if (!found && ctx.connector != nullptr) found = connector_name(expr, ctx, diags, use);
    if (!found && ctx.compound != nullptr) found = compound_name(expr, ctx);
  } else if (parts.size() == 2) {
    if (ctx.connector != nullptr) found = port_data(expr, ctx, diags);
    if (!found && ctx.compound != nullptr && ctx.where == Where::CompoundPriorityGuard) {
      found = component_data(expr, ctx, symbols, diags);
    }
  }
  if (!found) found = constant_name(expr, ctx, symbols, diags);
  if (found) return *found;
  diags.error(parts.front().loc, "undeclared variable '" + expr.name.text() + "'");
  return error_type();
}

bool names_constant(const ast::Expr& expr, const ExprContext& ctx) {
  if (expr.kind != ast::Expr::Kind::Name) return false;
  const int i = expr.ref.index;
  auto const_at = [i](const auto& decls) {
    return i >= 0 && static_cast<std::size_t>(i) < decls.size() && decls[i].type.is_const;
  };
  switch (expr.ref.kind) {
    case ast::RefKind::ConstData:
      return true;
    case ast::RefKind::AtomData:
      return ctx.atom != nullptr && const_at(ctx.atom->data);
    case ast::RefKind::AtomParam:
      return ctx.atom != nullptr && const_at(ctx.atom->params);
    case ast::RefKind::ConnectorData:
      return ctx.connector != nullptr && const_at(ctx.connector->data);
    case ast::RefKind::CompoundParam:
      return ctx.compound != nullptr && const_at(ctx.compound->params);
    default:
      return false;
  }
}

}  // namespace smcbip::bipc::detail
