#include "monitors/online/state_program.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace smcbip::monitors::online {
namespace {

// Arithmetic and comparisons map onto the codes in the order of Expr::Kind.
static_assert(static_cast<int>(Expr::Kind::NotEqual) - static_cast<int>(Expr::Kind::Negate) ==
              static_cast<int>(StateProgram::Code::NotEqual) -
                  static_cast<int>(StateProgram::Code::Negate));
static_assert(static_cast<int>(Expr::Kind::Less) - static_cast<int>(Expr::Kind::Negate) ==
              static_cast<int>(StateProgram::Code::Less) -
                  static_cast<int>(StateProgram::Code::Negate));

/// The stack depth the postfix program of `e` needs.
std::size_t depth(const Expr& e) {
  std::size_t most = 1;
  for (std::size_t k = 0; k < e.operands.size(); ++k) {
    most = std::max(most, k + depth(*e.operands[k]));
  }
  return most;
}

std::size_t depth(const Formula& f) {
  if (f.kind == Formula::Kind::Atom) return depth(*f.atom);
  std::size_t most = 1;
  for (std::size_t k = 0; k < f.operands.size(); ++k) {
    most = std::max(most, k + depth(*f.operands[k]));
  }
  // Implies is compiled as !a || b, Iff as (a || !b) and (!a || b): one more level each.
  return f.kind == Formula::Kind::Iff ? most + 2 : most;
}

bool state_formula(const Formula& f) {
  using K = Formula::Kind;
  switch (f.kind) {
    case K::True:
    case K::False:
      return true;
    case K::Atom:
      return reads_places_and_data_only(*f.atom);
    case K::Not:
    case K::And:
    case K::Or:
    case K::Implies:
    case K::Iff:
      return std::all_of(f.operands.begin(), f.operands.end(),
                         [](const auto& operand) { return state_formula(*operand); });
    default:
      return false;
  }
}

}  // namespace

bool StateProgram::accepts(const Formula& f) { return state_formula(f) && depth(f) <= kMaxDepth; }

StateProgram::StateProgram(const Formula& f, bool negated, const Bindings& bindings)
    : bindings_(&bindings) {
  formula(f, negated);
  bindings_ = nullptr;
  for (Code junction : {Code::And, Code::Or}) {
    if (joins_comparisons(ops_.size(), junction)) form_ = junction;
  }
  if (form_ != Code::Number) {
    for (const Op& op : ops_) {
      if (op.code != Code::Compare) continue;
      compares_.push_back(op);
      compares_.back().holds_when = holds_when_of(op.compare);
    }
  }
}

std::uint8_t StateProgram::holds_when_of(Code code) {
  std::uint8_t mask = 0;
  // One pair of values in each order: apply() says which orders the comparison holds in.
  const double unordered = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [x, y] : {std::pair{0.0, 1.0}, {1.0, 1.0}, {1.0, 0.0}, {unordered, 1.0}}) {
    if (apply(code, Op{}, x, y) != 0) mask |= static_cast<std::uint8_t>(order_bit(x, y));
  }
  return mask;
}

bool StateProgram::joins_comparisons(std::size_t n, Code junction) const {
  // Postfix read from the end: each instruction gives one of the values still needed, and a
  // junction needs two more.
  std::size_t needed = 1;
  for (std::size_t k = n; k-- > 0;) {
    if (needed == 0) return false;
    --needed;
    if (ops_[k].code == junction) {
      needed += 2;
    } else if (ops_[k].code != Code::Compare) {
      return false;
    }
  }
  return needed == 0;
}

bool StateProgram::is_load(Code code) {
  return code == Code::Data || code == Code::Int || code == Code::Bool || code == Code::Float ||
         code == Code::Place || code == Code::Name;
}

