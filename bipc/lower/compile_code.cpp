// Compiles checked expressions and statements to the IR's stack code, folding constants.
#include <charconv>
#include <string>
#include <system_error>
#include <vector>

#include "bipc/lower/detail/lowering.h"

namespace smcbip::bipc::lower {

using ir::Op;
using ir::ValueKind;

namespace {

ir::Instr make(Op op, ValueKind kind = ValueKind::Int) {
  ir::Instr in;
  in.op = op;
  in.kind = kind;
  return in;
}

ir::Instr access(Op op, ir::Scope scope, ir::Index index, ir::Index arg, ValueKind kind) {
  ir::Instr in = make(op, kind);
  in.scope = scope;
  in.index = index;
  in.arg = static_cast<std::uint16_t>(arg);
  return in;
}

/// Turns an integer literal into a float literal, which is what a conversion of it would give.
void push_float(ir::Instr& in) {
  const double value = static_cast<double>(in.imm.i);
  in.op = Op::PushFloat;
  in.kind = ValueKind::Float;
  in.imm.f = value;
}

/// Inserts an int-to-float conversion at `at`, moving the jumps of the code after it along.
/// `begin` is where the converted operand starts: a lone literal is converted in place.
void insert_conversion(std::vector<ir::Instr>& out, std::size_t begin, std::size_t at) {
  if (at == begin + 1 && out[begin].op == Op::PushInt) {
    push_float(out[begin]);
    return;
  }
  for (std::size_t i = at; i < out.size(); ++i) {
    if (ir::is_jump(out[i].op) && out[i].index >= at) ++out[i].index;
  }
  out.insert(out.begin() + static_cast<std::ptrdiff_t>(at), make(Op::IntToFloat, ValueKind::Float));
}

/// Converts the value the code ends with. An int expression that ends with a literal is that
/// literal alone (BIP has no conditional expressions), so the literal itself is converted.
void convert_at_end(std::vector<ir::Instr>& out, ValueKind from, ValueKind to) {
  if (from != ValueKind::Int || to != ValueKind::Float) return;
  if (!out.empty() && out.back().op == Op::PushInt) {
    push_float(out.back());
  } else {
    out.push_back(make(Op::IntToFloat, ValueKind::Float));
  }
}

bool is_comparison(ast::BinaryOp op) {
  using B = ast::BinaryOp;
  return op == B::Eq || op == B::Ne || op == B::Lt || op == B::Gt || op == B::Le || op == B::Ge;
}

bool is_bitwise(ast::BinaryOp op) {
  using B = ast::BinaryOp;
  return op == B::BitAnd || op == B::BitOr || op == B::BitXor;
}

Op binary_op(ast::BinaryOp op) {
  switch (op) {
    case ast::BinaryOp::BitOr:
      return Op::BitOr;
    case ast::BinaryOp::BitXor:
      return Op::BitXor;
    case ast::BinaryOp::BitAnd:
      return Op::BitAnd;
    case ast::BinaryOp::Eq:
      return Op::Eq;
    case ast::BinaryOp::Ne:
      return Op::Ne;
    case ast::BinaryOp::Lt:
      return Op::Lt;
    case ast::BinaryOp::Gt:
      return Op::Gt;
    case ast::BinaryOp::Le:
      return Op::Le;
    case ast::BinaryOp::Ge:
      return Op::Ge;
    case ast::BinaryOp::Add:
      return Op::Add;
    case ast::BinaryOp::Sub:
      return Op::Sub;
    case ast::BinaryOp::Mul:
      return Op::Mul;
    case ast::BinaryOp::Div:
      return Op::Div;
    case ast::BinaryOp::Mod:
    default:
      return Op::Mod;
  }
}

/// The slot an assignment target or a name denotes, when it is one code can store to.
struct Slot {
  ir::Scope scope = ir::Scope::AtomData;
  ir::Index index = 0;
  ir::Index arg = 0;
};

std::optional<Slot> writable_slot(const ast::Resolution& ref) {
  if (ref.index < 0) return std::nullopt;
  const auto index = static_cast<ir::Index>(ref.index);
  switch (ref.kind) {
    case ast::RefKind::AtomData:
      return Slot{ir::Scope::AtomData, index, 0};
    case ast::RefKind::AtomClock:
      return Slot{ir::Scope::Clock, index, 0};
    case ast::RefKind::ConnectorData:
      return Slot{ir::Scope::ConnectorData, index, 0};
    case ast::RefKind::PortParam:
      if (ref.sub < 0) return std::nullopt;
      return Slot{ir::Scope::PortParam, index, static_cast<ir::Index>(ref.sub)};
    default:
      return std::nullopt;
  }
}

}  // namespace

ir::Code CodeCompiler::expression(const ast::Expr* e, ValueKind expected) {
  ir::Code code;
  if (e == nullptr) return code;
  const Shape shape = expr(*e, code.instrs);
  if (expected != ValueKind::Void) convert_at_end(code.instrs, shape.kind, expected);
  return code;
}

ir::Code CodeCompiler::block(const ast::Block& block) {
  ir::Code code;
  for (const ast::StatementPtr& s : block) {
    if (s) statement(*s, code.instrs);
  }
  return code;
}

CodeCompiler::Shape CodeCompiler::expr(const ast::Expr& e, Instrs& out) {
  ir::Instr in;
  switch (e.kind) {
    case ast::Expr::Kind::Int:
      in = make(Op::PushInt, ValueKind::Int);
      in.imm.i = e.int_value;
      out.push_back(in);
      return {ValueKind::Int, true};
    case ast::Expr::Kind::Float:
      in = make(Op::PushFloat, ValueKind::Float);
      in.imm.f = e.float_value;
      out.push_back(in);
      return {ValueKind::Float, true};
    case ast::Expr::Kind::Bool:
      in = make(Op::PushBool, ValueKind::Bool);
      in.imm.b = e.bool_value;
      out.push_back(in);
      return {ValueKind::Bool, true};
    case ast::Expr::Kind::String:
      in = make(Op::PushString, ValueKind::String);
      in.index = lowering_.string(e.string_value);
      out.push_back(in);
      return {ValueKind::String, true};
    case ast::Expr::Kind::Name:
      return name(e, out);
    case ast::Expr::Kind::Call:
    case ast::Expr::Kind::Unary:
    case ast::Expr::Kind::Binary:
      // Extern functions, and operators declared on extern types, are both calls.
      if (e.function != nullptr) return call(e, *e.function, out);
      if (e.kind == ast::Expr::Kind::Unary) return unary(e, out);
      if (e.kind == ast::Expr::Kind::Binary) return binary(e, out);
      break;
    case ast::Expr::Kind::Prime:
      break;
  }
  lowering_.internal_error(e.loc, "expression without a resolved meaning");
  out.push_back(make(Op::PushInt));  // keeps the stack shape of the rest of the code
  return {ValueKind::Int, false};
}

CodeCompiler::Shape CodeCompiler::push_value(const ir::Value& value, Instrs& out) {
  ir::Instr in = make(Op::PushInt, value.kind);
  switch (value.kind) {
    case ValueKind::Bool:
      in.op = Op::PushBool;
      in.imm.b = value.b;
      break;
    case ValueKind::Float:
      in.op = Op::PushFloat;
      in.imm.f = value.f;
      break;
    case ValueKind::String:
      in.op = Op::PushString;
      in.index = lowering_.string(value.s);
      break;
    default:
      in.imm.i = value.i;
      break;
  }
  out.push_back(in);
  return {value.kind, true};
}

CodeCompiler::Shape CodeCompiler::name(const ast::Expr& e, Instrs& out) {
  const ast::Resolution& ref = e.ref;
  const ValueKind kind = value_kind(e.type);
  switch (ref.kind) {
    case ast::RefKind::ConstData:
      if (ref.const_data != nullptr) {
        if (auto value = lowering_.constant(*ref.const_data)) return push_value(*value, out);
        out.push_back(make(Op::PushInt));  // reported by constant()
        return {ValueKind::Int, false};
      }
      break;
    case ast::RefKind::CompoundParam:
      if (const ir::Value* value = bindings_ ? bindings_->compound_param(ref.index) : nullptr) {
        return push_value(*value, out);
      }
      break;
    case ast::RefKind::ComponentData:
      if (bindings_ != nullptr) {
        if (auto slot = bindings_->component_data(ref.index, ref.member)) {
          const ir::Index data = check_arg(slot->second, e.loc);
          out.push_back(access(Op::Load, ir::Scope::InstanceData, slot->first, data, kind));
          return {kind, false};
        }
      }
      break;
    case ast::RefKind::AtomParam:
      if (ref.index >= 0) {
        out.push_back(
            access(Op::Load, ir::Scope::AtomParam, static_cast<ir::Index>(ref.index), 0, kind));
        return {kind, false};
      }
      break;
    default:
      if (auto slot = writable_slot(ref)) {
        // Clocks read as real numbers whatever the checker called them.
        const ValueKind slot_kind = slot->scope == ir::Scope::Clock ? ValueKind::Float : kind;
        out.push_back(
            access(Op::Load, slot->scope, slot->index, check_arg(slot->arg, e.loc), slot_kind));
        return {slot_kind, false};
      }
      break;
  }
  lowering_.internal_error(e.loc, "unresolved name '" + e.name.text() + "'");
  out.push_back(make(Op::PushInt));
  return {ValueKind::Int, false};
}

CodeCompiler::Shape CodeCompiler::call(const ast::Expr& e, const ast::ExternFunctionDecl& f,
                                       Instrs& out) {
  for (std::size_t i = 0; i < e.operands.size(); ++i) {
    const Shape arg = expr(*e.operands[i], out);
    if (i < f.params.size()) convert_at_end(out, arg.kind, value_kind(f.params[i].type.resolved));
  }
  const ValueKind result = f.result ? value_kind(f.result->resolved) : ValueKind::Void;
  ir::Instr in = make(Op::Call, result);
  in.index = lowering_.function(f);
  in.arg = static_cast<std::uint16_t>(check_arg(e.operands.size(), e.loc));
  in.site = lowering_.site(e.loc);
  out.push_back(in);
  return {result, false};
}

CodeCompiler::Shape CodeCompiler::unary(const ast::Expr& e, Instrs& out) {
  if (e.operands.size() != 1) {
    lowering_.internal_error(e.loc, "malformed unary expression");
    out.push_back(make(Op::PushInt));
    return {ValueKind::Int, false};
  }
  const std::size_t begin = out.size();
  Shape shape = expr(*e.operands[0], out);
  switch (e.unary) {
    case ast::UnaryOp::Plus:
      return shape;
    case ast::UnaryOp::Minus:
      out.push_back(make(Op::Neg, shape.kind));
      break;
    case ast::UnaryOp::Not:
      out.push_back(make(Op::Not, ValueKind::Bool));
      shape.kind = ValueKind::Bool;
      break;
    case ast::UnaryOp::BitNot:
      out.push_back(make(Op::BitNot, ValueKind::Int));
      shape.kind = ValueKind::Int;
      break;
  }
  fold(begin, shape, out);
  return shape;
}

CodeCompiler::Shape CodeCompiler::binary(const ast::Expr& e, Instrs& out) {
  if (e.operands.size() != 2) {
    lowering_.internal_error(e.loc, "malformed binary expression");
    out.push_back(make(Op::PushInt));
    return {ValueKind::Int, false};
  }
  if (e.binary == ast::BinaryOp::And || e.binary == ast::BinaryOp::Or) return logical(e, out);
  const std::size_t begin = out.size();
  const Shape lhs = expr(*e.operands[0], out);
  const std::size_t lhs_end = out.size();
  const Shape rhs = expr(*e.operands[1], out);

  // Mixed int/float operands compute in float: convert the int side where it was pushed.
  ValueKind kind = lhs.kind;
  if (!is_bitwise(e.binary)) {
    if (lhs.kind == ValueKind::Int && rhs.kind == ValueKind::Float) {
      insert_conversion(out, begin, lhs_end);
      kind = ValueKind::Float;
    } else if (lhs.kind == ValueKind::Float && rhs.kind == ValueKind::Int) {
      convert_at_end(out, rhs.kind, ValueKind::Float);
    }
  }
  ir::Instr operation = make(binary_op(e.binary), kind);
  if (operation.op == Op::Div || operation.op == Op::Mod) operation.site = lowering_.site(e.loc);
  out.push_back(operation);
  const Shape shape{is_comparison(e.binary) ? ValueKind::Bool : kind, lhs.constant && rhs.constant};
  fold(begin, shape, out);
  return shape;
}

CodeCompiler::Shape CodeCompiler::logical(const ast::Expr& e, Instrs& out) {
  const std::size_t begin = out.size();
  const Shape lhs = expr(*e.operands[0], out);
  const std::size_t jump = out.size();
  out.push_back(make(e.binary == ast::BinaryOp::And ? Op::JumpIfFalseKeep : Op::JumpIfTrueKeep,
                     ValueKind::Bool));
  const Shape rhs = expr(*e.operands[1], out);
  out[jump].index = static_cast<ir::Index>(out.size());
  const Shape shape{ValueKind::Bool, lhs.constant && rhs.constant};
  fold(begin, shape, out);
  return shape;
}

ir::Index CodeCompiler::check_arg(std::size_t value, Location at) {
  if (value <= 0xFFFF) return static_cast<ir::Index>(value);
  lowering_.diags().error(at,
                          "more than 65535 data, port parameters or call arguments: not supported");
  return 0;
}

void CodeCompiler::fold(std::size_t begin, Shape shape, Instrs& out) {
  if (!shape.constant || out.size() - begin <= 1) return;
  std::optional<ir::Value> value =
      evaluate_constant(out, begin, out.size(), lowering_.system().strings);
  if (!value) return;  // e.g. a division by zero: left for the engine to report
  out.resize(begin);
  push_value(*value, out);
}

void CodeCompiler::statement(const ast::Statement& s, Instrs& out) {
  switch (s.kind) {
    case ast::Statement::Kind::Assign:
      assignment(s, out);
      return;
    case ast::Statement::Kind::Call:
      if (s.value) {
        const Shape shape = expr(*s.value, out);
        if (shape.kind != ValueKind::Void) out.push_back(make(Op::Pop, shape.kind));
      }
      return;
    case ast::Statement::Kind::If:
      if_statement(s, out);
      return;
  }
}

void CodeCompiler::assignment(const ast::Statement& s, Instrs& out) {
  if (!s.target || !s.value) {
    lowering_.internal_error(s.loc, "malformed assignment");
    return;
  }
  const ast::Expr& target = *s.target;
  const bool rate = target.kind == ast::Expr::Kind::Prime && target.operands.size() == 1;
  const ast::Expr& name = rate ? *target.operands[0] : target;
  std::optional<Slot> slot = writable_slot(name.ref);
  if (name.kind != ast::Expr::Kind::Name || !slot || (rate && slot->scope != ir::Scope::Clock)) {
    lowering_.internal_error(target.loc, "assignment to something that is not a variable");
    return;
  }
  const bool to_clock = slot->scope == ir::Scope::Clock;
  const ValueKind kind = to_clock ? ValueKind::Float : value_kind(name.type);
  const Shape value = expr(*s.value, out);
  convert_at_end(out, value.kind, kind);
  if (rate) {
    ir::Instr in = make(Op::StoreRate, ValueKind::Float);
    in.index = slot->index;
    out.push_back(in);
    return;
  }
  out.push_back(access(Op::Store, slot->scope, slot->index, check_arg(slot->arg, s.loc), kind));
}

void CodeCompiler::if_statement(const ast::Statement& s, Instrs& out) {
  if (!s.value) {
    lowering_.internal_error(s.loc, "if without a condition");
    return;
  }
  expr(*s.value, out);
  const std::size_t skip_then = out.size();
  out.push_back(make(Op::JumpIfFalse, ValueKind::Bool));
  for (const ast::StatementPtr& inner : s.then_branch) {
    if (inner) statement(*inner, out);
  }
  if (s.else_branch.empty()) {
    out[skip_then].index = static_cast<ir::Index>(out.size());
    return;
  }
  const std::size_t skip_else = out.size();
  out.push_back(make(Op::Jump, ValueKind::Void));
  out[skip_then].index = static_cast<ir::Index>(out.size());
  for (const ast::StatementPtr& inner : s.else_branch) {
    if (inner) statement(*inner, out);
  }
  out[skip_else].index = static_cast<ir::Index>(out.size());
}

std::optional<ir::Code> CodeCompiler::stochastic_param(const std::string& raw,
                                                       const ast::AtomTypeDecl& atom) {
  const auto first = raw.find_first_not_of(" \t");
  if (first == std::string::npos) return std::nullopt;
  const std::string text = raw.substr(first, raw.find_last_not_of(" \t") - first + 1);
  ir::Code code;
  double number = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, number);
  if (ec == std::errc() && ptr == end) {
    ir::Instr in = make(Op::PushFloat, ValueKind::Float);
    in.imm.f = number;
    code.instrs.push_back(in);
    return code;
  }
  // A name: an atom parameter first, then data, as the Verimag SBIP tools look them up.
  auto numeric = [](ValueKind k) { return k == ValueKind::Int || k == ValueKind::Float; };
  for (std::size_t i = 0; i < atom.params.size(); ++i) {
    const ValueKind kind = value_kind(atom.params[i].type.resolved);
    if (atom.params[i].name.text != text || !numeric(kind)) continue;
    code.instrs.push_back(
        access(Op::Load, ir::Scope::AtomParam, static_cast<ir::Index>(i), 0, kind));
    convert_at_end(code.instrs, kind, ValueKind::Float);
    return code;
  }
  for (std::size_t i = 0; i < atom.data.size(); ++i) {
    const ValueKind kind = value_kind(atom.data[i].type.resolved);
    if (atom.data[i].name.text != text || !numeric(kind)) continue;
    code.instrs.push_back(
        access(Op::Load, ir::Scope::AtomData, static_cast<ir::Index>(i), 0, kind));
    convert_at_end(code.instrs, kind, ValueKind::Float);
    return code;
  }
  return std::nullopt;
}

}  // namespace smcbip::bipc::lower
