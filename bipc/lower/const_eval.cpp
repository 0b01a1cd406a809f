// A small interpreter for constant stack code: folds package constants, component arguments
// and constant subexpressions at compile time.
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bipc/lower/detail/lowering.h"

namespace smcbip::bipc::lower {

using ir::Op;
using ir::Value;
using ir::ValueKind;

ir::Value convert_value(ir::Value value, ir::ValueKind to) {
  if (value.kind == ValueKind::Int && to == ValueKind::Float) {
    value.kind = ValueKind::Float;
    value.f = static_cast<double>(value.i);
  }
  return value;
}

ir::ValueKind value_kind(const ast::ValueType& type) {
  switch (type.kind) {
    case ast::ValueType::Kind::Bool:
      return ValueKind::Bool;
    case ast::ValueType::Kind::Int:
      return ValueKind::Int;
    case ast::ValueType::Kind::Float:
      return ValueKind::Float;
    case ast::ValueType::Kind::String:
      return ValueKind::String;
    case ast::ValueType::Kind::Extern:
      return ValueKind::Extern;
    case ast::ValueType::Kind::Error:
    case ast::ValueType::Kind::Void:
      break;
  }
  return ValueKind::Void;
}

namespace {

Value make_bool(bool b) {
  Value v;
  v.kind = ValueKind::Bool;
  v.b = b;
  return v;
}

Value make_int(std::int64_t i) {
  Value v;
  v.kind = ValueKind::Int;
  v.i = i;
  return v;
}

Value make_float(double f) {
  Value v;
  v.kind = ValueKind::Float;
  v.f = f;
  return v;
}

// Integer arithmetic wraps (two's complement) instead of overflowing, so folding is never
// undefined behaviour; division cases the hardware traps on are left to run time.
std::optional<std::int64_t> int_arith(Op op, std::int64_t a, std::int64_t b) {
  const auto ua = static_cast<std::uint64_t>(a);
  const auto ub = static_cast<std::uint64_t>(b);
  switch (op) {
    case Op::Add:
      return static_cast<std::int64_t>(ua + ub);
    case Op::Sub:
      return static_cast<std::int64_t>(ua - ub);
    case Op::Mul:
      return static_cast<std::int64_t>(ua * ub);
    case Op::Div:
    case Op::Mod:
      if (b == 0 || (a == std::numeric_limits<std::int64_t>::min() && b == -1)) return std::nullopt;
      return op == Op::Div ? a / b : a % b;
    case Op::BitAnd:
      return a & b;
    case Op::BitOr:
      return a | b;
    case Op::BitXor:
      return a ^ b;
    default:
      return std::nullopt;
  }
}

std::optional<double> float_arith(Op op, double a, double b) {
  switch (op) {
    case Op::Add:
      return a + b;
    case Op::Sub:
      return a - b;
    case Op::Mul:
      return a * b;
    case Op::Div:
      if (b == 0.0) return std::nullopt;  // the engine decides what x/0.0 means
      return a / b;
    case Op::Mod:
      if (b == 0.0) return std::nullopt;
      return std::fmod(a, b);
    default:
      return std::nullopt;
  }
}

template <typename T>
bool compare(Op op, const T& a, const T& b) {
  switch (op) {
    case Op::Eq:
      return a == b;
    case Op::Ne:
      return a != b;
    case Op::Lt:
      return a < b;
    case Op::Le:
      return a <= b;
    case Op::Gt:
      return a > b;
    default:
      return a >= b;
  }
}

std::optional<Value> comparison(Op op, const Value& a, const Value& b) {
  if (a.kind != b.kind) return std::nullopt;
  switch (a.kind) {
    case ValueKind::Bool:
      return make_bool(compare(op, a.b, b.b));
    case ValueKind::Int:
      return make_bool(compare(op, a.i, b.i));
    case ValueKind::Float:
      return make_bool(compare(op, a.f, b.f));
    case ValueKind::String:
      return make_bool(compare(op, a.s, b.s));
    default:
      return std::nullopt;
  }
}

std::optional<Value> arithmetic(Op op, const Value& a, const Value& b) {
  if (a.kind != b.kind) return std::nullopt;
  if (a.kind == ValueKind::Int) {
    if (auto r = int_arith(op, a.i, b.i)) return make_int(*r);
  } else if (a.kind == ValueKind::Float) {
    if (auto r = float_arith(op, a.f, b.f)) return make_float(*r);
  }
  return std::nullopt;
}

std::optional<Value> unary(Op op, const Value& a) {
  if (op == Op::Not && a.kind == ValueKind::Bool) return make_bool(!a.b);
  if (op == Op::BitNot && a.kind == ValueKind::Int) return make_int(~a.i);
  if (op == Op::Neg && a.kind == ValueKind::Int) return make_int(*int_arith(Op::Sub, 0, a.i));
  if (op == Op::Neg && a.kind == ValueKind::Float) return make_float(-a.f);
  if (op == Op::IntToFloat && a.kind == ValueKind::Int) return convert_value(a, ValueKind::Float);
  return std::nullopt;
}

/// One step of the interpreter over the value stack; false when the code is not constant.
class ConstMachine {
 public:
  ConstMachine(const std::vector<ir::Instr>& code, const std::vector<std::string>& strings)
      : code_(code), strings_(strings) {}

