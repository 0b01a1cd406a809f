// What the C++ that `bipc gen` generates compiles against, besides model.h's interfaces: the
// frame its code runs over, its faults, the extern functions it calls, and the clock bounds it
// narrows inline. Generated code includes this, code_ops.h and its own headers, nothing else
// of the engines: their layouts and step paths stay inside the engines library.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/api/time_value.h"
#include "engines/api/value.h"

namespace smcbip::engines {

/// A clock of a running atom: its value `value_at` (in its unit) at date `since`, growing at
/// `rate` units per unit of time.
struct ClockState {
  double value_at = 0.0;
  TimeValue since = 0;
  double rate = 1.0;
};

/// The value of a clock at a date, in the clock's unit.
inline double clock_value(const ClockState& clock, TimeValue unit, TimeValue at) {
  return clock.value_at +
         clock.rate * static_cast<double>(at - clock.since) / static_cast<double>(unit);
}

/// Where code finds the slots of its context. Port parameters go through `port_slot` because a
/// connector's port may stand for an atom's data or a sub-connector's exported data.
struct Frame {
  Val* atom_data = nullptr;
  const Val* atom_params = nullptr;
  ClockState* clocks = nullptr;            // null when the atom has no clocks
  const TimeValue* clock_units = nullptr;  // nanoseconds per unit of each clock
  Val* connector_data = nullptr;
  Val* (*port_slot)(const void* context, bipc::ir::Index port, std::uint16_t arg) = nullptr;
  const void* port_context = nullptr;
  Val* (*instance_slot)(const void* context, bipc::ir::Index atom, std::uint16_t slot) = nullptr;
  const void* instance_context = nullptr;
  TimeValue now = 0;
};

/// A run-time fault of model code (division by zero, unknown extern), reported as an error of
/// the run at the instruction's source location, with kInputError: the model's fault, not the
/// tool's.
struct CodeFault {
  std::string message;
  bipc::ir::Index site = bipc::ir::kNone;  // System::sites, where the faulting code was written
};

/// The extern functions a system's calls resolve to, looked up once per model.
struct BoundFunctions {
  std::vector<const Externs::Function*> functions;  // per System::functions entry
  std::vector<std::vector<ValueKind>> arg_kinds;
  std::vector<std::uint64_t> string_ids;  // per System::strings entry, interned
  /// Extern-port classes by backend name (`as "<class>"`); null when none is registered.
  std::map<std::string, const ExternPortFactory*> port_classes;
};

/// The engines' interpreter of `system`'s code (the ModelCode of InterpretedModel): generated
/// code hands it the guards over clocks it does not solve itself (holds_when's time sets).
/// `guard_bounds` as CompiledModel::CodeFactory receives it.
std::unique_ptr<ModelCode> make_interpreted_code(const bipc::ir::System& system,
                                                 const BoundFunctions& functions, CallContext& call,
                                                 const GuardBounds* guard_bounds);

/// Narrows `dates` to the dates at which `clock clock_op literal` holds (clock_op one of < <= >
/// >= ==), in integers, when the floating-point solution of the interpreter's holds_when is sure
/// to be that exact one: a clock running at rate 1 from 0, dates and literal*unit within 2^30 ns
/// of it, |literal| < 2^20. False otherwise, leaving `dates` unspecified: holds_when then answers.
[[gnu::always_inline]] inline bool narrow_to_clock_bound(bipc::ir::Op clock_op,
                                                         std::int64_t literal,
                                                         const ClockState& clock, TimeValue unit,
                                                         TimeValue now, Interval& dates) {
  // A clock running at rate 1 from 0 since `since` reaches the literal L at the integer date
  // r = since + L*unit: the bound holds from (or until) r. holds_when solves for the delay
  // e = r - now in floating point, up to a rounding error below 4 * 2^-53 times the largest of
  // |now - since|, |L*unit| and |e|; under 2^30 ns that is below 1e-6, which solve() rounds to
  // e exactly (finding it "integral"), and then adds now back: the same dates.
  constexpr TimeValue kExact = TimeValue{1} << 30;
  if (clock.rate != 1.0 || clock.value_at != 0.0) return false;
  const TimeValue elapsed = now - clock.since;
  const TimeValue reach = literal * unit;
  if (elapsed < 0 || elapsed >= kExact || reach <= -kExact || reach >= kExact) return false;
  const TimeValue r = clock.since + reach;
  Interval holds = Interval::all();
  switch (clock_op) {
    case bipc::ir::Op::Lt:
    case bipc::ir::Op::Le:
      holds.right = r;
      holds.right_open = clock_op == bipc::ir::Op::Lt;
      break;
    case bipc::ir::Op::Gt:
    case bipc::ir::Op::Ge:
      holds.left = r;
      holds.left_open = clock_op == bipc::ir::Op::Gt;
      break;
    case bipc::ir::Op::Eq:
      holds = Interval::point(r);
      break;
    default:
      return false;
  }
  narrow(dates, holds);
  return true;
}

}  // namespace smcbip::engines
