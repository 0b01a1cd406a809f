// Non-determinism an atom's text shows: two transitions on one port (or two internal ones) whose
// source places are nested, so both are enabled whenever the one with more places is. Unguarded
// pairs are errors and guarded ones warnings, after the Verimag front end's
// checkDuplicatedTriggerPortFromSameState; its coverability analysis of disjoint sources is left
// to the engines, which report the non-determinism when it happens (exit code 1).
#include <algorithm>
#include <optional>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using ast::BinaryOp;
using ast::Expr;

bool same_expression(const Expr& a, const Expr& b) {
  if (a.kind != b.kind || a.operands.size() != b.operands.size()) return false;
  switch (a.kind) {
    case Expr::Kind::Int:
      if (a.int_value != b.int_value) return false;
      break;
    case Expr::Kind::Float:
      if (a.float_value != b.float_value) return false;
      break;
    case Expr::Kind::String:
      if (a.string_value != b.string_value) return false;
      break;
    case Expr::Kind::Bool:
      if (a.bool_value != b.bool_value) return false;
      break;
    case Expr::Kind::Name:
    case Expr::Kind::Call:
      if (a.name.text() != b.name.text()) return false;
      break;
    case Expr::Kind::Unary:
      if (a.unary != b.unary) return false;
      break;
    case Expr::Kind::Binary:
      if (a.binary != b.binary) return false;
      break;
    case Expr::Kind::Prime:
      break;
  }
  for (std::size_t i = 0; i < a.operands.size(); ++i) {
    if (!a.operands[i] || !b.operands[i]) return false;
    if (!same_expression(*a.operands[i], *b.operands[i])) return false;
  }
  return true;
}

/// Whether `e` has `n` operands, all present (the checker only sees parsed packages, but a
/// malformed tree must not crash it).
bool has_operands(const Expr& e, std::size_t n) {
  return e.operands.size() == n && std::all_of(e.operands.begin(), e.operands.end(),
                                               [](const ast::ExprPtr& p) { return p != nullptr; });
}

/// The comparison that holds exactly when `op` does not (x == y against x != y, ...).
std::optional<BinaryOp> complement(BinaryOp op) {
  switch (op) {
    case BinaryOp::Eq:
      return BinaryOp::Ne;
    case BinaryOp::Ne:
      return BinaryOp::Eq;
    case BinaryOp::Lt:
      return BinaryOp::Ge;
    case BinaryOp::Ge:
      return BinaryOp::Lt;
    case BinaryOp::Gt:
      return BinaryOp::Le;
    case BinaryOp::Le:
      return BinaryOp::Gt;
    default:
      return std::nullopt;
  }
}

bool is_not(const Expr& e) {
  return e.kind == Expr::Kind::Unary && e.unary == ast::UnaryOp::Not && has_operands(e, 1);
}

/// Whether `b` is written as the negation of `a`: `g` and `!(g)`, or complementary comparisons
/// of the same operands (`x == 0` and `x != 0`).
bool negates(const Expr& a, const Expr& b) {
  if (is_not(a) && same_expression(*a.operands[0], b)) return true;
  if (is_not(b) && same_expression(*b.operands[0], a)) return true;
  if (a.kind != Expr::Kind::Binary || b.kind != Expr::Kind::Binary) return false;
  if (!has_operands(a, 2) || !has_operands(b, 2)) return false;
  const std::optional<BinaryOp> opposite = complement(a.binary);
  return opposite && *opposite == b.binary && same_expression(*a.operands[0], *b.operands[0]) &&
         same_expression(*a.operands[1], *b.operands[1]);
}

bool is_literal(const Expr& e) {
  return e.kind == Expr::Kind::Int || e.kind == Expr::Kind::Float || e.kind == Expr::Kind::Bool ||
         e.kind == Expr::Kind::String;
}

