// Symbolic execution of the IR's stack code: one path per outcome of each conditional jump
// (jumps go forward only, so paths are finite), merged into if-then-else terms.
#include "fdir/smt/code_encoding.h"

#include <cstdint>
#include <limits>
#include <string>

namespace smcbip::fdir {

namespace {

using bipc::ir::Instr;
using bipc::ir::Op;
using bipc::ir::Scope;
using bipc::ir::ValueKind;

/// Beyond this many paths through one code, its effect is left unknown.
constexpr std::size_t kMaxPaths = 256;

}  // namespace

struct CodeEncoder::Path {
  std::size_t pc = 0;
  std::vector<z3::expr> stack;
  std::vector<z3::expr> data;
  z3::expr condition;
};

z3::expr CodeEncoder::unknown(ValueKind kind) {
  const std::string name = "unknown!" + std::to_string(counter_++);
  z3::expr e = kind == ValueKind::Bool  ? context_.bool_const(name.c_str())
               : kind == ValueKind::Int ? context_.int_const(name.c_str())
                                        : context_.real_const(name.c_str());
  fresh_.push_back(e);
  return e;
}

z3::expr value_term(CodeEncoder& encoder, const bipc::ir::Value& value) {
  z3::context& c = encoder.context();
  if (value.kind == ValueKind::Bool) return c.bool_val(value.b);
  if (value.kind == ValueKind::Int) return c.int_val(value.i);
  return encoder.unknown(value.kind);
}

z3::expr CodeEncoder::load(const Instr& in, const CodeFrame& frame, const Path& path) {
  if (in.kind != ValueKind::Int && in.kind != ValueKind::Bool) return unknown(in.kind);
  switch (in.scope) {
    case Scope::AtomData:
      if (in.index < path.data.size()) return path.data[in.index];
      break;
    case Scope::AtomParam:
      if (frame.params && in.index < frame.params->size()) {
        return value_term(*this, (*frame.params)[in.index]);
      }
      break;
    case Scope::PortParam:
      if (frame.port_data) {
        if (std::optional<z3::expr> e = frame.port_data(in.index, in.arg)) return *e;
      }
      break;
    default:
      break;
  }
  return unknown(in.kind);
}

void CodeEncoder::store(const Instr& in, Path& path) {
  z3::expr value = path.stack.back();
  path.stack.pop_back();
  if (in.scope != Scope::AtomData || in.index >= path.data.size()) return;
  const z3::sort sort = path.data[in.index].get_sort();
  // Data the encoding does not follow (floats, strings) keep their own unknown term.
  if (sort.is_int() && value.is_int()) path.data[in.index] = value;
  if (sort.is_bool() && value.is_bool()) path.data[in.index] = value;
}

z3::expr int64_bounds(const z3::expr& e) {
  z3::context& c = e.ctx();
  if (!e.is_int()) return c.bool_val(true);
  return c.int_val(std::numeric_limits<std::int64_t>::min()) <= e &&
         e <= c.int_val(std::numeric_limits<std::int64_t>::max());
}

z3::expr CodeEncoder::in_range(const z3::expr& exact) {
  // The engines' integers wrap around on 64 bits: where the mathematical result leaves that
  // range, the value is left unknown.
  return z3::ite(int64_bounds(exact), exact, unknown(ValueKind::Int));
}

z3::expr CodeEncoder::arithmetic(Op op, const z3::expr& a, const z3::expr& b) {
  switch (op) {
    case Op::Add:
      return in_range(a + b);
    case Op::Sub:
      return in_range(a - b);
    case Op::Mul:
      return in_range(a * b);
    case Op::Div:
    case Op::Mod: {
      // Z3's division is Euclidean, C++'s truncates: they agree on a >= 0 and b > 0.
      if (!b.is_numeral()) return unknown(ValueKind::Int);
      const z3::expr exact = op == Op::Div ? a / b : z3::mod(a, b);
      return z3::ite(a >= 0 && b > 0, exact, unknown(ValueKind::Int));
    }
    default:
      return unknown(ValueKind::Int);
  }
}

z3::expr CodeEncoder::binary(const Instr& in, const z3::expr& a, const z3::expr& b) {
  if (in.kind != ValueKind::Int && in.kind != ValueKind::Bool) {
    return unknown(bipc::ir::is_comparison(in.op) ? ValueKind::Bool : in.kind);
  }
  if (a.get_sort().id() != b.get_sort().id()) {
    return unknown(bipc::ir::is_comparison(in.op) ? ValueKind::Bool : in.kind);
  }
  switch (in.op) {
    case Op::Eq:
      return a == b;
    case Op::Ne:
      return a != b;
    case Op::Lt:
      return in.kind == ValueKind::Int ? a < b : unknown(ValueKind::Bool);
    case Op::Le:
      return in.kind == ValueKind::Int ? a <= b : unknown(ValueKind::Bool);
    case Op::Gt:
      return in.kind == ValueKind::Int ? a > b : unknown(ValueKind::Bool);
    case Op::Ge:
      return in.kind == ValueKind::Int ? a >= b : unknown(ValueKind::Bool);
    default:
      return in.kind == ValueKind::Int ? arithmetic(in.op, a, b) : unknown(in.kind);
  }
}

void CodeEncoder::step(const Instr& in, const CodeFrame& frame, Path& path) {
  auto pop = [&] {
    z3::expr e = path.stack.back();
    path.stack.pop_back();
    return e;
  };
  switch (in.op) {
    case Op::PushBool:
      path.stack.push_back(context_.bool_val(in.imm.b));
      return;
    case Op::PushInt:
      path.stack.push_back(context_.int_val(in.imm.i));
      return;
    case Op::Load:
      path.stack.push_back(load(in, frame, path));
      return;
    case Op::Store:
      store(in, path);
      return;
    case Op::StoreRate:
    case Op::Pop:
      pop();
      return;
    case Op::Neg: {
      const z3::expr a = pop();
      path.stack.push_back(a.is_int() ? in_range(-a) : unknown(in.kind));
      return;
    }
    case Op::Not: {
      const z3::expr a = pop();
      path.stack.push_back(a.is_bool() ? !a : unknown(ValueKind::Bool));
      return;
    }
    case Op::Call:
      for (unsigned k = 0; k < in.arg; ++k) pop();
      path.stack.push_back(unknown(ValueKind::Int));
      return;
    default:
      break;
  }
  if (bipc::ir::is_binary(in.op)) {
    const z3::expr b = pop();
    const z3::expr a = pop();
    path.stack.push_back(binary(in, a, b));
    return;
  }
  // PushFloat, PushString, BitNot, IntToFloat: values the encoding does not follow.
  if (in.op == Op::BitNot || in.op == Op::IntToFloat) pop();
  path.stack.push_back(unknown(in.op == Op::BitNot ? ValueKind::Int : ValueKind::Float));
}

std::optional<std::vector<CodeEncoder::Path>> CodeEncoder::paths(const bipc::ir::Code& code,
                                                                 const CodeFrame& frame) {
  std::vector<Path> done, open;
  open.push_back(Path{0, {}, frame.data, context_.bool_val(true)});
  const std::size_t size = code.instrs.size();
  while (!open.empty()) {
    Path path = std::move(open.back());
    open.pop_back();
    while (path.pc < size) {
      const Instr& in = code.instrs[path.pc];
      if (!bipc::ir::is_jump(in.op)) {
        step(in, frame, path);
        ++path.pc;
        continue;
      }
      if (in.index <= path.pc) return std::nullopt;  // a loop: not followed
      if (in.op == Op::Jump) {
        path.pc = in.index;
        continue;
      }
      if (open.size() + done.size() >= kMaxPaths) return std::nullopt;
      // The value deciding the jump; `&&`/`||` keep it as the result when they jump.
      const z3::expr c = path.stack.back();
      const bool jump_when_true = in.op == Op::JumpIfTrueKeep;
      const bool keep = in.op != Op::JumpIfFalse;
      path.stack.pop_back();
      Path jumped = path;
      jumped.pc = in.index;
      jumped.condition = path.condition && (jump_when_true ? c : !c);
      if (keep) jumped.stack.push_back(context_.bool_val(jump_when_true));
      open.push_back(std::move(jumped));
      path.condition = path.condition && (jump_when_true ? !c : c);
      ++path.pc;
    }
    done.push_back(std::move(path));
  }
  return done;
}

z3::expr CodeEncoder::expression(const bipc::ir::Code& code, const CodeFrame& frame) {
  if (code.empty()) return context_.bool_val(true);
  const std::optional<std::vector<Path>> all = paths(code, frame);
  if (!all || all->empty() || all->front().stack.empty()) return unknown(ValueKind::Bool);
  z3::expr result = all->back().stack.back();
  for (std::size_t k = all->size() - 1; k-- > 0;) {
    const z3::expr& value = (*all)[k].stack.back();
    if (value.get_sort().id() != result.get_sort().id()) return unknown(ValueKind::Bool);
    result = z3::ite((*all)[k].condition, value, result);
  }
  return result.simplify();
}

void CodeEncoder::statement(const bipc::ir::Code& code, CodeFrame& frame) {
  if (code.empty()) return;
  const std::optional<std::vector<Path>> all = paths(code, frame);
  if (!all) {
    // Not followed: every tracked datum may have any value afterwards.
    for (z3::expr& d : frame.data) {
      d = unknown(d.is_bool() ? ValueKind::Bool : d.is_int() ? ValueKind::Int : ValueKind::Float);
    }
    return;
  }
  for (std::size_t slot = 0; slot < frame.data.size(); ++slot) {
    z3::expr value = all->back().data[slot];
    for (std::size_t k = all->size() - 1; k-- > 0;) {
      value = z3::ite((*all)[k].condition, (*all)[k].data[slot], value);
    }
    frame.data[slot] = value.simplify();
  }
}

bool writes_port(const bipc::ir::Code& down, bipc::ir::Index param) {
  for (const bipc::ir::Instr& in : down.instrs) {
    if (in.op == bipc::ir::Op::Store && in.scope == bipc::ir::Scope::PortParam &&
        in.index == param) {
      return true;
    }
  }
  return false;
}

}  // namespace smcbip::fdir