void StateProgram::push(Op op) {
  // A load compared with a number is one instruction.
  const std::size_t n = ops_.size();
  if (op.code >= Code::Less && op.code <= Code::NotEqual && n >= 2 &&
      ops_[n - 1].code == Code::Number && is_load(ops_[n - 2].code)) {
    Op fused = ops_[n - 2];
    fused.load = fused.code;
    fused.code = Code::Compare;
    fused.compare = op.code;
    fused.number = ops_[n - 1].number;
    ops_.resize(n - 2);
    depth_ -= 2;
    op = fused;
  }
  // Loads push a value; unary operators keep the depth; binary ones pop one.
  switch (op.code) {
    case Code::Number:
    case Code::Data:
    case Code::Int:
    case Code::Bool:
    case Code::Float:
    case Code::Place:
    case Code::Name:
    case Code::Initial:
    case Code::Compare:
      max_depth_ = std::max(max_depth_, ++depth_);
      break;
    case Code::Negate:
    case Code::Abs:
    case Code::Truth:
    case Code::Not:
      break;
    default:
      --depth_;
      break;
  }
  ops_.push_back(op);
}

void StateProgram::formula(const Formula& f, bool negated) {
  using K = Formula::Kind;
  auto operand = [&](std::size_t k, bool neg) { formula(*f.operands[k], neg); };
  auto binary = [&](Code code, bool a_neg, bool b_neg) {
    operand(0, a_neg);
    operand(1, b_neg);
    push({code});
  };
  switch (f.kind) {
    case K::True:
    case K::False:
      push({Code::Number, 0, 0, (f.kind == K::True) != negated ? 1.0 : 0.0});
      return;
    case K::Atom: {
      expression(*f.atom);
      // A comparison gives 1 or 0 already; != and == negate exactly (NaN included).
      Op& last = ops_.back();
      const Code code = last.code == Code::Compare ? last.compare : last.code;
      const bool truth = code >= Code::Less && code <= Code::NotEqual;
      if (negated && last.code == Code::Compare &&
          (code == Code::Equal || code == Code::NotEqual)) {
        last.compare = code == Code::Equal ? Code::NotEqual : Code::Equal;
      } else if (negated || !truth) {
        push({negated ? Code::Not : Code::Truth});
      }
      return;
    }
    case K::Not:
      operand(0, !negated);
      return;
    case K::And:  // !(a && b) = !a || !b
      binary(negated ? Code::Or : Code::And, negated, negated);
      return;
    case K::Or:
      binary(negated ? Code::And : Code::Or, negated, negated);
      return;
    case K::Implies:  // a -> b = !a || b; negated: a && !b
      binary(negated ? Code::And : Code::Or, !negated, negated);
      return;
    case K::Iff:  // a <-> b = (!a || b) && (a || !b); negated: (a || b) && (!a || !b)
      binary(Code::Or, true, negated);
      binary(Code::Or, false, !negated);
      push({Code::And});
      return;
    default:  // accepts() lets no temporal operator through
      return;
  }
}

void StateProgram::expression(const Expr& e) {
  using K = Expr::Kind;
  for (const auto& operand : e.operands) expression(*operand);
  Op op;
  op.expr = &e;
  switch (e.kind) {
    case K::Number:
      op.number = e.value.number;
      break;
    case K::Bool:
      op.number = e.boolean ? 1 : 0;
      break;
    case K::Name: {
      const Reference& r = e.reference;
      if (r.kind == Reference::Kind::Constant || r.kind == Reference::Kind::Unresolved) {
        const auto it = bindings_->find(e.path);
        if (it != bindings_->end()) {
          op.number = it->second;
          break;
        }
      }
      op.atom = r.atom;
      op.index = r.index;
      op.code = r.kind == Reference::Kind::Data      ? Code::Data
                : r.kind == Reference::Kind::Place   ? Code::Place
                : r.kind == Reference::Kind::Initial ? Code::Initial
                                                     : Code::Name;
      break;
    }
    case K::Fired:  // accepts() lets no event through
      op.code = Code::Name;
      break;
    case K::Call:
      op.code = e.path == "abs" ? Code::Abs : e.path == "min" ? Code::Min : Code::Max;
      break;
    default: {
      // The arithmetic and comparisons, in the order of Expr::Kind.
      const int offset = static_cast<int>(e.kind) - static_cast<int>(K::Negate);
      op.code = static_cast<Code>(static_cast<int>(Code::Negate) + offset);
      break;
    }
  }
  push(op);
}

}  // namespace smcbip::monitors::online
