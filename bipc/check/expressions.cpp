// Typing of expressions: literals, names, native operators (language.rst, "Actions") and extern
// operators; conditions, whose clock constraints clock_constraints.cpp checks.
#include <optional>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using Kind = ast::ValueType::Kind;
using ast::BinaryOp;
using ast::UnaryOp;

ast::ValueType native(Kind kind) { return ast::ValueType{kind, nullptr}; }

const char* symbol(UnaryOp op) {
  switch (op) {
    case UnaryOp::Minus:
      return "-";
    case UnaryOp::Plus:
      return "+";
    case UnaryOp::Not:
      return "!";
    case UnaryOp::BitNot:
      return "~";
  }
  return "?";
}

const char* symbol(BinaryOp op) {
  static const char* const kSymbols[] = {"||", "&&", "|",  "^", "&", "==", "!=", "<",
                                         ">",  "<=", ">=", "+", "-", "*",  "/",  "%"};
  return kSymbols[static_cast<int>(op)];
}

std::optional<ast::ValueType> native_unary(UnaryOp op, const ast::ValueType& operand) {
  switch (op) {
    case UnaryOp::Minus:
    case UnaryOp::Plus:
      if (is_numeric(operand)) return operand;
      break;
    case UnaryOp::Not:
      if (operand.kind == Kind::Bool) return operand;
      break;
    case UnaryOp::BitNot:
      if (operand.kind == Kind::Int) return operand;
      break;
  }
  return std::nullopt;
}

const char* unary_expectation(UnaryOp op) {
  if (op == UnaryOp::Not) return "a bool operand";
  if (op == UnaryOp::BitNot) return "an int operand";
  return "an int or float operand";
}

std::optional<ast::ValueType> native_binary(BinaryOp op, const ast::ValueType& l,
                                            const ast::ValueType& r) {
  switch (op) {
    case BinaryOp::Or:
    case BinaryOp::And:
      if (l.kind == Kind::Bool && r.kind == Kind::Bool) return native(Kind::Bool);
      break;
    case BinaryOp::BitOr:
    case BinaryOp::BitXor:
    case BinaryOp::BitAnd:
    case BinaryOp::Mod:
      if (l.kind == Kind::Int && r.kind == Kind::Int) return native(Kind::Int);
      break;
    case BinaryOp::Add:
    case BinaryOp::Sub:
    case BinaryOp::Mul:
    case BinaryOp::Div:
      if (is_numeric(l) && is_numeric(r)) {
        return native(l.kind == Kind::Int && r.kind == Kind::Int ? Kind::Int : Kind::Float);
      }
      break;
    default:  // comparisons: the same native type, or int and float mixed
      if ((is_numeric(l) && is_numeric(r)) || (is_native(l) && l == r)) return native(Kind::Bool);
      break;
  }
  return std::nullopt;
}

const char* binary_expectation(BinaryOp op) {
  switch (op) {
    case BinaryOp::Or:
    case BinaryOp::And:
      return "bool operands";
    case BinaryOp::BitOr:
    case BinaryOp::BitXor:
    case BinaryOp::BitAnd:
    case BinaryOp::Mod:
      return "int operands";
    case BinaryOp::Add:
    case BinaryOp::Sub:
    case BinaryOp::Mul:
    case BinaryOp::Div:
      return "int or float operands";
    default:
      return "two operands of the same native type (or int and float)";
  }
}

/// Falls back on the extern operators when the native ones do not apply; reports otherwise.
ast::ValueType extern_operator(ast::Expr& expr, const std::string& op,
                               const std::vector<ast::ValueType>& operands, const char* expected,
                               const ExprContext& ctx, const Symbols& symbols, Diagnostics& diags) {
  OperatorMatch match;
  if (ctx.where != ExprContext::Where::ConstInit)
    match = match_operator(op, operands, ctx, symbols);
  if (match.decl != nullptr) {
    expr.function = match.decl;
    return match.decl->result ? match.decl->result->resolved : native(Kind::Void);
  }
  if (match.ambiguous) {
    diags.error(expr.loc,
                "ambiguous operator '" + op + "' for operand types " + type_list(operands));
  } else if (match.exists) {
    diags.error(expr.loc, "no matching operator '" + op + "' for operand types " +
                              type_list(operands) + ": expected " + expected +
                              " or the operand types of an extern operator '" + op + "'");
  } else {
    std::string got = type_name(operands[0]);
    if (operands.size() == 2) got += " and " + type_name(operands[1]);
    diags.error(expr.loc, "operator '" + op + "' expects " + expected + ", got " + got);
  }
  return {};
}

