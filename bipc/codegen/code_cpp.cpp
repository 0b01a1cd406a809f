// Stack code to C++: stack depths found once (jumps go forward), then one statement per
// instruction.
#include "bipc/codegen/code_cpp.h"

#include <algorithm>
#include <bit>
#include <cinttypes>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include "bipc/ir/ir_json.h"

namespace smcbip::bipc::codegen {

namespace {

using ir::Instr;
using ir::Op;

/// An enumerator of the IR as a constant C++ expression (the statement's comment names it).
template <class Enum>
std::string constant(const char* type, Enum value) {
  return std::string("static_cast<ir::") + type + ">(" +
         std::to_string(static_cast<unsigned>(value)) + ")";
}

/// An integer literal valid for every int64 (the most negative one has no literal of its own).
/// An Instr::site (kNone included) as an unsigned literal.
std::string site_literal(ir::Index site) { return std::to_string(site) + "u"; }

std::string int_literal(std::int64_t v) {
  if (v == std::numeric_limits<std::int64_t>::min()) return "(-INT64_C(9223372036854775807) - 1)";
  return "INT64_C(" + std::to_string(v) + ")";
}

/// A double by its bits: exact for every value, infinities and NaNs included.
std::string float_literal(double v) {
  char bits[32];
  std::snprintf(bits, sizeof bits, "0x%016" PRIx64, std::bit_cast<std::uint64_t>(v));
  char readable[40];
  std::snprintf(readable, sizeof readable, "%.17g", v);
  return std::string("std::bit_cast<double>(UINT64_C(") + bits + ")) /* " + readable + " */";
}

/// How many values the instruction leaves minus how many it takes (jumps: on falling through).
int stack_effect(const ir::System& system, const Instr& in) {
  if (ir::is_binary(in.op)) return -1;
  switch (in.op) {
    case Op::PushBool:
    case Op::PushInt:
    case Op::PushFloat:
    case Op::PushString:
    case Op::Load:
      return 1;
    case Op::Store:
    case Op::StoreRate:
    case Op::Pop:
    case Op::JumpIfFalse:
    case Op::JumpIfFalseKeep:
    case Op::JumpIfTrueKeep:
      return -1;
    case Op::Call:
      return (system.functions.at(in.index).result ? 1 : 0) - static_cast<int>(in.arg);
    default:  // Neg, Not, BitNot, IntToFloat, Jump
      return 0;
  }
}

/// The stack depth before each instruction (nullopt where none reaches) and at the end.
struct Depths {
  std::vector<std::optional<int>> before;
  std::vector<bool> targeted;  // per instruction and the end: a jump lands there
  int max = 0;
};

void meet(std::optional<int>& slot, int depth, std::size_t pc) {
  if (slot && *slot != depth) {
    throw UntranslatableCode{"stacks of depths " + std::to_string(*slot) + " and " +
                             std::to_string(depth) + " meet at instruction " + std::to_string(pc)};
  }
  slot = depth;
}

Depths depths_of(const ir::System& system, const ir::Code& code) {
  const std::size_t n = code.instrs.size();
  Depths d{std::vector<std::optional<int>>(n + 1), std::vector<bool>(n + 1, false), 0};
  d.before[0] = 0;
  for (std::size_t pc = 0; pc < n; ++pc) {
    if (!d.before[pc]) continue;  // unreachable (after an unconditional jump)
    const Instr& in = code.instrs[pc];
    const int depth = *d.before[pc];
    const int after = depth + stack_effect(system, in);
    if (after < 0 || (in.op != Op::Jump && ir::is_jump(in.op) && depth < 1)) {
      throw UntranslatableCode{"stack underflow at instruction " + std::to_string(pc)};
    }
    if (ir::is_jump(in.op)) {
      if (in.index <= pc || in.index > n) {
        throw UntranslatableCode{"jump from " + std::to_string(pc) + " to " +
                                 std::to_string(in.index) + " does not go forward"};
      }
      // `&&`/`||` keep their deciding value when they jump.
      const bool keeps = in.op == Op::JumpIfFalseKeep || in.op == Op::JumpIfTrueKeep;
      meet(d.before[in.index], keeps ? depth : after, in.index);
      d.targeted[in.index] = true;
    }
    if (in.op != Op::Jump) meet(d.before[pc + 1], after, pc + 1);
    d.max = std::max({d.max, depth, after});
  }
  return d;
}

/// The statement of a Call at stack depth `d`: its result replaces its arguments.
std::string call_statement(const ir::System& system, const Instr& in, int d) {
  const int first = d - static_cast<int>(in.arg);
  std::string text = "{ const se::Val r = ops::call_extern(c.system, c.functions, c.call, " +
                     std::to_string(in.index) + ", " + std::to_string(in.arg) + ", s + " +
                     std::to_string(d) + ", " + site_literal(in.site) + ");";
  if (system.functions.at(in.index).result) {
    text += " s[" + std::to_string(first) + "] = r;";
  } else {
    text += " (void)r;";
  }
  return text + " }";
}

/// The statement of one instruction at stack depth `d`.
std::string statement(const ir::System& system, const Instr& in, int d) {
  const std::string top = "s[" + std::to_string(d - 1) + "]";
  const std::string below = "s[" + std::to_string(d - 2) + "]";
  const std::string next = "s[" + std::to_string(d) + "]";
  const std::string kind = constant("ValueKind", in.kind);
  const std::string op = constant("Op", in.op);
  const std::string label = "L" + std::to_string(in.index);
  const std::string place =
      constant("Scope", in.scope) + ", " + std::to_string(in.index) + ", " + std::to_string(in.arg);
  if (ir::is_comparison(in.op)) {
    return below + " = se::make_bool(ops::compare(" + op + ", " + kind + ", " + below + ", " + top +
           ", c.call.strings));";
  }
  if (ir::is_binary(in.op)) {
    const std::string site = in.site == ir::kNone ? "" : ", " + site_literal(in.site);
    return below + " = ops::arithmetic(" + op + ", " + kind + ", " + below + ", " + top + site +
           ");";
  }
  switch (in.op) {
    case Op::PushBool:
      return next + " = se::make_bool(" + (in.imm.b ? "true" : "false") + ");";
    case Op::PushInt:
      return next + " = se::make_int(" + int_literal(in.imm.i) + ");";
    case Op::PushFloat:
      return next + " = se::make_float(" + float_literal(in.imm.f) + ");";
    case Op::PushString:
      return next + ".s = c.functions.string_ids[" + std::to_string(in.index) + "];";
    case Op::Load:
      return next + " = ops::load(" + place + ", f);";
    case Op::Store:
      return "ops::store(" + place + ", f, " + top + ");";
    case Op::StoreRate:
      return "ops::store_rate(" + std::to_string(in.index) + ", f, " + top + ");";
    case Op::Neg:
      return top + " = ops::negate(" + kind + ", " + top + ");";
    case Op::Not:
      return top + " = se::make_bool(!" + top + ".b);";
    case Op::BitNot:
      return top + " = se::make_int(~" + top + ".i);";
    case Op::IntToFloat:
      return top + " = se::make_float(static_cast<double>(" + top + ".i));";
    case Op::Call:
      return call_statement(system, in, d);
    case Op::Pop:
      return ";";
    case Op::Jump:
      return "goto " + label + ";";
    case Op::JumpIfFalse:
    case Op::JumpIfFalseKeep:
      return "if (!" + top + ".b) goto " + label + ";";
    case Op::JumpIfTrueKeep:
      return "if (" + top + ".b) goto " + label + ";";
    default:  // binary operations, above
      break;
  }
  return "";
}

}  // namespace

std::string code_function(const ir::System& system, const ir::Code& code, const std::string& name,
                          bool returns_value) {
  const Depths depths = depths_of(system, code);
  const std::size_t n = code.instrs.size();
  std::ostringstream out;
  out << "[[maybe_unused]] " << (returns_value ? "se::Val " : "void ") << name
      << "([[maybe_unused]] Context& c, [[maybe_unused]] const se::Frame& f) {\n";
  out << "  [[maybe_unused]] se::Val s[" << std::max(depths.max, 1) << "] = {};\n";
  for (std::size_t pc = 0; pc < n; ++pc) {
    if (depths.targeted[pc]) out << " L" << pc << ":;\n";
    if (!depths.before[pc]) continue;
    const Instr& in = code.instrs[pc];
    out << "  " << statement(system, in, *depths.before[pc]) << "  // "
        << ir::instruction_text(in, system) << "\n";
  }
  if (depths.targeted[n]) out << " L" << n << ":;\n";
  if (returns_value) {
    const int end = depths.before[n].value_or(0);
    if (end == 0) {
      out << "  return se::make_bool(true);\n";
    } else {
      out << "  return s[" << end - 1 << "];\n";
    }
  }
  out << "}\n";
  return out.str();
}

}  // namespace smcbip::bipc::codegen
