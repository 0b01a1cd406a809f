// Stack-code evaluation: plain values, and time sets for guards over clocks.
#include "engines/interpreter/code_eval.h"

#include <cmath>
#include <string>

namespace smcbip::engines {

namespace {

using bipc::ir::Instr;
using bipc::ir::Op;
using bipc::ir::Scope;

std::int64_t wrap_add(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
}
std::int64_t wrap_sub(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) - static_cast<std::uint64_t>(b));
}
std::int64_t wrap_mul(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b));
}

Val* slot(const Instr& in, const Frame& f) {
  switch (in.scope) {
    case Scope::AtomData:
      return f.atom_data + in.index;
    case Scope::AtomParam:
      return const_cast<Val*>(f.atom_params + in.index);
    case Scope::ConnectorData:
      return f.connector_data + in.index;
    case Scope::PortParam:
      return f.port_slot(f.port_context, in.index, in.arg);
    case Scope::InstanceData:
      return f.instance_slot(f.instance_context, in.index, in.arg);
    case Scope::Clock:
      break;
  }
  return nullptr;
}

bool compare(Op op, ValueKind kind, Val a, Val b, const StringPool& strings) {
  int order = 0;
  switch (kind) {
    case ValueKind::Bool:
      order = static_cast<int>(a.b) - static_cast<int>(b.b);
      break;
    case ValueKind::Float:
      order = a.f < b.f ? -1 : (a.f > b.f ? 1 : 0);
      break;
    case ValueKind::String:
      order = a.s == b.s ? 0 : strings.text(a.s).compare(strings.text(b.s));
      break;
    default:
      order = a.i < b.i ? -1 : (a.i > b.i ? 1 : 0);
      break;
  }
  switch (op) {
    case Op::Eq:
      return order == 0;
    case Op::Ne:
      return order != 0;
    case Op::Lt:
      return order < 0;
    case Op::Le:
      return order <= 0;
    case Op::Gt:
      return order > 0;
    default:
      return order >= 0;
  }
}

Val arithmetic(Op op, ValueKind kind, Val a, Val b) {
  if (kind == ValueKind::Float) {
    switch (op) {
      case Op::Add:
        return make_float(a.f + b.f);
      case Op::Sub:
        return make_float(a.f - b.f);
      case Op::Mul:
        return make_float(a.f * b.f);
      case Op::Div:
        if (b.f == 0.0) throw CodeFault{"division by zero"};
        return make_float(a.f / b.f);
      default:
        if (b.f == 0.0) throw CodeFault{"modulo by zero"};
        return make_float(std::fmod(a.f, b.f));
    }
  }
  switch (op) {
    case Op::Add:
      return make_int(wrap_add(a.i, b.i));
    case Op::Sub:
      return make_int(wrap_sub(a.i, b.i));
    case Op::Mul:
      return make_int(wrap_mul(a.i, b.i));
    case Op::Div:
      if (b.i == 0) throw CodeFault{"division by zero"};
      if (b.i == -1) return make_int(wrap_sub(0, a.i));
      return make_int(a.i / b.i);
    case Op::Mod:
      if (b.i == 0) throw CodeFault{"modulo by zero"};
      if (b.i == -1) return make_int(0);
      return make_int(a.i % b.i);
    case Op::BitAnd:
      return make_int(a.i & b.i);
    case Op::BitOr:
      return make_int(a.i | b.i);
    default:
      return make_int(a.i ^ b.i);
  }
}

// ---------------------------------------------------------------------------------------------
// Time sets. A clock-dependent value is linear in the delay d (ns) from now: a + b*d.

struct TimedItem {
  enum class Kind : std::uint8_t { Plain, Linear, Set } kind = Kind::Plain;
  Val value{};
  double a = 0.0, b = 0.0;
  Interval set;  // relative delays
};

double as_double(const TimedItem& item, ValueKind kind) {
  if (item.kind == TimedItem::Kind::Linear) return item.a;
  return kind == ValueKind::Float ? item.value.f : static_cast<double>(item.value.i);
}

Interval relative_set(bool holds) { return holds ? Interval::all() : Interval::none(); }

