// Evaluation of the IR's stack code: plain values for actions and data guards, and time sets
// for guards over clocks (the interval of dates at which the guard holds).
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/externs.h"
#include "engines/model.h"
#include "engines/time_value.h"
#include "engines/value.h"

namespace smcbip::engines {

/// A clock of a running atom: its value `value_at` (in its unit) at date `since`, growing at
/// `rate` units per unit of time.
struct ClockState {
  double value_at = 0.0;
  TimeValue since = 0;
  double rate = 1.0;
};

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

/// Resolves the system's extern functions against a registry and interns its string literals;
/// an error message names the first function without an implementation.
std::string bind_functions(const bipc::ir::System& system, const Externs& externs,
                           StringPool& strings, BoundFunctions& out);

class GuardBounds;

namespace detail {

/// A value of a guard over clocks during CodeEvaluator::holds_when: a plain value, a value
/// linear in the delay d (ns) from now (a + b*d), or the set of delays at which a condition
/// holds.
struct TimedItem {
  enum class Kind : std::uint8_t { Plain, Linear, Set } kind = Kind::Plain;
  Val value{};
  double a = 0.0, b = 0.0;
  Interval set;  // relative delays
};

/// The left side of a `&&` (conjunction) or `||` over clocks, joined with the right side at
/// instruction `target`, where the short-circuit jump would have landed.
struct PendingJoin {
  std::size_t target = 0;
  bool conjunction = false;
  Interval left;
};

}  // namespace detail

/// Interprets the IR's code over one frame (the ModelCode of InterpretedModel). Not
/// thread-safe: one evaluator per thread.
class CodeEvaluator final : public ModelCode {
 public:
  /// `guard_bounds`, when given, answers holds_when for the guards it knows.
  CodeEvaluator(const bipc::ir::System& system, const BoundFunctions& functions, CallContext& call,
                const GuardBounds* guard_bounds = nullptr);

  Val evaluate(const bipc::ir::Code& code, const Frame& frame) override;
  void execute(const bipc::ir::Code& code, const Frame& frame) override;
  Interval holds_when(const bipc::ir::Code& code, const Frame& frame) override;

  /// The value of a clock at a date, in the clock's unit.
  static double clock_value(const ClockState& clock, TimeValue unit, TimeValue at) {
    return clock.value_at +
           clock.rate * static_cast<double>(at - clock.since) / static_cast<double>(unit);
  }

 private:
  /// Runs the code over stack_; returns how many values it leaves there.
  std::size_t run(const bipc::ir::Code& code, const Frame& frame);
  /// One instruction other than a jump over the values below `sp`; returns the new top.
  /// Inlined into run(): a call per instruction cost as much as the instruction.
  [[gnu::always_inline]] inline Val* apply(const bipc::ir::Instr& in, const Frame& frame, Val* sp);
  // holds_when's steps over the stack of time sets below `sp`.
  static void join_sides(const detail::PendingJoin& join, detail::TimedItem& top);
  /// Instructions that time sets change; false leaves the instruction to the plain machine.
  [[gnu::always_inline]] inline bool timed_step(const bipc::ir::Instr& in, const Frame& frame,
                                                detail::TimedItem*& sp, detail::PendingJoin*& join);
  [[gnu::always_inline]] static inline bool linear_step(const bipc::ir::Instr& in,
                                                        detail::TimedItem*& sp);
  detail::TimedItem* plain_step(const bipc::ir::Instr& in, const Frame& frame,
                                detail::TimedItem* sp);

  const bipc::ir::System& system_;
  const BoundFunctions& functions_;
  CallContext& call_;
  const GuardBounds* guard_bounds_;
  std::vector<Val> stack_;  // sized, not grown: run() indexes it through a pointer
  // holds_when's stacks, kept between calls so that guards do not allocate (holds_when never
  // re-enters itself).
  std::vector<detail::TimedItem> timed_;
  std::vector<detail::PendingJoin> joins_;
};

}  // namespace smcbip::engines
