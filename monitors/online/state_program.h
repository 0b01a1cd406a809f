// A state formula (true, false, predicates over places and data, and the boolean connectives
// between them) compiled once into a postfix program, so that judging a state costs a few
// loads and comparisons rather than a walk of the expression trees.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "monitors/online/online_monitor.h"

namespace smcbip::monitors::online {

class StateProgram {
 public:
  /// What an instruction does. Loads push a value; the others pop their operands and push
  /// their result.
  enum class Code : std::uint8_t {
    Number,   // push `number`
    Data,     // a data slot whose kind is not bound yet (bind_data)
    Int,      // data slot `index` of atom `atom`, read as an integer (or a string's id)
    Bool,     // ... read as a boolean
    Float,    // ... read as a float
    Place,    // 1 when atom `atom` marks place `index`
    Name,     // any other name: the reader's value of `expr`
    Initial,  // 1 in the run's first state
    Negate,
    Add,
    Subtract,
    Multiply,
    Divide,  // throws MonitorError at `expr` on a zero divisor, as evaluate does
    Modulo,
    Less,
    LessEqual,
    Greater,
    GreaterEqual,
    Equal,
    NotEqual,
    Abs,
    Min,
    Max,
    Truth,  // 1 when the value is not 0 (an atomic predicate's truth)
    Not,
    And,
    Or,
    Compare,  // push the comparison `compare` of the load `load` with `number`
  };
  struct Op {
    Code code = Code::Number;
    std::uint32_t atom = 0, index = 0;
    double number = 0;
    const Expr* expr = nullptr;  // Name, Data, Divide, Modulo; Compare: the load's
    Code load = Code::Number;    // Compare: what is loaded (a load code)
    Code compare = Code::Equal;  // Compare: Less ... NotEqual
    std::size_t offset = 0;      // Int, Bool, Float, Place: where a bound reader finds it
    /// A Compare of compares_: the orders of the load to `number` it holds in, a bit each
    /// (order_bit).
    std::uint8_t holds_when = 0;
  };
  /// The kind of a data slot as the model declares it (Int also for strings and externs).
  enum class DataKind : std::uint8_t { Int, Bool, Float };

  /// Whether `f` is a state formula over places, data, constants and `init` only, small
  /// enough for the program's fixed stack.
  static bool accepts(const Formula& f);

  /// The program of `f` (accepts(f)), negated when `negated`; names bound in `bindings` are
  /// read from there, as evaluate reads them.
  StateProgram(const Formula& f, bool negated, const Bindings& bindings);
  /// The program of `true`.
  StateProgram() : ops_{Op{Code::Number, 0, 0, 1.0, nullptr}}, bindings_(nullptr) {}

  /// Binds every Data load to its kind: `kind_of(atom, slot)` gives it.
  template <class KindOf>
  void bind_data(const KindOf& kind_of) {
    for (std::vector<Op>* ops : {&ops_, &compares_}) {
      for (Op& op : *ops) bind(op, kind_of);
    }
  }
  /// Binds every Int, Bool, Float and Place load to where it is read: `data_offset(atom, slot)`
  /// and `place_offset(atom, place)` give it (after bind_data).
  template <class DataOffset, class PlaceOffset>
  void bind_offsets(const DataOffset& data_offset, const PlaceOffset& place_offset) {
    for (std::vector<Op>* ops : {&ops_, &compares_}) {
      for (Op& op : *ops) {
        const Code code = op.code == Code::Compare ? op.load : op.code;
        if (code == Code::Int || code == Code::Bool || code == Code::Float) {
          op.offset = data_offset(op.atom, op.index);
        } else if (code == Code::Place) {
          op.offset = place_offset(op.atom, op.index);
        }
      }
    }
  }
  template <class KindOf>
  static void bind(Op& op, const KindOf& kind_of) {
    Code& code = op.code == Code::Compare ? op.load : op.code;
    if (code != Code::Data && code != Code::Int && code != Code::Bool && code != Code::Float) {
      return;
    }
    const DataKind kind = kind_of(op.atom, op.index);
    code = kind == DataKind::Bool ? Code::Bool : kind == DataKind::Float ? Code::Float : Code::Int;
  }

  /// The formula's truth in a state. `read.load(code, op)` gives the value of the load `code`
  /// (Data, Int, Bool, Float, Place, Name) that `op` describes; `initial`: the state is the
  /// run's first.
  /// Inline for comparisons joined by && or || (the most frequent formulas), whose loop needs
  /// no stack; the general program runs out of line.
  template <class Reader>
  [[gnu::always_inline]] bool holds(const Reader& read, bool initial) const {
    if (form_ == Code::And) {
      for (const Op& op : compares_) {
        if (!compare(read, op)) return false;
      }
      return true;
    }
    if (form_ == Code::Or) {
      for (const Op& op : compares_) {
        if (compare(read, op)) return true;
      }
      return false;
    }
    return holds_postfix(read, initial);
  }

