// Recognition of actions made of assignments from literals or from a datum plus a literal.
#include "bipc/ir/simple_action.h"

namespace smcbip::bipc::ir {

namespace {

/// The value an assignment starting at `at` stores, and where its Store is; nullopt when the
/// instructions there are not of the shape.
std::optional<SimpleAssignment> value_at(const std::vector<Instr>& instrs, std::size_t& at) {
  const Instr& first = instrs[at];
  SimpleAssignment out;
  if (first.op == Op::PushFloat && first.kind == ValueKind::Float) {
    out.kind = SimpleAssignment::Kind::Float;
    out.real = first.imm.f;
    at += 1;
    return out;
  }
  if (first.op == Op::PushInt && first.kind == ValueKind::Int) {
    if (at + 1 < instrs.size() && instrs[at + 1].op == Op::IntToFloat) {
      out.kind = SimpleAssignment::Kind::Float;
      out.real = static_cast<double>(first.imm.i);
      at += 2;
      return out;
    }
    out.literal = first.imm.i;
    at += 1;
    return out;
  }
  if (first.op != Op::Load || first.scope != Scope::AtomData || first.kind != ValueKind::Int ||
      first.arg != 0 || at + 2 >= instrs.size()) {
    return std::nullopt;
  }
  const Instr& literal = instrs[at + 1];
  const Instr& op = instrs[at + 2];
  if (literal.op != Op::PushInt || literal.kind != ValueKind::Int ||
      (op.op != Op::Add && op.op != Op::Sub) || op.kind != ValueKind::Int) {
    return std::nullopt;
  }
  out.kind = SimpleAssignment::Kind::AddInt;
  out.source = first.index;
  // Two's complement: a - k wraps as a + (0 - k) does.
  const auto k = static_cast<std::uint64_t>(literal.imm.i);
  out.literal = static_cast<std::int64_t>(op.op == Op::Add ? k : std::uint64_t{0} - k);
  at += 3;
  return out;
}

}  // namespace

std::optional<std::vector<SimpleAssignment>> simple_action(const Code& action) {
  const std::vector<Instr>& instrs = action.instrs;
  std::vector<SimpleAssignment> out;
  for (std::size_t at = 0; at < instrs.size();) {
    std::optional<SimpleAssignment> assignment = value_at(instrs, at);
    if (!assignment || at >= instrs.size()) return std::nullopt;
    const Instr& store = instrs[at++];
    if (store.op != Op::Store || store.arg != 0) return std::nullopt;
    const bool real = assignment->kind == SimpleAssignment::Kind::Float;
    if (store.scope == Scope::Clock && real && store.kind == ValueKind::Float) {
      assignment->kind = SimpleAssignment::Kind::ClockSet;
    } else if (store.scope != Scope::AtomData ||
               store.kind != (real ? ValueKind::Float : ValueKind::Int)) {
      return std::nullopt;
    }
    assignment->target = store.index;
    out.push_back(*assignment);
  }
  return out;
}

}  // namespace smcbip::bipc::ir
