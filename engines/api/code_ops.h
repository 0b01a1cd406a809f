// What each instruction of the IR's stack code does to plain values, once: the interpreter calls
// these with the instruction's fields, generated C++ with constants (so that they fold away).
#pragma once

#include <cmath>
#include <cstdint>
#include <span>

#include "bipc/ir/ir.h"
#include "engines/api/compiled_model.h"
#include "engines/api/externs.h"
#include "engines/api/value.h"

namespace smcbip::engines::code_ops {

using bipc::ir::Index;
using bipc::ir::Op;
using bipc::ir::Scope;

/// Two's complement arithmetic on 64 bits (overflow wraps, as in the reference engine's C++).
inline std::int64_t wrap_add(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
}
inline std::int64_t wrap_sub(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) - static_cast<std::uint64_t>(b));
}
inline std::int64_t wrap_mul(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b));
}

/// The slot a Load or Store of a scope other than Clock reads or writes.
[[gnu::always_inline]] inline Val* slot(Scope scope, Index index, std::uint16_t arg,
                                        const Frame& f) {
  switch (scope) {
    case Scope::AtomData:
      return f.atom_data + index;
    case Scope::AtomParam:
      return const_cast<Val*>(f.atom_params + index);
    case Scope::ConnectorData:
      return f.connector_data + index;
    case Scope::PortParam:
      return f.port_slot(f.port_context, index, arg);
    case Scope::InstanceData:
      return f.instance_slot(f.instance_context, index, arg);
    case Scope::Clock:
      break;
  }
  return nullptr;
}

/// Load: a slot's value, or a clock's value now in its unit.
[[gnu::always_inline]] inline Val load(Scope scope, Index index, std::uint16_t arg,
                                       const Frame& f) {
  if (scope == Scope::Clock) {
    return make_float(clock_value(f.clocks[index], f.clock_units[index], f.now));
  }
  return *slot(scope, index, arg, f);
}

/// Store: into a slot, or a clock reset to the value (in its unit) now.
[[gnu::always_inline]] inline void store(Scope scope, Index index, std::uint16_t arg,
                                         const Frame& f, Val v) {
  if (scope == Scope::Clock) {
    ClockState& clock = f.clocks[index];
    clock.value_at = v.f;
    clock.since = f.now;
    return;
  }
  *slot(scope, index, arg, f) = v;
}

/// StoreRate: the clock keeps its value now and grows at the new rate from now on.
[[gnu::always_inline]] inline void store_rate(Index clock_index, const Frame& f, Val rate) {
  ClockState& clock = f.clocks[clock_index];
  clock.value_at = clock_value(clock, f.clock_units[clock_index], f.now);
  clock.since = f.now;
  clock.rate = rate.f;
}

[[gnu::always_inline]] inline Val negate(ValueKind kind, Val v) {
  return kind == ValueKind::Float ? make_float(-v.f) : make_int(wrap_sub(0, v.i));
}

/// Eq..Ge on operands of `kind` (strings by text, through the pool).
[[gnu::always_inline]] inline bool compare(Op op, ValueKind kind, Val a, Val b,
                                           const StringPool& strings) {
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

/// Add..BitXor on operands of `kind`; division and modulo by zero are faults at `site`
/// (Instr::site).
[[gnu::always_inline]] inline Val arithmetic(Op op, ValueKind kind, Val a, Val b,
                                             Index site = bipc::ir::kNone) {
  if (kind == ValueKind::Float) {
    switch (op) {
      case Op::Add:
        return make_float(a.f + b.f);
      case Op::Sub:
        return make_float(a.f - b.f);
      case Op::Mul:
        return make_float(a.f * b.f);
      case Op::Div:
        if (b.f == 0.0) throw CodeFault{"division by zero", site};
        return make_float(a.f / b.f);
      default:
        if (b.f == 0.0) throw CodeFault{"modulo by zero", site};
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
      if (b.i == 0) throw CodeFault{"division by zero", site};
      if (b.i == -1) return make_int(wrap_sub(0, a.i));
      return make_int(a.i / b.i);
    case Op::Mod:
      if (b.i == 0) throw CodeFault{"modulo by zero", site};
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

/// Call: extern function `function` of the system on the `count` values ending at `args_end`;
/// a function without an implementation is a fault naming its signature, at `site`.
Val call_extern(const bipc::ir::System& system, const BoundFunctions& functions, CallContext& call,
                Index function, std::size_t count, const Val* args_end, Index site);

}  // namespace smcbip::engines::code_ops
