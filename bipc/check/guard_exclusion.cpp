// Whether two guards can never hold together, read from their text: the test that spares the
// usual complementary guards (`x == 0` / `x != 0`, `g` / `!(g)`) a non-determinism warning. It
// only says "exclusive" when that is certain; anything else counts as possibly overlapping.
#include <algorithm>
#include <optional>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using ast::BinaryOp;
using ast::Expr;

/// Whether `e` has `n` operands, all present (the checker only sees parsed packages, but a
/// malformed tree must not crash it).
bool has_operands(const Expr& e, std::size_t n) {
  return e.operands.size() == n && std::all_of(e.operands.begin(), e.operands.end(),
                                               [](const ast::ExprPtr& p) { return p != nullptr; });
}

bool same_node(const Expr& a, const Expr& b) {
  switch (a.kind) {
    case Expr::Kind::Int:
      return a.int_value == b.int_value;
    case Expr::Kind::Float:
      return a.float_value == b.float_value;
    case Expr::Kind::String:
      return a.string_value == b.string_value;
    case Expr::Kind::Bool:
      return a.bool_value == b.bool_value;
    case Expr::Kind::Name:
    case Expr::Kind::Call:
      return a.name.text() == b.name.text();
    case Expr::Kind::Unary:
      return a.unary == b.unary;
    case Expr::Kind::Binary:
      return a.binary == b.binary;
    case Expr::Kind::Prime:
      return true;
  }
  return false;
}

bool same_expression(const Expr& a, const Expr& b) {
  if (a.kind != b.kind || a.operands.size() != b.operands.size() || !same_node(a, b)) return false;
  for (std::size_t i = 0; i < a.operands.size(); ++i) {
    if (!a.operands[i] || !b.operands[i]) return false;
    if (!same_expression(*a.operands[i], *b.operands[i])) return false;
  }
  return true;
}

/// A comparison of native values with two operands (an extern operator may mean anything).
bool is_native_comparison(const Expr& e) {
  return e.kind == Expr::Kind::Binary && e.function == nullptr && has_operands(e, 2);
}

// The orders of its operands a comparison allows.
constexpr unsigned kLess = 1, kEqual = 2, kGreater = 4;

std::optional<unsigned> allowed_orders(BinaryOp op) {
  switch (op) {
    case BinaryOp::Eq:
      return kEqual;
    case BinaryOp::Ne:
      return kLess | kGreater;
    case BinaryOp::Lt:
      return kLess;
    case BinaryOp::Le:
      return kLess | kEqual;
    case BinaryOp::Gt:
      return kGreater;
    case BinaryOp::Ge:
      return kGreater | kEqual;
    default:
      return std::nullopt;
  }
}

/// The orders allowed once the operands are swapped (`a < b` is `b > a`).
unsigned mirrored(unsigned orders) {
  return (orders & kEqual) | ((orders & kLess) != 0 ? kGreater : 0U) |
         ((orders & kGreater) != 0 ? kLess : 0U);
}

/// Whether two comparisons of the same operands, in either order, allow no common order:
/// `x == 0` and `x != 0`, `n < max` and `n == max`, `a < b` and `b < a`.
bool disjoint_comparisons(const Expr& a, const Expr& b) {
  if (!is_native_comparison(a) || !is_native_comparison(b)) return false;
  const std::optional<unsigned> left = allowed_orders(a.binary);
  const std::optional<unsigned> right = allowed_orders(b.binary);
  if (!left || !right) return false;
  const Expr &a0 = *a.operands[0], &a1 = *a.operands[1];
  const Expr &b0 = *b.operands[0], &b1 = *b.operands[1];
  if (same_expression(a0, b0) && same_expression(a1, b1)) return (*left & *right) == 0;
  if (same_expression(a0, b1) && same_expression(a1, b0)) return (*left & mirrored(*right)) == 0;
  return false;
}

bool is_literal(const Expr& e) {
  return e.kind == Expr::Kind::Int || e.kind == Expr::Kind::Float || e.kind == Expr::Kind::Bool ||
         e.kind == Expr::Kind::String;
}

/// Whether `a` and `b` equate one expression with two different literals of one kind
/// (`s == 0` and `s == 1`, in either order of operands).
bool equals_different_literals(const Expr& a, const Expr& b) {
  if (!is_native_comparison(a) || !is_native_comparison(b)) return false;
  if (a.binary != BinaryOp::Eq || b.binary != BinaryOp::Eq) return false;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const Expr& value_a = *a.operands[1 - i];
      const Expr& value_b = *b.operands[1 - j];
      if (same_expression(*a.operands[i], *b.operands[j]) && is_literal(value_a) &&
          value_a.kind == value_b.kind && !same_expression(value_a, value_b)) {
        return true;
      }
    }
  }
  return false;
}

bool is_binary(const Expr& e, BinaryOp op) {
  return e.kind == Expr::Kind::Binary && e.binary == op && has_operands(e, 2);
}

/// The operands of a chain of `op` (`a && b && c`: a, b, c), whatever the chain's nesting.
void add_operands_of(BinaryOp op, const Expr& e, std::vector<const Expr*>& out) {
  if (is_binary(e, op)) {
    add_operands_of(op, *e.operands[0], out);
    add_operands_of(op, *e.operands[1], out);
  } else {
    out.push_back(&e);
  }
}

std::vector<const Expr*> conjuncts(const Expr& e) {
  std::vector<const Expr*> out;
  add_operands_of(BinaryOp::And, e, out);
  return out;
}

bool holds_among(const Expr& e, const std::vector<const Expr*>& facts) {
  return std::any_of(facts.begin(), facts.end(),
                     [&e](const Expr* fact) { return same_expression(e, *fact); });
}

/// Whether `facts` (conjuncts known to hold) make `e` hold: each of its conjuncts is a fact.
bool implied(const Expr& e, const std::vector<const Expr*>& facts) {
  const std::vector<const Expr*> needed = conjuncts(e);
  return std::all_of(needed.begin(), needed.end(),
                     [&facts](const Expr* c) { return holds_among(*c, facts); });
}

/// Whether `e` is `!(g)` with `g` made to hold by `facts`, or `!(d1 || ... || dn)` with some `di`
/// that they make hold.
bool refuted_by(const Expr& e, const std::vector<const Expr*>& facts) {
  if (e.kind != Expr::Kind::Unary || e.unary != ast::UnaryOp::Not || e.function != nullptr ||
      !has_operands(e, 1)) {
    return false;
  }
  if (implied(*e.operands[0], facts)) return true;
  std::vector<const Expr*> disjuncts;
  add_operands_of(BinaryOp::Or, *e.operands[0], disjuncts);
  return std::any_of(disjuncts.begin(), disjuncts.end(),
                     [&facts](const Expr* d) { return implied(*d, facts); });
}

}  // namespace

bool guards_exclusive(const ast::Expr& a, const ast::Expr& b) {
  const std::vector<const Expr*> left = conjuncts(a), right = conjuncts(b);
  for (const Expr* x : left) {
    if (refuted_by(*x, right)) return true;
    for (const Expr* y : right) {
      if (refuted_by(*y, left) || disjoint_comparisons(*x, *y) ||
          equals_different_literals(*x, *y)) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace smcbip::bipc::detail
