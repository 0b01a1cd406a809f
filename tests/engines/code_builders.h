// IR stack code written by hand in tests of guard analyses (clock bounds, leading comparisons):
// instructions as the compiler lays them out.
#pragma once

#include <cstdint>

#include "bipc/ir/ir.h"
#include "engines/api/value.h"

namespace smcbip::engines::code_builders {

using bipc::ir::Code;
using bipc::ir::Instr;
using bipc::ir::Op;
using bipc::ir::Scope;

inline Instr load(Scope scope, bipc::ir::Index index, ValueKind kind) {
  Instr in;
  in.op = Op::Load;
  in.scope = scope;
  in.kind = kind;
  in.index = index;
  return in;
}

inline Instr push_float(double value) {
  Instr in;
  in.op = Op::PushFloat;
  in.kind = ValueKind::Float;
  in.imm.f = value;
  return in;
}

inline Instr push_int(std::int64_t value) {
  Instr in;
  in.op = Op::PushInt;
  in.kind = ValueKind::Int;
  in.imm.i = value;
  return in;
}

inline Instr op(Op code, ValueKind kind) {
  Instr in;
  in.op = code;
  in.kind = kind;
  return in;
}

/// `a && b` (`jump_op` JumpIfFalseKeep) or `a || b` (JumpIfTrueKeep), as the compiler lays
/// them out: the jump lands after b.
inline Code joined(const Code& a, const Code& b, Op jump_op = Op::JumpIfFalseKeep) {
  Code out = a;
  Instr jump = op(jump_op, ValueKind::Bool);
  jump.index = static_cast<bipc::ir::Index>(a.instrs.size() + 1 + b.instrs.size());
  out.instrs.push_back(jump);
  out.instrs.insert(out.instrs.end(), b.instrs.begin(), b.instrs.end());
  return out;
}

}  // namespace smcbip::engines::code_builders
