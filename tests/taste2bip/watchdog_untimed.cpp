// The untimed abstraction of a system: clock comparisons replaced by true.
#include "tests/taste2bip/watchdog_untimed.h"

#include <optional>
#include <vector>

namespace smcbip::taste2bip::test {

namespace {

using bipc::ir::Code;
using bipc::ir::Index;
using bipc::ir::Instr;
using bipc::ir::Op;
using bipc::ir::Scope;

/// A value on the stack of a straight-line reading of the code: where its computation starts
/// and whether it depends on a clock.
struct Operand {
  std::size_t start = 0;
  bool clock = false;
};

/// The comparisons of `code` that read a clock, as [first, last] instruction spans.
struct ClockSpans {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  std::string error;
};

/// Pops `n` operands; their combination (start of the first, clock of any).
Operand pop(std::vector<Operand>& stack, std::size_t n, std::size_t pc) {
  Operand combined{pc, false};
  for (std::size_t k = 0; k < n && !stack.empty(); ++k) {
    combined.start = stack.back().start;
    combined.clock = combined.clock || stack.back().clock;
    stack.pop_back();
  }
  return combined;
}

ClockSpans find_clock_comparisons(const Code& code, const bipc::ir::System& system) {
  ClockSpans out;
  std::vector<Operand> stack;
  for (std::size_t pc = 0; pc < code.instrs.size(); ++pc) {
    const Instr& in = code.instrs[pc];
    switch (in.op) {
      case Op::PushBool:
      case Op::PushInt:
      case Op::PushFloat:
      case Op::PushString:
        stack.push_back({pc, false});
        break;
      case Op::Load:
        stack.push_back({pc, in.scope == Scope::Clock});
        break;
      case Op::Store:
      case Op::StoreRate:
      case Op::Pop:
      case Op::JumpIfFalse:
      case Op::JumpIfFalseKeep:
      case Op::JumpIfTrueKeep:
        if (pop(stack, 1, pc).clock) out.error = "a clock's value is stored or branched on";
        break;
      case Op::Neg:
      case Op::Not:
      case Op::BitNot:
      case Op::IntToFloat:
      case Op::Jump:
        break;
      case Op::Call: {
        if (pop(stack, in.arg, pc).clock) out.error = "a clock's value is passed to a function";
        if (system.functions[in.index].result) stack.push_back({pc, false});
        break;
      }
      default: {  // binary operators
        const Operand both = pop(stack, 2, pc);
        if (both.clock && bipc::ir::is_comparison(in.op)) {
          out.spans.emplace_back(both.start, pc);
          stack.push_back({both.start, false});
        } else {
          stack.push_back(both);
        }
      }
    }
    if (!out.error.empty()) return out;
  }
  return out;
}

/// Whether an instruction of `code` jumps into (first, last] or lies there and jumps.
bool crosses_jumps(const Code& code, std::size_t first, std::size_t last) {
  for (std::size_t pc = 0; pc < code.instrs.size(); ++pc) {
    const Instr& in = code.instrs[pc];
    if (!bipc::ir::is_jump(in.op)) continue;
    if (pc >= first && pc <= last) return true;
    if (in.index > first && in.index <= last) return true;
  }
  return false;
}

std::string abstract_code(Code& code, const bipc::ir::System& system) {
  const ClockSpans found = find_clock_comparisons(code, system);
  if (!found.error.empty()) return found.error;
  for (const auto& [first, last] : found.spans) {
    if (crosses_jumps(code, first, last)) return "a clock comparison's operands contain jumps";
  }
  for (const auto& [first, last] : found.spans) {
    for (std::size_t pc = first; pc < last; ++pc) {
      Instr jump;
      jump.op = Op::Jump;
      jump.index = static_cast<Index>(pc + 1);
      code.instrs[pc] = jump;
    }
    Instr yes;
    yes.op = Op::PushBool;
    yes.kind = bipc::ir::ValueKind::Bool;
    yes.imm.b = true;
    code.instrs[last] = yes;
  }
  return "";
}

}  // namespace

std::string make_untimed(bipc::ir::System& system) {
  std::string error;
  const bipc::ir::System& read = system;
  bipc::ir::for_each_code(system, [&](Code& code, bipc::ir::CodeUse) {
    if (!error.empty()) return;
    error = abstract_code(code, read);
  });
  if (!error.empty()) return error;
  for (bipc::ir::AtomType& type : system.atom_types) {
    type.invariants.clear();
    for (bipc::ir::Transition& t : type.transitions) t.urgency = bipc::ir::Urgency::Lazy;
    for (bipc::ir::Port& port : type.ports) port.stochastic.reset();
  }
  return "";
}

}  // namespace smcbip::taste2bip::test