/// {d | a + b*d op c}, on integer nanoseconds.
Interval solve(Op op, double a, double b, double c) {
  if (b == 0.0) {
    const bool holds = op == Op::Lt   ? a < c
                       : op == Op::Le ? a <= c
                       : op == Op::Gt ? a > c
                       : op == Op::Ge ? a >= c
                       : op == Op::Eq ? a == c
                                      : a != c;
    return relative_set(holds);
  }
  const double x = (c - a) / b;
  if (b < 0.0) {
    // Dividing by a negative slope turns the comparison around.
    op = op == Op::Lt   ? Op::Gt
         : op == Op::Le ? Op::Ge
         : op == Op::Gt ? Op::Lt
         : op == Op::Ge ? Op::Le
                        : op;
  }
  const double limit = 9.0e18;
  if (x > limit) return op == Op::Lt || op == Op::Le ? Interval::all() : Interval::none();
  if (x < -limit) return op == Op::Gt || op == Op::Ge ? Interval::all() : Interval::none();
  const double nearest = std::nearbyint(x);
  const bool integral = std::fabs(x - nearest) <= 1e-6 * std::max(1.0, std::fabs(x));
  const auto at = static_cast<TimeValue>(nearest);
  Interval result = Interval::all();
  switch (op) {
    case Op::Lt:
      if (integral) return {kMinusInfinity, at, false, true};
      result.right = static_cast<TimeValue>(std::floor(x));
      return result;
    case Op::Le:
      result.right = integral ? at : static_cast<TimeValue>(std::floor(x));
      return result;
    case Op::Gt:
      if (integral) return {at, kPlusInfinity, true, false};
      result.left = static_cast<TimeValue>(std::ceil(x));
      return result;
    case Op::Ge:
      result.left = integral ? at : static_cast<TimeValue>(std::ceil(x));
      return result;
    case Op::Eq:
      return integral ? Interval::point(at) : Interval::none();
    default:
      // `!=` over clocks is refused by the checker; keep the dates where it holds now.
      return Interval::all();
  }
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

Interval shift(const Interval& set, TimeValue now) {
  Interval r = set;
  if (r.left != kMinusInfinity) r.left += now;
  if (r.right != kPlusInfinity) r.right += now;
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
                             CallContext& call)
    : system_(system), functions_(functions), call_(call) {
  stack_.reserve(64);
}

Val CodeEvaluator::evaluate(const bipc::ir::Code& code, const Frame& frame) {
  if (code.empty()) return make_bool(true);
  stack_.clear();
  run(code, frame);
  return stack_.empty() ? make_bool(true) : stack_.back();
}

void CodeEvaluator::execute(const bipc::ir::Code& code, const Frame& frame) {
  if (code.empty()) return;
  stack_.clear();
  run(code, frame);
}

Val CodeEvaluator::call(const Instr& in) {
  const Externs::Function* f = functions_.functions[in.index];
  const std::vector<ValueKind>& kinds = functions_.arg_kinds[in.index];
  const std::size_t count = in.arg;
  if (!f) {
    const bipc::ir::ExternFunction& decl = system_.functions[in.index];
    std::string signature = decl.name + "(";
    for (std::size_t i = 0; i < kinds.size(); ++i) {
      signature += (i ? ", " : "") + std::string(bipc::ir::value_kind_name(kinds[i]));
    }
    throw CodeFault{"extern function " + signature + ") has no implementation"};
  }
  const std::span<const Val> args(stack_.data() + stack_.size() - count, count);
  // Variadic calls see their own argument kinds; the IR declares them per call site.
  call_.arg_kinds = kinds;
  if (f->variadic && count > kinds.size()) call_.arg_kinds = {};
  const Val result = f->fn(call_, args);
  stack_.resize(stack_.size() - count);
  return result;
}

void CodeEvaluator::run(const bipc::ir::Code& code, const Frame& frame) {
  const std::vector<Instr>& instrs = code.instrs;
  for (std::size_t pc = 0; pc < instrs.size(); ++pc) step(instrs[pc], frame, pc);
}

void CodeEvaluator::step(const Instr& in, const Frame& frame, std::size_t& pc) {
  switch (in.op) {
    case Op::PushBool:
      stack_.push_back(make_bool(in.imm.b));
      break;
    case Op::PushInt:
      stack_.push_back(make_int(in.imm.i));
      break;
    case Op::PushFloat:
      stack_.push_back(make_float(in.imm.f));
      break;
    case Op::PushString: {
      Val v;
      v.s = functions_.string_ids[in.index];
      stack_.push_back(v);
      break;
    }
    case Op::Load:
      if (in.scope == Scope::Clock) {
        stack_.push_back(make_float(
            clock_value(frame.clocks[in.index], frame.clock_units[in.index], frame.now)));
      } else {
        stack_.push_back(*slot(in, frame));
      }
      break;
    case Op::Store: {
      const Val v = stack_.back();
      stack_.pop_back();
      if (in.scope == Scope::Clock) {
        ClockState& clock = frame.clocks[in.index];
        clock.value_at = v.f;
        clock.since = frame.now;
      } else {
        *slot(in, frame) = v;
      }
      break;
    }
    case Op::StoreRate: {
      const Val v = stack_.back();
      stack_.pop_back();
      ClockState& clock = frame.clocks[in.index];
      clock.value_at = clock_value(clock, frame.clock_units[in.index], frame.now);
      clock.since = frame.now;
      clock.rate = v.f;
      break;
    }
    case Op::Neg:
      stack_.back() = in.kind == ValueKind::Float ? make_float(-stack_.back().f)
                                                  : make_int(wrap_sub(0, stack_.back().i));
      break;
    case Op::Not:
      stack_.back() = make_bool(!stack_.back().b);
      break;
    case Op::BitNot:
      stack_.back() = make_int(~stack_.back().i);
      break;
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
    case Op::BitAnd:
    case Op::BitOr:
    case Op::BitXor: {
      const Val b = stack_.back();
      stack_.pop_back();
      stack_.back() = arithmetic(in.op, in.kind, stack_.back(), b);
      break;
    }
    case Op::Eq:
    case Op::Ne:
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge: {
      const Val b = stack_.back();
      stack_.pop_back();
      stack_.back() = make_bool(compare(in.op, in.kind, stack_.back(), b, call_.strings));
      break;
    }
    case Op::IntToFloat:
      stack_.back() = make_float(static_cast<double>(stack_.back().i));
      break;
    case Op::Call: {
      const Val result = call(in);
      if (system_.functions[in.index].result) stack_.push_back(result);
      break;
    }
    case Op::Jump:
      pc = in.index - 1;
      break;
    case Op::JumpIfFalse: {
      const bool c = stack_.back().b;
      stack_.pop_back();
      if (!c) pc = in.index - 1;
      break;
    }
    case Op::JumpIfFalseKeep:
      if (!stack_.back().b) {
        pc = in.index - 1;
      } else {
        stack_.pop_back();
      }
      break;
    case Op::JumpIfTrueKeep:
      if (stack_.back().b) {
        pc = in.index - 1;
      } else {
        stack_.pop_back();
      }
      break;
    case Op::Pop:
      stack_.pop_back();
      break;
  }
}

Interval CodeEvaluator::holds_when(const bipc::ir::Code& code, const Frame& frame) {
  if (code.empty()) return Interval::all();
  // Without clocks a guard holds at all dates or at none: no need for time sets.
  if (frame.clocks == nullptr) return holds(code, frame) ? Interval::all() : Interval::none();
  using Kind = TimedItem::Kind;
  // Kept per thread between calls so that a guard's evaluation does not allocate (this runs
  // for every enabled transition of every fired atom); holds_when never re-enters itself.
  thread_local std::vector<TimedItem> stack;
  stack.clear();
  // A `&&`/`||` whose left side depends on time cannot short-circuit: remember it and combine
  // both sides where the jump would have landed.
  struct Pending {
    std::size_t target;
    bool conjunction;
    Interval left;
  };
  thread_local std::vector<Pending> pending;
  pending.clear();
  auto as_set = [](const TimedItem& item) {
    return item.kind == Kind::Set ? item.set : relative_set(item.value.b);
  };
  const std::vector<Instr>& instrs = code.instrs;
  for (std::size_t pc = 0; pc <= instrs.size(); ++pc) {
    while (!pending.empty() && pending.back().target == pc) {
      const Pending p = pending.back();
      pending.pop_back();
      TimedItem& top = stack.back();
      const Interval right = as_set(top);
      top.kind = Kind::Set;
      if (p.conjunction) {
        top.set = p.left.intersect(right);
      } else {
        top.set = right.empty() ? p.left : hull(p.left, right);
      }
    }
    if (pc == instrs.size()) break;
    const Instr& in = instrs[pc];
    switch (in.op) {
      case Op::Load:
        if (in.scope == Scope::Clock) {
          const ClockState& clock = frame.clocks[in.index];
          const auto unit = static_cast<double>(frame.clock_units[in.index]);
          TimedItem item;
          item.kind = Kind::Linear;
          item.a = clock_value(clock, frame.clock_units[in.index], frame.now);
          item.b = clock.rate / unit;
          stack.push_back(item);
        } else {
          stack.push_back({Kind::Plain, *slot(in, frame), 0, 0, {}});
        }
        continue;
      case Op::PushBool:
        stack.push_back({Kind::Plain, make_bool(in.imm.b), 0, 0, {}});
        continue;
      case Op::PushInt:
        stack.push_back({Kind::Plain, make_int(in.imm.i), 0, 0, {}});
        continue;
      case Op::PushFloat:
        stack.push_back({Kind::Plain, make_float(in.imm.f), 0, 0, {}});
        continue;
      case Op::Add:
      case Op::Sub:
      case Op::Neg:
      case Op::IntToFloat:
      case Op::Lt:
      case Op::Le:
      case Op::Gt:
      case Op::Ge:
      case Op::Eq:
      case Op::Ne: {
        const bool binary = in.op != Op::Neg && in.op != Op::IntToFloat;
        const bool timed = stack.back().kind == Kind::Linear ||
                           (binary && stack[stack.size() - 2].kind == Kind::Linear);
        if (!timed) break;  // handled below by the plain machine
        if (!binary) {
          TimedItem& top = stack.back();
          if (in.op == Op::Neg) {
            top.a = -top.a;
            top.b = -top.b;
          }
          continue;
        }
        TimedItem rhs = stack.back();
        stack.pop_back();
        TimedItem& lhs = stack.back();
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
        continue;
      }
      case Op::Not:
        if (stack.back().kind == Kind::Set) {
          // Never produced by checked code (no `!` over clocks); keep the complement's hull.
          const Interval s = stack.back().set;
          stack.back().set = s.empty() ? Interval::all() : Interval::none();
          continue;
        }
        break;
      case Op::JumpIfFalseKeep:
      case Op::JumpIfTrueKeep:
        if (stack.back().kind == Kind::Set) {
          pending.push_back({in.index, in.op == Op::JumpIfFalseKeep, stack.back().set});
          stack.pop_back();
          continue;
        }
        break;
      default:
        break;
    }
    // Plain instruction: run it on the plain values through a one-instruction program.
    if (in.op == Op::Jump || in.op == Op::JumpIfFalse || in.op == Op::JumpIfFalseKeep ||
        in.op == Op::JumpIfTrueKeep) {
      const bool c = in.op == Op::Jump ? false : stack.back().value.b;
      const bool keep = in.op == Op::JumpIfFalseKeep || in.op == Op::JumpIfTrueKeep;
      const bool jump = in.op == Op::Jump ? true : in.op == Op::JumpIfTrueKeep ? c : !c;
      if (in.op != Op::Jump && !(keep && jump)) stack.pop_back();
      if (jump) pc = in.index - 1;
      continue;
    }
    stack_.clear();
    const std::size_t arity =
        in.op == Op::Call                       ? in.arg
        : (in.op >= Op::Add && in.op <= Op::Ge) ? 2
        : (in.op == Op::Neg || in.op == Op::Not || in.op == Op::BitNot || in.op == Op::IntToFloat ||
           in.op == Op::Pop || in.op == Op::Store || in.op == Op::StoreRate)
            ? 1
            : 0;
    for (std::size_t i = stack.size() - arity; i < stack.size(); ++i) {
      const TimedItem& item = stack[i];
      stack_.push_back(item.kind == Kind::Set ? make_bool(!item.set.empty()) : item.value);
    }
    stack.resize(stack.size() - arity);
    std::size_t no_jump = pc;
    step(in, frame, no_jump);
    for (const Val v : stack_) stack.push_back({Kind::Plain, v, 0, 0, {}});
  }
  if (stack.empty()) return Interval::all();
  return shift(as_set(stack.back()), frame.now);
}

}  // namespace smcbip::engines