/// Whether `a` and `b` equate one expression with two different literals of one kind
/// (`s == 0` and `s == 1`, in either order of operands).
bool equals_different_literals(const Expr& a, const Expr& b) {
  if (a.kind != Expr::Kind::Binary || b.kind != Expr::Kind::Binary) return false;
  if (a.binary != BinaryOp::Eq || b.binary != BinaryOp::Eq) return false;
  if (!has_operands(a, 2) || !has_operands(b, 2)) return false;
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

/// The expression and, when it is a conjunction, its sub-conjunctions and conjuncts: anything
/// that holds whenever it does.
void add_conjuncts(const Expr& e, std::vector<const Expr*>& out) {
  out.push_back(&e);
  if (e.kind == Expr::Kind::Binary && e.binary == BinaryOp::And && has_operands(e, 2)) {
    add_conjuncts(*e.operands[0], out);
    add_conjuncts(*e.operands[1], out);
  }
}

/// Whether two guards can never hold together because a conjunct of one contradicts one of the
/// other's: a syntactic test, so that the usual complementary guards raise no warning.
bool exclusive(const Expr& a, const Expr& b) {
  std::vector<const Expr*> left, right;
  add_conjuncts(a, left);
  add_conjuncts(b, right);
  for (const Expr* x : left) {
    for (const Expr* y : right) {
      if (negates(*x, *y) || equals_different_literals(*x, *y)) return true;
    }
  }
  return false;
}

/// Whether the transition's port and places all resolved (errors are reported elsewhere).
bool resolved(const ast::Transition& t) {
  if (t.port && t.port_index < 0) return false;
  return std::none_of(t.from_index.begin(), t.from_index.end(), [](int p) { return p < 0; });
}

bool contains_all(const std::vector<int>& big, const std::vector<int>& small) {
  return std::all_of(small.begin(), small.end(),
                     [&big](int p) { return std::find(big.begin(), big.end(), p) != big.end(); });
}

/// Whether both transitions are enabled whenever their guards hold in the larger one's places.
bool overlap(const ast::Transition& a, const ast::Transition& b) {
  if (a.port_index != b.port_index || !resolved(a) || !resolved(b)) return false;
  return contains_all(a.from_index, b.from_index) || contains_all(b.from_index, a.from_index);
}

bool suppressed(const ast::Annotations& annotations) {
  return suppresses(annotations, "nondeterminism");
}

std::string places_text(const ast::Transition& t) {
  std::string text;
  for (const ast::Ident& place : t.from) text += (text.empty() ? "" : ", ") + place.text;
  return text;
}

std::string subject(const ast::Transition& t) {
  return t.port ? "transitions on port '" + t.port->text + "'" : "internal transitions";
}

void report(const ast::Transition& later, const ast::Transition& earlier, bool guarded,
            Diagnostics& diags) {
  const std::string pair = subject(later) + " from " + places_text(later) + " (here) and from " +
                           places_text(earlier) + " (line " + std::to_string(earlier.loc.line) +
                           ")";
  if (guarded) {
    diags.warning(later.loc, "possible non-determinism: " + pair +
                                 " can be enabled together when both guards hold; "
                                 "@SuppressWarning(nondeterminism) accepts it");
  } else {
    diags.error(later.loc,
                "non-determinism: " + pair + " can be enabled together, and neither has a guard");
  }
  diags.note(earlier.loc, "the other transition is here");
}

}  // namespace

void check_atom_determinism(const ast::AtomTypeDecl& atom, const ast::Package& package,
                            Diagnostics& diags) {
  const bool warnings_off = suppressed(atom.annotations) || suppressed(package.annotations);
  const std::vector<ast::Transition>& all = atom.transitions;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const ast::Transition* warned_with = nullptr;
    bool failed = false;
    for (std::size_t j = 0; j < i && !failed; ++j) {
      if (!overlap(all[i], all[j])) continue;
      if (!all[i].guard && !all[j].guard) {
        report(all[i], all[j], false, diags);
        failed = true;
      } else if (warned_with == nullptr &&
                 !(all[i].guard && all[j].guard && exclusive(*all[i].guard, *all[j].guard))) {
        warned_with = &all[j];
      }
    }
    // One diagnostic per transition (an error rather than a warning), as the Verimag front end
    // reports them.
    if (!failed && warned_with != nullptr && !warnings_off && !suppressed(all[i].annotations)) {
      report(all[i], *warned_with, true, diags);
    }
  }
}

}  // namespace smcbip::bipc::detail
