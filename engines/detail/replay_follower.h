// The run side of a replay: the picker that fires the interaction each step of the trace names,
// and the observer that compares the states reached with the recorded ones. Internal to engines/.
#pragma once

#include <optional>
#include <string>

#include "engines/api/replay.h"
#include "engines/detail/scheduler.h"

namespace smcbip::engines::detail {

class ReplayFollower : public ItemPicker, public RunObserver {
 public:
  explicit ReplayFollower(const ReplayScript& script) : script_(script) {}

  /// The enabled item step `next` of the trace names; nullopt at the end of the trace (or on a
  /// mismatch, recorded in failure()).
  std::optional<std::size_t> pick(const Runtime& runtime) override;
  /// The date the trace records for the step picked last.
  std::optional<TimeValue> date() const override { return date_; }
  /// Compares the state with the one the trace records at that step; false on a mismatch.
  bool observe(const StepInfo& step, const StateView& state) override;
  /// A run that ends (deadlock, time-lock) before the trace does is a mismatch.
  void finish(RunEnd end, int code, const std::string& message) override;

  /// Why the trace could not be followed (code kInputError, `where` the trace's file:line).
  const std::optional<RunResult>& failure() const { return failure_; }

 private:
  void fail(std::size_t line, const std::string& message);
  std::string compare(const ReplayStep& step, const StateView& state) const;

  const ReplayScript& script_;
  std::size_t next_ = 1;  // the step to fire next
  std::optional<RunResult> failure_;
  std::optional<TimeValue> date_;
};

}  // namespace smcbip::engines::detail
