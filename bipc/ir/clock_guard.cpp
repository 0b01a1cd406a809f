// Recognition of guards that bound clocks by literals.
#include "bipc/ir/clock_guard.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace smcbip::bipc::ir {

namespace {

bool is_clock_load(const Instr& in) { return in.op == Op::Load && in.scope == Scope::Clock; }

/// A literal pushed from instruction `pc` (PushInt, PushFloat, or PushInt then IntToFloat), as
/// the 64 bits a stack slot would hold; `pc` then moves past it.
struct Literal {
  std::uint64_t bits = 0;
  double f() const { return std::bit_cast<double>(bits); }
  std::int64_t i() const { return std::bit_cast<std::int64_t>(bits); }
  static Literal of(double v) { return {std::bit_cast<std::uint64_t>(v)}; }
  static Literal of(std::int64_t v) { return {std::bit_cast<std::uint64_t>(v)}; }
};

std::optional<Literal> literal_at(const std::vector<Instr>& instrs, std::size_t& pc) {
  if (pc >= instrs.size()) return std::nullopt;
  const Instr& in = instrs[pc];
  if (in.op == Op::PushFloat) {
    ++pc;
    return Literal::of(in.imm.f);
  }
  if (in.op != Op::PushInt) return std::nullopt;
  ++pc;
  if (pc < instrs.size() && instrs[pc].op == Op::IntToFloat) {
    ++pc;
    return Literal::of(static_cast<double>(in.imm.i));
  }
  return Literal::of(in.imm.i);
}

/// The comparison starting at instruction `pc`, if it is one of a clock and a literal; `pc`
/// then moves past it.
std::optional<ClockComparison> comparison_at(const std::vector<Instr>& instrs, std::size_t& pc) {
  ClockComparison c;
  std::optional<Literal> literal;
  if (pc < instrs.size() && is_clock_load(instrs[pc])) {
    c.clock = instrs[pc++].index;
    literal = literal_at(instrs, pc);
  } else {
    literal = literal_at(instrs, pc);
    if (!literal || pc >= instrs.size() || !is_clock_load(instrs[pc])) return std::nullopt;
    c.clock = instrs[pc++].index;
    c.clock_on_left = false;
  }
  if (!literal || pc >= instrs.size() || !is_comparison(instrs[pc].op)) return std::nullopt;
  const Instr& compare = instrs[pc++];
  c.op = compare.op;
  // A plain operand is read by the comparison's kind (as a double for clocks).
  c.literal = compare.kind == ValueKind::Float ? literal->f() : static_cast<double>(literal->i());
  if (std::fabs(c.literal) < 0x1p20 && c.literal == std::floor(c.literal)) {
    c.small_literal = static_cast<std::int64_t>(c.literal);
  }
  c.clock_op = c.clock_on_left ? c.op : turned_around(c.op);
  return c;
}

}  // namespace

bool reads_clock(const Code& code) {
  return std::any_of(code.instrs.begin(), code.instrs.end(), is_clock_load);
}

std::optional<std::vector<ClockComparison>> clock_comparisons(const Code& guard) {
  const std::vector<Instr>& instrs = guard.instrs;
  std::vector<ClockComparison> out;
  std::size_t pc = 0;
  for (;;) {
    const std::optional<ClockComparison> c = comparison_at(instrs, pc);
    if (!c) return std::nullopt;
    out.push_back(*c);
    if (pc == instrs.size()) return out;
    // `a && b`: the left side's short-circuit jump lands right after the right side.
    const Instr& jump = instrs[pc++];
    std::size_t next = pc;
    if (jump.op != Op::JumpIfFalseKeep || !comparison_at(instrs, next) || jump.index != next) {
      return std::nullopt;
    }
  }
}

}  // namespace smcbip::bipc::ir
