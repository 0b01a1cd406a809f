// The normalised text of properties: what golden files, reports and error messages show.
#include "monitors/property/ast.h"

namespace smcbip::monitors {

namespace {

// Binding strength of expression operators, loosest first; operands looser than their operator
// get parentheses.
enum ExprPrecedence : int { kComparison = 1, kAdditive, kMultiplicative, kNegate, kPrimary };

int precedence(const Expr& e) {
  switch (e.kind) {
    case Expr::Kind::Less:
    case Expr::Kind::LessEqual:
    case Expr::Kind::Greater:
    case Expr::Kind::GreaterEqual:
    case Expr::Kind::Equal:
    case Expr::Kind::NotEqual:
      return kComparison;
    case Expr::Kind::Add:
    case Expr::Kind::Subtract:
      return kAdditive;
    case Expr::Kind::Multiply:
    case Expr::Kind::Divide:
    case Expr::Kind::Modulo:
      return kMultiplicative;
    case Expr::Kind::Negate:
      return kNegate;
    default:
      return kPrimary;
  }
}

const char* expr_operator(Expr::Kind kind) {
  switch (kind) {
    case Expr::Kind::Add:
      return "+";
    case Expr::Kind::Subtract:
      return "-";
    case Expr::Kind::Multiply:
      return "*";
    case Expr::Kind::Divide:
      return "/";
    case Expr::Kind::Modulo:
      return "%";
    case Expr::Kind::Less:
      return "<";
    case Expr::Kind::LessEqual:
      return "<=";
    case Expr::Kind::Greater:
      return ">";
    case Expr::Kind::GreaterEqual:
      return ">=";
    case Expr::Kind::Equal:
      return "==";
    case Expr::Kind::NotEqual:
      return "!=";
    default:
      return "?";
  }
}

std::string parenthesised(std::string text, bool needed) {
  return needed ? "(" + text + ")" : text;
}

bool is_leaf(const Formula& f) {
  return f.kind == Formula::Kind::True || f.kind == Formula::Kind::False ||
         f.kind == Formula::Kind::Atom;
}

// The operand of a prefix operator: in parentheses unless it is a constant or a predicate
// without operators (`!deadlock`, `F[0,10] done`, `G (x > 2)`, `F (a && b)`).
std::string unary_operand(const Formula& operand) {
  const bool simple = operand.kind != Formula::Kind::Atom ? is_leaf(operand)
                                                          : precedence(*operand.atom) == kPrimary;
  return parenthesised(to_string(operand), !simple);
}

// The operands of a binary operator: in parentheses unless they are predicates or constants,
// whose operators all bind tighter than the formula's.
std::string binary(const Formula& f, const char* op) {
  const Formula& left = *f.operands[0];
  const Formula& right = *f.operands[1];
  return parenthesised(to_string(left), !is_leaf(left)) + " " + op + to_string(f.bound) + " " +
         parenthesised(to_string(right), !is_leaf(right));
}

const char* unit_suffix(TimeUnit unit) {
  switch (unit) {
    case TimeUnit::None:
      return "";
    case TimeUnit::Seconds:
      return "s";
    case TimeUnit::Milliseconds:
      return "ms";
    case TimeUnit::Microseconds:
      return "us";
    case TimeUnit::Nanoseconds:
      return "ns";
  }
  return "";
}

const char* comparison_text(Comparison c) {
  switch (c) {
    case Comparison::GreaterEqual:
      return ">=";
    case Comparison::Greater:
      return ">";
    case Comparison::LessEqual:
      return "<=";
    case Comparison::Less:
      return "<";
  }
  return ">=";
}

// A run bound inside brackets: `<=100`, `#<=50`.
std::string run_bound(const Bound& bound) {
  if (bound.kind == Bound::Kind::Steps) return "#<=" + to_string(bound.high);
  return "<=" + to_string(bound.high);
}

}  // namespace

std::string to_string(const Value& value) {
  if (value.is_name()) return value.name;
  return value.text + unit_suffix(value.unit);
}

std::string to_string(const Bound& bound) {
  switch (bound.kind) {
    case Bound::Kind::None:
      return "";
    case Bound::Kind::Time:
      return "[" + to_string(bound.low) + "," + to_string(bound.high) + "]";
    case Bound::Kind::Steps:
      return "{" + to_string(bound.high) + "}";
  }
  return "";
}

std::string to_string(const Expr& e) {
  switch (e.kind) {
    case Expr::Kind::Number:
      return to_string(e.value);
    case Expr::Kind::Bool:
      return e.boolean ? "true" : "false";
    case Expr::Kind::Name:
      return e.path;
    case Expr::Kind::Fired:
      return "fired(" + e.path + ")";
    case Expr::Kind::Negate:
      return "-" + parenthesised(to_string(*e.operands[0]), precedence(*e.operands[0]) < kNegate);
    case Expr::Kind::Call: {
      std::string out = e.path + "(";
      for (std::size_t i = 0; i < e.operands.size(); ++i) {
        out += (i == 0 ? "" : ", ") + to_string(*e.operands[i]);
      }
      return out + ")";
    }
    default:
      break;
  }
  // Binary: arithmetic is left-associative, comparisons do not chain.
  const int p = precedence(e);
  const Expr& left = *e.operands[0];
  const Expr& right = *e.operands[1];
  const bool comparison = p == kComparison;
  return parenthesised(to_string(left),
                       precedence(left) < p || (comparison && precedence(left) == p)) +
         " " + expr_operator(e.kind) + " " +
         parenthesised(to_string(right), precedence(right) <= p);
}

std::string to_string(const Formula& f) {
  switch (f.kind) {
    case Formula::Kind::True:
      return "true";
    case Formula::Kind::False:
      return "false";
    case Formula::Kind::Atom:
      return to_string(*f.atom);
    case Formula::Kind::Not:
      return "!" + unary_operand(*f.operands[0]);
    case Formula::Kind::Next:
      return "X " + unary_operand(*f.operands[0]);
    case Formula::Kind::Finally:
      return "F" + to_string(f.bound) + " " + unary_operand(*f.operands[0]);
    case Formula::Kind::Globally:
      return "G" + to_string(f.bound) + " " + unary_operand(*f.operands[0]);
    case Formula::Kind::And:
      return binary(f, "&&");
    case Formula::Kind::Or:
      return binary(f, "||");
    case Formula::Kind::Implies:
      return binary(f, "->");
    case Formula::Kind::Iff:
      return binary(f, "<->");
    case Formula::Kind::Until:
      return binary(f, "U");
    case Formula::Kind::Release:
      return binary(f, "R");
  }
  return "";
}

std::string to_string(const Query& q) {
  switch (q.kind) {
    case Query::Kind::Estimate:
      if (q.pr_form) return "Pr[" + run_bound(q.run) + "](" + to_string(*q.formula) + ")";
      return "P=? [ " + to_string(*q.formula) + " ]";
    case Query::Kind::Hypothesis: {
      const std::string threshold = to_string(q.threshold);
      if (q.pr_form) {
        return "Pr[" + run_bound(q.run) + "](" + to_string(*q.formula) + ") " +
               comparison_text(q.comparison) + " " + threshold;
      }
      return std::string("P") + comparison_text(q.comparison) + threshold + " [ " +
             to_string(*q.formula) + " ]";
    }
    case Query::Kind::Compare:
      return "Pr[" + run_bound(q.run) + "](" + to_string(*q.formula) + ") " +
             comparison_text(q.comparison) + " Pr[" + run_bound(q.other_run) + "](" +
             to_string(*q.other) + ")";
    case Query::Kind::Simulate: {
      std::string out = "simulate [" + run_bound(q.run) + "; " + to_string(q.runs) + "] { ";
      for (std::size_t i = 0; i < q.series.size(); ++i) {
        out += (i == 0 ? "" : ", ") + to_string(*q.series[i]);
      }
      return out + " }";
    }
    case Query::Kind::Invariant:
      return "A[] " + to_string(*q.formula);
    case Query::Kind::Reachable:
      return "E<> " + to_string(*q.formula);
    case Query::Kind::Expectation: {
      const std::string observed =
          std::string(observation_keyword(q.observe)) + ": " + to_string(*q.observed);
      if (!q.pr_form) return "E=? [ " + observed + " ]";
      return "E[" + run_bound(q.run) + "; " + to_string(q.runs) + "](" + observed + ")";
    }
  }
  return "";
}

namespace {

void names_in(const Value& v, std::set<std::string>& names) {
  if (v.is_name()) names.insert(v.name);
}
void names_in(const Bound& b, std::set<std::string>& names) {
  names_in(b.low, names);
  names_in(b.high, names);
}
void names_in(const Expr& e, std::set<std::string>& names) {
  if (e.kind == Expr::Kind::Name) names.insert(e.path);
  for (const auto& operand : e.operands) names_in(*operand, names);
}
void names_in(const Formula& f, std::set<std::string>& names) {
  names_in(f.bound, names);
  if (f.atom) names_in(*f.atom, names);
  for (const auto& operand : f.operands) names_in(*operand, names);
}

}  // namespace

std::set<std::string> names_read(const Query& q) {
  std::set<std::string> names;
  names_in(q.run, names);
  names_in(q.other_run, names);
  names_in(q.threshold, names);
  names_in(q.runs, names);
  if (q.formula) names_in(*q.formula, names);
  if (q.other) names_in(*q.other, names);
  if (q.observed) names_in(*q.observed, names);
  for (const auto& e : q.series) names_in(*e, names);
  return names;
}

const char* observation_keyword(Observation observe) {
  switch (observe) {
    case Observation::Max:
      return "max";
    case Observation::Min:
      return "min";
    case Observation::Last:
      return "last";
    case Observation::Integral:
      return "int";
    case Observation::Count:
      return "count";
  }
  return "max";
}

std::string to_string(const Declaration& d) {
  if (d.kind == Declaration::Kind::Constant) return "const " + d.name + " = " + to_string(d.value);
  std::string out = "param " + d.name + " = ";
  if (d.range) {
    return out + to_string(d.values[0]) + ":" + to_string(d.values[1]) + ":" +
           to_string(d.values[2]);
  }
  out += "{";
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    out += (i == 0 ? "" : ", ") + to_string(d.values[i]);
  }
  return out + "}";
}

}  // namespace smcbip::monitors