ast::Expr* operand(ast::Expr& expr, std::size_t i) {
  return i < expr.operands.size() ? expr.operands[i].get() : nullptr;
}

ast::ValueType check_unary(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                           Diagnostics& diags) {
  ast::Expr* arg = operand(expr, 0);
  if (arg == nullptr) return {};
  const ast::ValueType type = check_value(*arg, ctx, symbols, diags, false);
  if (type.kind == Kind::Error) return type;
  if (auto result = native_unary(expr.unary, type)) return *result;
  return extern_operator(expr, symbol(expr.unary), {type}, unary_expectation(expr.unary), ctx,
                         symbols, diags);
}

ast::ValueType check_binary(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                            Diagnostics& diags) {
  ast::Expr* left = operand(expr, 0);
  ast::Expr* right = operand(expr, 1);
  if (left == nullptr || right == nullptr) return {};
  const ast::ValueType l = check_value(*left, ctx, symbols, diags, false);
  const ast::ValueType r = check_value(*right, ctx, symbols, diags, false);
  if (l.kind == Kind::Error || r.kind == Kind::Error) return {};
  if (auto result = native_binary(expr.binary, l, r)) return *result;
  return extern_operator(expr, symbol(expr.binary), {l, r}, binary_expectation(expr.binary), ctx,
                         symbols, diags);
}

bool is_clock(const ast::Expr* expr) {
  return expr != nullptr && expr->kind == ast::Expr::Kind::Name &&
         expr->ref.kind == ast::RefKind::AtomClock;
}

}  // namespace

const ast::Expr* first_clock(const ast::Expr& expr) {
  if (is_clock(&expr)) return &expr;
  for (const ast::ExprPtr& sub : expr.operands) {
    if (!sub) continue;
    if (const ast::Expr* found = first_clock(*sub)) return found;
  }
  return nullptr;
}

bool mentions_clock(const ast::Expr& expr) { return first_clock(expr) != nullptr; }

Location start_of(const ast::Expr& expr) {
  const bool operand_first =
      expr.kind == ast::Expr::Kind::Binary || expr.kind == ast::Expr::Kind::Prime;
  if (operand_first && !expr.operands.empty() && expr.operands.front()) {
    return start_of(*expr.operands.front());
  }
  return expr.loc;
}

ast::ValueType check_value(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                           Diagnostics& diags, bool allow_void) {
  ast::ValueType type;
  switch (expr.kind) {
    case ast::Expr::Kind::Int:
      type = native(Kind::Int);
      break;
    case ast::Expr::Kind::Float:
      type = native(Kind::Float);
      break;
    case ast::Expr::Kind::String:
      type = native(Kind::String);
      break;
    case ast::Expr::Kind::Bool:
      type = native(Kind::Bool);
      break;
    case ast::Expr::Kind::Name:
      type = resolve_name(expr, ctx, symbols, diags, NameUse::Read);
      break;
    case ast::Expr::Kind::Call:
      type = check_call(expr, ctx, symbols, diags, allow_void);
      break;
    case ast::Expr::Kind::Unary:
      type = check_unary(expr, ctx, symbols, diags);
      break;
    case ast::Expr::Kind::Binary:
      type = check_binary(expr, ctx, symbols, diags);
      break;
    case ast::Expr::Kind::Prime:
      diags.error(expr.loc, "a clock rate (x') can only be set by an assignment in an action");
      break;
  }
  expr.type = type;
  return type;
}

ast::ValueType check_expression(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                                Diagnostics& diags) {
  return check_value(expr, ctx, symbols, diags, false);
}

void check_condition(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                     Diagnostics& diags, const char* what) {
  const ast::ValueType type = check_expression(expr, ctx, symbols, diags);
  if (type.kind == Kind::Error) return;  // reported, and clock forms would only repeat it
  if (type.kind != Kind::Bool) {
    diags.error(start_of(expr),
                std::string(what) + " must be a bool expression, got " + type_name(type));
    return;
  }
  if (clocks_comparable(ctx.where)) check_clock_constraints(expr, diags);
}

}  // namespace smcbip::bipc::detail
