// The timed-automata forms of guards over clocks (the Verimag compiler's time constraints):
// comparisons of one clock, or of the difference of two, with a clock-free number, joined by &&
// (and by || when only one side has clocks); never `!=`, never under `!`, never scaled.
#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using ast::BinaryOp;
using ast::UnaryOp;

struct ClockTerm {
  const ast::Expr* clock;
  int sign;  // of the term once everything is moved to the left-hand side
};

bool is_binary(const ast::Expr& expr, BinaryOp op) {
  return expr.kind == ast::Expr::Kind::Binary && expr.binary == op && expr.operands.size() == 2 &&
         expr.operands[0] && expr.operands[1];
}

bool is_comparison(const ast::Expr& expr) {
  return is_binary(expr, BinaryOp::Eq) || is_binary(expr, BinaryOp::Ne) ||
         is_binary(expr, BinaryOp::Lt) || is_binary(expr, BinaryOp::Gt) ||
         is_binary(expr, BinaryOp::Le) || is_binary(expr, BinaryOp::Ge);
}

/// Collects the clocks of a sum or difference with their signs; returns the first clock used
/// otherwise (scaled, passed to a function, compared), or nullptr when all are plain terms.
const ast::Expr* collect_terms(const ast::Expr& expr, int sign, std::vector<ClockTerm>& terms) {
  if (!mentions_clock(expr)) return nullptr;
  if (expr.kind == ast::Expr::Kind::Name) {
    terms.push_back({&expr, sign});
    return nullptr;
  }
  if (is_binary(expr, BinaryOp::Add) || is_binary(expr, BinaryOp::Sub)) {
    const int right = is_binary(expr, BinaryOp::Sub) ? -sign : sign;
    if (const ast::Expr* bad = collect_terms(*expr.operands[0], sign, terms)) return bad;
    return collect_terms(*expr.operands[1], right, terms);
  }
  if (expr.kind == ast::Expr::Kind::Unary && !expr.operands.empty() && expr.operands[0] &&
      (expr.unary == UnaryOp::Minus || expr.unary == UnaryOp::Plus)) {
    return collect_terms(*expr.operands[0], expr.unary == UnaryOp::Minus ? -sign : sign, terms);
  }
  return first_clock(expr);
}

void report_form(const ast::Expr& clock, Diagnostics& diags) {
  const std::string name = clock.name.text();
  diags.error(clock.loc, "clock '" + name +
                             "' can only be compared with a clock-free int or float expression ('" +
                             name +
                             " < e', '<=', '==', '>=', '>', or a difference of two clocks "
                             "'" +
                             name + " - y < e'), such comparisons joined by && and ||");
}

void check_comparison(const ast::Expr& expr, const ast::Expr& clock, Diagnostics& diags) {
  if (expr.binary == BinaryOp::Ne) {
    diags.error(start_of(expr),
                "'!=' cannot compare clock '" + clock.name.text() + "': use <, <=, ==, >= or >");
    return;
  }
  std::vector<ClockTerm> terms;
  const ast::Expr* bad = collect_terms(*expr.operands[0], 1, terms);
  if (bad == nullptr) bad = collect_terms(*expr.operands[1], -1, terms);
  if (bad != nullptr) {
    report_form(*bad, diags);
  } else if (terms.size() > 2) {
    diags.error(start_of(expr), "a clock constraint can compare at most two clocks");
  } else if (terms.size() == 2 && terms[0].sign == terms[1].sign) {
    diags.error(start_of(expr),
                "clocks '" + terms[0].clock->name.text() + "' and '" + terms[1].clock->name.text() +
                    "' can only be compared through their difference ('" +
                    terms[0].clock->name.text() + " - " + terms[1].clock->name.text() +
                    " < e' or '" + terms[0].clock->name.text() + " < " +
                    terms[1].clock->name.text() + " + e')");
  }
}

}  // namespace

void check_clock_constraints(const ast::Expr& expr, Diagnostics& diags) {
  const ast::Expr* clock = first_clock(expr);
  if (clock == nullptr) return;
  if (is_binary(expr, BinaryOp::And)) {
    check_clock_constraints(*expr.operands[0], diags);
    check_clock_constraints(*expr.operands[1], diags);
  } else if (is_binary(expr, BinaryOp::Or)) {
    if (mentions_clock(*expr.operands[0]) && mentions_clock(*expr.operands[1])) {
      diags.error(start_of(expr),
                  "clocks can appear on one side of '||' only: a disjunction of "
                  "clock constraints is not a timed-automaton guard");
      return;
    }
    check_clock_constraints(*expr.operands[0], diags);
    check_clock_constraints(*expr.operands[1], diags);
  } else if (expr.kind == ast::Expr::Kind::Unary && expr.unary == UnaryOp::Not) {
    diags.error(start_of(expr), "negation '!' cannot apply to a constraint on clock '" +
                                    clock->name.text() +
                                    "': write the opposite comparison instead");
  } else if (is_comparison(expr)) {
    check_comparison(expr, *clock, diags);
  } else {
    report_form(*clock, diags);
  }
}

}  // namespace smcbip::bipc::detail
