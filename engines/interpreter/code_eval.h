// Evaluation of the IR's stack code: plain values for actions and data guards, and time sets
// for guards over clocks (the interval of dates at which the guard holds).
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/compiled_model.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/api/time_value.h"
#include "engines/api/value.h"

namespace smcbip::engines {

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
    return engines::clock_value(clock, unit, at);
  }

 private:
  /// Runs the code over stack_; returns how many values it leaves there.
  std::size_t run(const bipc::ir::Code& code, const Frame& frame);
  /// One instruction other than a jump over the values below `sp`; returns the new top.
  /// Inlined into run(): a call per instruction cost as much as the instruction.
  [[gnu::always_inline]] inline Val* apply(const bipc::ir::Instr& in, const Frame& frame, Val* sp);
  /// Call: the arguments below `sp` give way to the extern function's result, if it has one.
  [[gnu::always_inline]] inline Val* call(const bipc::ir::Instr& in, Val* sp);
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
