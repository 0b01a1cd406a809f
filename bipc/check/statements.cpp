// Checking of action blocks: assignments (what each context may write), clock resets and rates,
// calls as statements, and if-then-else.
#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using Kind = ast::ValueType::Kind;
using Where = ExprContext::Where;

bool in_atom_action(const ExprContext& ctx) {
  return ctx.where == Where::AtomAction || ctx.where == Where::AtomInit;
}

/// The value given to a clock (reset or rate) must be a clock-free number.
void check_clock_value(ast::Expr& value, const ExprContext& ctx, const Symbols& symbols,
                       Diagnostics& diags, const std::string& what) {
  const ast::ValueType type = check_expression(value, ctx, symbols, diags);
  if (type.kind != Kind::Error && !is_numeric(type)) {
    diags.error(start_of(value),
                what + " must be an int or float expression, got " + type_name(type));
  }
}

void check_rate(ast::Statement& stmt, const ExprContext& ctx, const Symbols& symbols,
                Diagnostics& diags) {
  ast::Expr& prime = *stmt.target;
  ast::Expr* clock = prime.operands.empty() ? nullptr : prime.operands.front().get();
  if (clock != nullptr && clock->kind == ast::Expr::Kind::Name) {
    const ast::ValueType type = resolve_name(*clock, ctx, symbols, diags, NameUse::Write);
    clock->type = type;
    prime.type = type;
    if (type.kind != Kind::Error && clock->ref.kind != ast::RefKind::AtomClock) {
      diags.error(clock->loc,
                  "only a clock has a rate: '" + name_text(*clock) + "' is not a clock");
    }
  }
  if (stmt.value) check_clock_value(*stmt.value, ctx, symbols, diags, "a clock rate");
}

/// Why a resolved name cannot be assigned in this context, or an empty string.
std::string write_error(const ast::Expr& target, const ExprContext& ctx) {
  const std::string name = name_text(target);
  switch (target.ref.kind) {
    case ast::RefKind::AtomData:
    case ast::RefKind::AtomClock:
      return in_atom_action(ctx) ? "" : "cannot assign to '" + name + "' here";
    case ast::RefKind::AtomParam:
    case ast::RefKind::CompoundParam:
      return std::string("cannot assign to ") + (names_constant(target, ctx) ? "const " : "") +
             "parameter '" + name + "'";
    case ast::RefKind::ConstData:
      return "cannot assign to constant '" + name + "'";
    case ast::RefKind::ConnectorData:
      return ctx.where == Where::ConnectorUp || ctx.where == Where::ConnectorDown
                 ? ""
                 : "cannot assign to '" + name + "' here";
    case ast::RefKind::PortParam:
      if (ctx.where == Where::ConnectorDown) return "";
      return "'up' cannot assign port data '" + name +
             "': it computes connector data, ports are written in 'down'";
    default:
      return "cannot assign to '" + name + "'";
  }
}

void check_assignment(ast::Statement& stmt, const ExprContext& ctx, const Symbols& symbols,
                      Diagnostics& diags) {
  if (!stmt.target) {
    if (stmt.value) check_expression(*stmt.value, ctx, symbols, diags);
    return;
  }
  ast::Expr& target = *stmt.target;
  if (target.kind == ast::Expr::Kind::Prime) {
    check_rate(stmt, ctx, symbols, diags);
    return;
  }
  if (target.kind != ast::Expr::Kind::Name) {
    diags.error(target.loc, "the left-hand side of an assignment must be a variable");
    if (stmt.value) check_expression(*stmt.value, ctx, symbols, diags);
    return;
  }
  const ast::ValueType type = resolve_name(target, ctx, symbols, diags, NameUse::Write);
  target.type = type;
  bool writable = type.kind != Kind::Error;
  if (writable) {
    std::string error = write_error(target, ctx);
    if (error.empty() && names_constant(target, ctx)) {
      error = "cannot assign to constant '" + name_text(target) + "'";
    }
    if (!error.empty()) diags.error(target.loc, error);
    writable = error.empty();
  }
  if (!stmt.value) return;
  if (target.ref.kind == ast::RefKind::AtomClock) {
    check_clock_value(*stmt.value, ctx, symbols, diags, "a clock reset");
    return;
  }
  const ast::ValueType value = check_expression(*stmt.value, ctx, symbols, diags);
  if (writable && !assignable(value, type)) {
    diags.error(start_of(*stmt.value), "type mismatch: cannot assign " + type_name(value) + " to " +
                                           type_name(type) + " '" + name_text(target) + "'");
  }
}

void check_statement(ast::Statement& stmt, const ExprContext& ctx, const Symbols& symbols,
                     Diagnostics& diags) {
  switch (stmt.kind) {
    case ast::Statement::Kind::Assign:
      check_assignment(stmt, ctx, symbols, diags);
      break;
    case ast::Statement::Kind::Call:
      if (stmt.value) check_value(*stmt.value, ctx, symbols, diags, true);
      break;
    case ast::Statement::Kind::If:
      if (stmt.value) check_condition(*stmt.value, ctx, symbols, diags, "an if condition");
      check_block(stmt.then_branch, ctx, symbols, diags);
      check_block(stmt.else_branch, ctx, symbols, diags);
      break;
  }
}

}  // namespace

void check_block(ast::Block& block, const ExprContext& ctx, const Symbols& symbols,
                 Diagnostics& diags) {
  for (ast::StatementPtr& stmt : block) {
    if (stmt) check_statement(*stmt, ctx, symbols, diags);
  }
}

}  // namespace smcbip::bipc::detail
