// Recognition of guards led by a comparison of integer data, parameters and literals.
#include "bipc/ir/data_guard.h"

namespace smcbip::bipc::ir {

namespace {

std::optional<IntOperand> int_operand(const Instr& in) {
  if (in.op == Op::PushInt && in.kind == ValueKind::Int) {
    return IntOperand{IntOperand::Kind::Literal, 0, in.imm.i};
  }
  if (in.op != Op::Load || in.kind != ValueKind::Int || in.arg != 0) return std::nullopt;
  if (in.scope == Scope::AtomData) return IntOperand{IntOperand::Kind::AtomData, in.index, 0};
  if (in.scope == Scope::AtomParam) return IntOperand{IntOperand::Kind::AtomParam, in.index, 0};
  return std::nullopt;
}

/// Whether a false left side of the `&&` jumping from instruction `jump` ends the guard false:
/// it lands at the end, possibly through further `&&` jumps (`a && b && c` nests to the left).
bool false_ends_guard(const std::vector<Instr>& instrs, std::size_t jump) {
  std::size_t at = jump;
  while (at < instrs.size()) {
    if (instrs[at].op != Op::JumpIfFalseKeep || instrs[at].index <= at) return false;
    at = instrs[at].index;
  }
  return at == instrs.size();
}

}  // namespace

std::optional<LeadingComparison> leading_comparison(const Code& guard) {
  const std::vector<Instr>& instrs = guard.instrs;
  if (instrs.size() < 3 || !is_comparison(instrs[2].op) || instrs[2].kind != ValueKind::Int) {
    return std::nullopt;
  }
  const std::optional<IntOperand> left = int_operand(instrs[0]);
  const std::optional<IntOperand> right = int_operand(instrs[1]);
  if (!left || !right) return std::nullopt;
  const bool whole = instrs.size() == 3;
  if (!whole && !false_ends_guard(instrs, 3)) return std::nullopt;
  return LeadingComparison{*left, *right, instrs[2].op, whole};
}

}  // namespace smcbip::bipc::ir
