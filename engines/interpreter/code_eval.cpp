// Stack-code evaluation: plain values, and time sets for guards over clocks.
#include "engines/interpreter/code_eval.h"

#include <cmath>
#include <string>

#include "engines/api/code_ops.h"
#include "engines/interpreter/clock_bounds.h"
#include "engines/interpreter/detail/time_sets.h"

namespace smcbip::engines {

namespace {

using bipc::ir::Instr;
using bipc::ir::Op;
using bipc::ir::Scope;
using code_ops::arithmetic;
using code_ops::compare;

Val* slot(const Instr& in, const Frame& f) { return code_ops::slot(in.scope, in.index, in.arg, f); }

// The steps of CodeEvaluator::apply over the stack whose top is `sp`; each returns the new top.

/// A Push or Load: `v` goes on top.
[[gnu::always_inline]] inline Val* push(Val* sp, Val v) {
  *sp = v;
  return sp + 1;
}

/// A unary operator: `v`, computed from the top value, replaces it.
[[gnu::always_inline]] inline Val* replace_top(Val* sp, Val v) {
  sp[-1] = v;
  return sp;
}

/// Add..BitXor: the two top values give way to their result.
[[gnu::always_inline]] inline Val* arithmetic_step(const Instr& in, Val* sp) {
  sp[-2] = arithmetic(in.op, in.kind, sp[-2], sp[-1], in.site);
  return sp - 1;
}

/// Eq..Ge: the two top values give way to the comparison's truth.
[[gnu::always_inline]] inline Val* comparison_step(const Instr& in, Val* sp,
                                                   const StringPool& strings) {
  sp[-2] = make_bool(compare(in.op, in.kind, sp[-2], sp[-1], strings));
  return sp - 1;
}

// ---------------------------------------------------------------------------------------------
// Time sets. A clock-dependent value is linear in the delay d (ns) from now: a + b*d.

using detail::relative_set;
using detail::shift;
using detail::solve;
using detail::TimedItem;

double as_double(const TimedItem& item, ValueKind kind) {
  if (item.kind == TimedItem::Kind::Linear) return item.a;
  return kind == ValueKind::Float ? item.value.f : static_cast<double>(item.value.i);
}

Interval as_set(const TimedItem& item) {
  return item.kind == TimedItem::Kind::Set ? item.set : relative_set(item.value.b);
}

Interval hull(const Interval& x, const Interval& y) {
  if (x.empty()) return y;
  if (y.empty()) return x;
  Interval r = x;
  if (y.left < r.left || (y.left == r.left && !y.left_open)) {
    r.left = y.left;
    r.left_open = y.left_open;
  }
  if (y.right > r.right || (y.right == r.right && !y.right_open)) {
    r.right = y.right;
    r.right_open = y.right_open;
  }
  return r;
}

}  // namespace

std::string bind_functions(const bipc::ir::System& system, const Externs& externs,
                           StringPool& strings, BoundFunctions& out) {
  out.functions.clear();
  out.arg_kinds.clear();
  for (const bipc::ir::ExternFunction& f : system.functions) {
    std::vector<ValueKind> kinds;
    for (const bipc::ir::DataType& t : f.params) kinds.push_back(t.kind);
    const Externs::Function* found = externs.find(f.name, kinds);
    out.functions.push_back(found);
    out.arg_kinds.push_back(kinds);
  }
  out.string_ids.clear();
  for (const std::string& s : system.strings) out.string_ids.push_back(strings.intern(s));
  out.port_classes.clear();
  for (const bipc::ir::AtomType& type : system.atom_types) {
    for (const bipc::ir::Port& port : type.ports) {
      if (port.is_extern)
        out.port_classes[port.backend_name] = externs.find_port_class(port.backend_name);
    }
  }
  return {};
}

CodeEvaluator::CodeEvaluator(const bipc::ir::System& system, const BoundFunctions& functions,
                             CallContext& call, const GuardBounds* guard_bounds)
    : system_(system), functions_(functions), call_(call), guard_bounds_(guard_bounds) {
  stack_.resize(64);
}

Val CodeEvaluator::evaluate(const bipc::ir::Code& code, const Frame& frame) {
  if (code.empty()) return make_bool(true);
  const std::size_t depth = run(code, frame);
  return depth == 0 ? make_bool(true) : stack_[depth - 1];
}

void CodeEvaluator::execute(const bipc::ir::Code& code, const Frame& frame) {
  if (code.empty()) return;
  run(code, frame);
}

Val code_ops::call_extern(const bipc::ir::System& system, const BoundFunctions& functions,
                          CallContext& call, Index function, std::size_t count, const Val* args_end,
                          Index site) {
  const Externs::Function* f = functions.functions[function];
  const std::vector<ValueKind>& kinds = functions.arg_kinds[function];
  if (!f) {
    const bipc::ir::ExternFunction& decl = system.functions[function];
    std::string signature = decl.name + "(";
    for (std::size_t i = 0; i < kinds.size(); ++i) {
      signature += (i ? ", " : "") + std::string(bipc::ir::value_kind_name(kinds[i]));
    }
    throw CodeFault{"extern function " + signature + ") has no implementation", site};
  }
  const std::span<const Val> args(args_end - count, count);
  // Variadic calls see their own argument kinds; the IR declares them per call site.
  call.arg_kinds = kinds;
  if (f->variadic && count > kinds.size()) call.arg_kinds = {};
  try {
    return f->fn(call, args);
  } catch (const ExternFault& fault) {
    throw CodeFault{system.functions[function].name + ": " + fault.what(), site};
  }
}

inline Val* CodeEvaluator::apply(const Instr& in, const Frame& frame, Val* sp) {
  switch (in.op) {
    case Op::PushBool:
      return push(sp, make_bool(in.imm.b));
    case Op::PushInt:
      return push(sp, make_int(in.imm.i));
    case Op::PushFloat:
      return push(sp, make_float(in.imm.f));
    case Op::PushString:
      sp->s = functions_.string_ids[in.index];
      return sp + 1;
    case Op::Load:
      return push(sp, code_ops::load(in.scope, in.index, in.arg, frame));
    case Op::Store:
      code_ops::store(in.scope, in.index, in.arg, frame, sp[-1]);
      return sp - 1;
    case Op::StoreRate:
      code_ops::store_rate(in.index, frame, sp[-1]);
      return sp - 1;
    case Op::Neg:
      return replace_top(sp, code_ops::negate(in.kind, sp[-1]));
    case Op::Not:
      return replace_top(sp, make_bool(!sp[-1].b));
    case Op::BitNot:
      return replace_top(sp, make_int(~sp[-1].i));
    case Op::IntToFloat:
      return replace_top(sp, make_float(static_cast<double>(sp[-1].i)));
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
    case Op::BitAnd:
    case Op::BitOr:
    case Op::BitXor:
      return arithmetic_step(in, sp);
    case Op::Eq:
    case Op::Ne:
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge:
      return comparison_step(in, sp, call_.strings);
    case Op::Call:
      return call(in, sp);
    case Op::Pop:
      return sp - 1;
    case Op::Jump:
    case Op::JumpIfFalse:
    case Op::JumpIfFalseKeep:
    case Op::JumpIfTrueKeep:
      break;  // run() and holds_when() follow jumps themselves
  }
  return sp;
}

inline Val* CodeEvaluator::call(const Instr& in, Val* sp) {
  const Val result =
      code_ops::call_extern(system_, functions_, call_, in.index, in.arg, sp, in.site);
  sp -= in.arg;
  if (system_.functions[in.index].result) *sp++ = result;
  return sp;
}

std::size_t CodeEvaluator::run(const bipc::ir::Code& code, const Frame& frame) {
  // Jumps go forward only (compile_code), so each instruction runs at most once and the stack
  // never holds more values than the code has instructions: no bound check per push.
  if (stack_.size() < code.instrs.size()) stack_.resize(code.instrs.size());
  Val* const bottom = stack_.data();
  Val* sp = bottom;
  const Instr* const first = code.instrs.data();
  const Instr* const last = first + code.instrs.size();
  for (const Instr* in = first; in != last; ++in) {
    if (!bipc::ir::is_jump(in->op)) {
      sp = apply(*in, frame, sp);
      continue;
    }
    bool jump = true;
    if (in->op == Op::JumpIfFalse) {
      --sp;
      jump = !sp->b;
    } else if (in->op != Op::Jump) {
      // `&&` / `||`: the deciding value stays as the result, otherwise the right side follows.
      jump = in->op == Op::JumpIfTrueKeep ? sp[-1].b : !sp[-1].b;
      if (!jump) --sp;
    }
    if (jump) in = first + in->index - 1;
  }
  return static_cast<std::size_t>(sp - bottom);
}

void CodeEvaluator::join_sides(const detail::PendingJoin& join, TimedItem& top) {
  const Interval right = as_set(top);
  top.kind = TimedItem::Kind::Set;
  if (join.conjunction) {
    top.set = join.left.intersect(right);
  } else {
    top.set = right.empty() ? join.left : hull(join.left, right);
  }
}

inline bool CodeEvaluator::timed_step(const Instr& in, const Frame& frame, TimedItem*& sp,
                                      detail::PendingJoin*& join) {
  using Kind = TimedItem::Kind;
  switch (in.op) {
    case Op::Load:
      if (in.scope == Scope::Clock) {
        const ClockState& clock = frame.clocks[in.index];
        const auto unit = static_cast<double>(frame.clock_units[in.index]);
        *sp = TimedItem{};
        sp->kind = Kind::Linear;
        sp->a = clock_value(clock, frame.clock_units[in.index], frame.now);
        sp->b = clock.rate / unit;
      } else {
        *sp = {Kind::Plain, *slot(in, frame), 0, 0, {}};
      }
      ++sp;
      return true;
    case Op::PushBool:
      *sp++ = {Kind::Plain, make_bool(in.imm.b), 0, 0, {}};
      return true;
    case Op::PushInt:
      *sp++ = {Kind::Plain, make_int(in.imm.i), 0, 0, {}};
      return true;
    case Op::PushFloat:
      *sp++ = {Kind::Plain, make_float(in.imm.f), 0, 0, {}};
      return true;
    case Op::IntToFloat:
      // Plain literals and data meet clocks through this conversion: done here, it spares them
      // the plain machine.
      if (sp[-1].kind == Kind::Plain) {
        sp[-1] = {Kind::Plain, make_float(static_cast<double>(sp[-1].value.i)), 0, 0, {}};
        return true;
      }
      return linear_step(in, sp);
    case Op::Add:
    case Op::Sub:
    case Op::Neg:
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge:
    case Op::Eq:
    case Op::Ne:
      return linear_step(in, sp);
    case Op::Not:
      if (sp[-1].kind != Kind::Set) return false;
      // Never produced by checked code (no `!` over clocks); keep the complement's hull.
      sp[-1].set = sp[-1].set.empty() ? Interval::all() : Interval::none();
      return true;
    case Op::JumpIfFalseKeep:
    case Op::JumpIfTrueKeep:
      // A `&&`/`||` whose left side depends on time cannot short-circuit: remember it and
      // combine both sides where the jump would have landed.
      if (sp[-1].kind != Kind::Set) return false;
      *join++ = {in.index, in.op == Op::JumpIfFalseKeep, sp[-1].set};
      --sp;
      return true;
    default:
      return false;
  }
}

inline bool CodeEvaluator::linear_step(const Instr& in, TimedItem*& sp) {
  using Kind = TimedItem::Kind;
  const bool binary = in.op != Op::Neg && in.op != Op::IntToFloat;
  const bool timed = sp[-1].kind == Kind::Linear || (binary && sp[-2].kind == Kind::Linear);
  if (!timed) return false;  // the plain machine's
  if (!binary) {
    if (in.op == Op::Neg) {
      sp[-1].a = -sp[-1].a;
      sp[-1].b = -sp[-1].b;
    }
    return true;
  }
  const TimedItem rhs = *--sp;
  TimedItem& lhs = sp[-1];
  const double la = as_double(lhs, in.kind), ra = as_double(rhs, in.kind);
  const double lb = lhs.kind == Kind::Linear ? lhs.b : 0.0;
  const double rb = rhs.kind == Kind::Linear ? rhs.b : 0.0;
  if (in.op == Op::Add || in.op == Op::Sub) {
    const double sign = in.op == Op::Add ? 1.0 : -1.0;
    lhs = {Kind::Linear, {}, la + sign * ra, lb + sign * rb, {}};
  } else {
    // (la + lb d) op (ra + rb d)  <=>  (la - ra) + (lb - rb) d op 0
    lhs = {Kind::Set, {}, 0, 0, solve(in.op, la - ra, lb - rb, 0.0)};
  }
  return true;
}

TimedItem* CodeEvaluator::plain_step(const Instr& in, const Frame& frame, TimedItem* sp) {
  // Runs the instruction on the plain values through a one-instruction program.
  const std::size_t arity =
      in.op == Op::Call            ? in.arg
      : bipc::ir::is_binary(in.op) ? 2
      : (in.op == Op::Neg || in.op == Op::Not || in.op == Op::BitNot || in.op == Op::IntToFloat ||
         in.op == Op::Pop || in.op == Op::Store || in.op == Op::StoreRate)
          ? 1
          : 0;
  if (stack_.size() < arity + 1) stack_.resize(arity + 1);
  Val* const operands = stack_.data();
  sp -= arity;
  for (std::size_t i = 0; i < arity; ++i) {
    const TimedItem& item = sp[i];
    operands[i] = item.kind == TimedItem::Kind::Set ? make_bool(!item.set.empty()) : item.value;
  }
  const Val* const results_end = apply(in, frame, operands + arity);
  for (const Val* v = operands; v != results_end; ++v) {
    *sp++ = {TimedItem::Kind::Plain, *v, 0, 0, {}};
  }
  return sp;
}

Interval CodeEvaluator::holds_when(const bipc::ir::Code& code, const Frame& frame) {
  if (code.empty()) return Interval::all();
  // Without clocks a guard holds at all dates or at none: no need for time sets.
  if (frame.clocks == nullptr) return holds(code, frame) ? Interval::all() : Interval::none();
  if (guard_bounds_ != nullptr) {
    if (guard_bounds_->clock_free(code)) {
      return holds(code, frame) ? Interval::all() : Interval::none();
    }
    if (const ClockBounds* bounds = guard_bounds_->find(code)) return bounds->holds_when(frame);
  }
  // As in run(), jumps go forward: neither stack outgrows the code.
  const std::vector<Instr>& instrs = code.instrs;
  if (timed_.size() < instrs.size()) timed_.resize(instrs.size());
  if (joins_.size() < instrs.size()) joins_.resize(instrs.size());
  TimedItem* const bottom = timed_.data();
  TimedItem* sp = bottom;
  detail::PendingJoin* const no_join = joins_.data();
  detail::PendingJoin* join = no_join;
  for (std::size_t pc = 0; pc <= instrs.size(); ++pc) {
    for (; join != no_join && join[-1].target == pc; --join) join_sides(join[-1], sp[-1]);
    if (pc == instrs.size()) break;
    const Instr& in = instrs[pc];
    if (timed_step(in, frame, sp, join)) continue;
    if (!bipc::ir::is_jump(in.op)) {
      sp = plain_step(in, frame, sp);
      continue;
    }
    const bool c = in.op == Op::Jump ? false : sp[-1].value.b;
    const bool keep = in.op == Op::JumpIfFalseKeep || in.op == Op::JumpIfTrueKeep;
    const bool jump = in.op == Op::Jump ? true : in.op == Op::JumpIfTrueKeep ? c : !c;
    if (in.op != Op::Jump && !(keep && jump)) --sp;
    if (jump) pc = in.index - 1;
  }
  if (sp == bottom) return Interval::all();
  return shift(as_set(sp[-1]), frame.now);
}

}  // namespace smcbip::engines