  static constexpr std::size_t kMaxDepth = 32;

 private:
  void formula(const Formula& f, bool negated);
  void expression(const Expr& e);
  void push(Op op);
  static double apply(Code code, const Op& op, double x, double y);
  static bool is_load(Code code);

  /// holds() for any program: its postfix form over a stack.
  template <class Reader>
  [[gnu::noinline]] bool holds_postfix(const Reader& read, bool initial) const;

  /// Whether the first `n` instructions are comparisons joined by `junction` only.
  bool joins_comparisons(std::size_t n, Code junction) const;
  /// The bit of Op::holds_when for the order of x to y: less, equal, greater, unordered (NaN).
  static unsigned order_bit(double x, double y) {
    return x < y ? 1u : x == y ? 2u : x > y ? 4u : 8u;
  }
  /// Op::holds_when of the comparison `code` (Less ... NotEqual), as apply() decides it.
  static std::uint8_t holds_when_of(Code code);
  /// A comparison of compares_, without a branch on its operator.
  template <class Reader>
  static bool compare(const Reader& read, const Op& op) {
    return (op.holds_when & order_bit(read.load(op.load, op), op.number)) != 0;
  }

  std::vector<Op> ops_;
  std::vector<Op> compares_;  // And, Or: the comparisons of ops_, in order
  /// And: the program is comparisons joined by &&, read until one fails (none can throw);
  /// Or: by ||, likewise; Number: any other program.
  Code form_ = Code::Number;
  const Bindings* bindings_;  // during construction only
  std::size_t depth_ = 0, max_depth_ = 0;
};

template <class Reader>
bool StateProgram::holds_postfix(const Reader& read, bool initial) const {
  std::array<double, kMaxDepth> stack;
  std::size_t top = 0;  // the number of values on the stack
  for (const Op& op : ops_) {
    switch (op.code) {
      case Code::Number:
        stack[top++] = op.number;
        break;
      case Code::Initial:
        stack[top++] = initial ? 1 : 0;
        break;
      case Code::Data:
      case Code::Int:
      case Code::Bool:
      case Code::Float:
      case Code::Place:
      case Code::Name:
        stack[top++] = read.load(op.code, op);
        break;
      case Code::Compare:  // a predicate `name op number`, the most frequent
        stack[top++] = apply(op.compare, op, read.load(op.load, op), op.number);
        break;
      case Code::Negate:
        stack[top - 1] = -stack[top - 1];
        break;
      case Code::Abs:
        stack[top - 1] = std::abs(stack[top - 1]);
        break;
      case Code::Truth:
        stack[top - 1] = stack[top - 1] != 0 ? 1 : 0;
        break;
      case Code::Not:
        stack[top - 1] = stack[top - 1] == 0 ? 1 : 0;
        break;
      case Code::And:
        --top;
        stack[top - 1] = stack[top - 1] != 0 && stack[top] != 0 ? 1 : 0;
        break;
      default:
        --top;
        stack[top - 1] = apply(op.code, op, stack[top - 1], stack[top]);
        break;
    }
  }
  return stack[0] != 0;
}

inline double StateProgram::apply(Code code, const Op& op, double x, double y) {
  switch (code) {
    case Code::Add:
      return x + y;
    case Code::Subtract:
      return x - y;
    case Code::Multiply:
      return x * y;
    case Code::Divide:
      return divide(*op.expr, x, y);
    case Code::Modulo:
      return remainder(*op.expr, x, y);
    case Code::Less:
      return x < y ? 1 : 0;
    case Code::LessEqual:
      return x <= y ? 1 : 0;
    case Code::Greater:
      return x > y ? 1 : 0;
    case Code::GreaterEqual:
      return x >= y ? 1 : 0;
    case Code::Equal:
      return x == y ? 1 : 0;
    case Code::NotEqual:
      return x != y ? 1 : 0;
    case Code::Min:
      return std::min(x, y);
    case Code::Max:
      return std::max(x, y);
    case Code::Or:
      return x != 0 || y != 0 ? 1 : 0;
    case Code::And:
      return x != 0 && y != 0 ? 1 : 0;
    default:
      return 0;
  }
}

}  // namespace smcbip::monitors::online