  std::optional<Value> run(std::size_t begin, std::size_t end) {
    std::size_t pc = begin;
    while (pc < end) {
      std::size_t next = pc + 1;
      if (!step(code_[pc], next)) return std::nullopt;
      // Compiled code only jumps forward; anything else is not ours and could loop.
      if (next <= pc || next > end) return std::nullopt;
      pc = next;
    }
    if (stack_.size() != 1) return std::nullopt;
    return stack_.back();
  }

 private:
  bool pop(Value& out) {
    if (stack_.empty()) return false;
    out = std::move(stack_.back());
    stack_.pop_back();
    return true;
  }

  bool push(std::optional<Value> value) {
    if (!value) return false;
    stack_.push_back(std::move(*value));
    return true;
  }

  bool push_literal(const ir::Instr& in) {
    switch (in.op) {
      case Op::PushBool:
        return push(make_bool(in.imm.b));
      case Op::PushInt:
        return push(make_int(in.imm.i));
      case Op::PushFloat:
        return push(make_float(in.imm.f));
      default:
        if (in.index >= strings_.size()) return false;
        Value v;
        v.kind = ValueKind::String;
        v.s = strings_[in.index];
        return push(std::move(v));
    }
  }

  bool binary(Op op) {
    Value b, a;
    if (!pop(b) || !pop(a)) return false;
    const bool is_comparison = op == Op::Eq || op == Op::Ne || op == Op::Lt || op == Op::Le ||
                               op == Op::Gt || op == Op::Ge;
    return push(is_comparison ? comparison(op, a, b) : arithmetic(op, a, b));
  }

  // Conditional jumps: `Keep` variants leave the tested value when they jump (short circuit).
  bool conditional(const ir::Instr& in, std::size_t& next) {
    if (stack_.empty() || stack_.back().kind != ValueKind::Bool) return false;
    const bool value = stack_.back().b;
    const bool jump_on = in.op == Op::JumpIfTrueKeep;
    if (in.op == Op::JumpIfFalse) {
      stack_.pop_back();
      if (!value) next = in.index;
      return true;
    }
    if (value == jump_on) {
      next = in.index;
    } else {
      stack_.pop_back();
    }
    return true;
  }

  bool step(const ir::Instr& in, std::size_t& next) {
    switch (in.op) {
      case Op::PushBool:
      case Op::PushInt:
      case Op::PushFloat:
      case Op::PushString:
        return push_literal(in);
      case Op::Neg:
      case Op::Not:
      case Op::BitNot:
      case Op::IntToFloat: {
        Value a;
        return pop(a) && push(unary(in.op, a));
      }
      case Op::Add:
      case Op::Sub:
      case Op::Mul:
      case Op::Div:
      case Op::Mod:
      case Op::BitAnd:
      case Op::BitOr:
      case Op::BitXor:
      case Op::Eq:
      case Op::Ne:
      case Op::Lt:
      case Op::Le:
      case Op::Gt:
      case Op::Ge:
        return binary(in.op);
      case Op::Jump:
        next = in.index;
        return true;
      case Op::JumpIfFalse:
      case Op::JumpIfFalseKeep:
      case Op::JumpIfTrueKeep:
        return conditional(in, next);
      case Op::Pop: {
        Value ignored;
        return pop(ignored);
      }
      case Op::Load:
      case Op::Store:
      case Op::StoreRate:
      case Op::Call:
        return false;  // state or side effects: not a constant
    }
    return false;
  }

  const std::vector<ir::Instr>& code_;
  const std::vector<std::string>& strings_;
  std::vector<Value> stack_;
};

}  // namespace

std::optional<ir::Value> evaluate_constant(const std::vector<ir::Instr>& code, std::size_t begin,
                                           std::size_t end,
                                           const std::vector<std::string>& strings) {
  if (begin > end || end > code.size()) return std::nullopt;
  return ConstMachine(code, strings).run(begin, end);
}

}  // namespace smcbip::bipc::lower
