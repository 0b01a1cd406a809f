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

/// The comparison at instructions `at`..`at + 2`, if there is one.
std::optional<IntComparison> comparison_at(const std::vector<Instr>& instrs, std::size_t at) {
  if (at + 3 > instrs.size() || !is_comparison(instrs[at + 2].op) ||
      instrs[at + 2].kind != ValueKind::Int) {
    return std::nullopt;
  }
  const std::optional<IntOperand> left = int_operand(instrs[at]);
  const std::optional<IntOperand> right = int_operand(instrs[at + 1]);
  if (!left || !right) return std::nullopt;
  return IntComparison{*left, *right, instrs[at + 2].op};
}

}  // namespace

std::optional<LeadingComparison> leading_comparison(const Code& guard) {
  const std::vector<Instr>& instrs = guard.instrs;
  LeadingComparison out;
  // Each comparison must be the whole guard or be followed by a `&&` whose false ends it.
  for (std::size_t at = 0; out.count < LeadingComparison::kMax; at += 4) {
    const std::optional<IntComparison> test = comparison_at(instrs, at);
    if (!test) break;
    if (at + 3 != instrs.size() && !false_ends_guard(instrs, at + 3)) break;
    out.tests[out.count++] = *test;
    if (at + 3 == instrs.size()) {
      out.whole = true;
      break;
    }
  }
  if (out.count == 0) return std::nullopt;
  return out;
}

}  // namespace smcbip::bipc::ir
