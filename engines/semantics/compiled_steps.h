// The engines' compiled step path, as the schedulers drive it (flat_steps.h makes it).
#pragma once

#include <cstdint>

#include "engines/api/model.h"

namespace smcbip::engines {

struct StepInfo;
class RandomStream;
class Runtime;
class DatePlanner;

/// A step path compiled together with a model's code (flat_steps.h): it takes
/// over a run the engines started and makes the steps the optimised engine would make, with the
/// same random draws, for the models it covers. It reports nothing but its steps: any state it
/// does not cover (an error of the model among them) ends its part of the run as Beyond, and the
/// engines replay the run from its start to find out what happens there.
class CompiledSteps {
 public:
  enum class Outcome : std::uint8_t { Fired, Deadlock, Timelock, Limit, Beyond };
  /// What a run on the compiled path draws from and how it chooses.
  struct Run {
    Runtime& runtime;      // its state: initialised, nothing fired yet
    RandomStream& random;  // the run's stream
    DatePlanner* planner;  // stochastic mode: draws the dates of the race; else nullptr
    bool asap = false, first_enabled = false;
    /// The run starts from the same state as every run before it that had this flag (the
    /// Scheduler's kept initial state): what begin() computes from it may be reused.
    bool kept_start = false;
    /// Each step tells whether it left every place and datum as they were (step_kept_state).
    bool checks_kept_state = false;
  };
  virtual ~CompiledSteps() = default;
  /// Takes over the run. False when its state is not covered.
  virtual bool begin(const Run& run) = 0;
  /// Decides and fires the next step (`info` tells which); Deadlock or Timelock when nothing
  /// is enabled (as the engines tell them apart), else Limit when `at_limit`.
  virtual Outcome step(bool at_limit, StepInfo& info) = 0;
  /// Run::checks_kept_state: whether the last step that fired left every place and datum as
  /// they were (Scheduler::discrete_state_kept), from what it fired alone.
  virtual bool step_kept_state() const = 0;
  /// From the next step on, as if the run had begun with Run::checks_kept_state.
  virtual void check_kept_state() = 0;
};

}  // namespace smcbip::engines
