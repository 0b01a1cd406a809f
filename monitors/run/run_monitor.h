// The online monitor on the engines' runs: an observer that reads each step's state through
// the names resolve_names bound to the model, and stops the run once the verdict is known.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "engines/api/run_observer.h"
#include "monitors/online/critical_bound.h"
#include "monitors/online/extremum.h"
#include "monitors/online/online_monitor.h"
#include "monitors/online/operator_monitor.h"

namespace smcbip::monitors {

/// How the monitors read the end of an engine's run: a deadlock and a time-lock decide, an
/// absorbing state decides formulas over places and data, the other ends cut the run short.
RunEnd monitor_end(engines::RunEnd end);

/// A state of a run as predicates read it: names resolved against the model (Expr::reference).
class EngineState final : public StateView {
 public:
  EngineState(const engines::StepInfo& step, const engines::StateView& state)
      : step_(step), state_(state) {}
  double value(const Expr& name) const override;
  bool fired(const Expr& fired) const override;
  double slope(const Expr& name) const override;

 private:
  const engines::StepInfo& step_;
  const engines::StateView& state_;
};

/// Which monitor judges a RunMonitor's runs: the fastest that takes its formula
/// (OperatorMonitor when it does), or OnlineMonitor always (to cross-check the two).
enum class Monitoring : std::uint8_t { Fastest, General };

/// Judges runs against a formula resolved against their model (resolve_names): give it to
/// engines::Simulator::run as the observer; reset() before each run.
class RunMonitor final : public engines::RunObserver {
 public:
  /// `scale`: nanosecond ticks (the engines' time) per unit of the model's clocks and per
  /// second. `run`: the query's run bound, if any.
  RunMonitor(const Formula& formula, const TimeScale& scale, const Bindings& bindings,
             const Bound& run = {}, Monitoring monitoring = Monitoring::Fastest);

  bool observe(const engines::StepInfo& step, const engines::StateView& state) override;
  void finish(engines::RunEnd end, int code, const std::string& message) override;

  Verdict verdict() const { return fast_ ? fast_->verdict() : general_->verdict(); }
  /// Whether an absorbing end decides the formula (engines::SimulateOptions::stop_absorbing).
  bool decided_by_absorbing() const {
    return fast_ ? fast_->decided_by_absorbing() : general_->decided_by_absorbing();
  }
  /// For F phi: the time (ms) at which phi first held, once the verdict is true; NaN otherwise.
  double first_hit_ms() const;
  void reset() {
    if (fast_) {
      fast_->reset();
    } else {
      general_->reset();
    }
  }
  /// Whether the formula is judged by OperatorMonitor.
  bool fast() const { return fast_.has_value(); }

 private:
  /// Binds the data loads of the fast monitor's programs to the kinds the state's system
  /// declares, and its loads to where the state's data and marking hold them (the same in
  /// every state of that system).
  void bind(const engines::StateView& state);

  std::optional<OperatorMonitor> fast_;
  std::optional<OnlineMonitor> general_;     // when fast_ is not
  const bipc::ir::System* bound_ = nullptr;  // the system fast_'s programs are bound to
};

/// Judges runs against F[0,t] phi or G[0,t] phi for every value of the parameter t at once
/// (CriticalBound); reset() before each run.
class RunCriticalBound final : public engines::RunObserver {
 public:
  /// `scale` as for RunMonitor; `largest`: the parameter's largest value.
  RunCriticalBound(const Formula& formula, const std::string& parameter, double largest,
                   const TimeScale& scale, const Bindings& bindings, const Bound& run = {})
      : bound_(formula, parameter, largest, scale, bindings, run) {}

  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    return !bound_.step(EngineState(step, state), step.time);
  }
  void finish(engines::RunEnd end, int, const std::string&) override {
    bound_.end(monitor_end(end));
  }

  /// The verdict for `value` of the parameter, once the run is over.
  Verdict verdict(double value) const { return bound_.verdict(value); }
  void reset() { bound_.reset(); }

 private:
  CriticalBound bound_;
};

/// The observed value of an expectation query on runs of its model: an observer that stops
/// the run past the query's run bound; reset() before each run.
class RunExtremum final : public engines::RunObserver {
 public:
  /// `scale` as for RunMonitor.
  RunExtremum(const Query& q, const TimeScale& scale, const Bindings& bindings)
      : extremum_(q, scale, bindings) {}

  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    return extremum_.step(EngineState(step, state), step.time,
                          static_cast<std::int64_t>(step.step));
  }
  void finish(engines::RunEnd end, int, const std::string&) override {
    extremum_.end(monitor_end(end));
  }
  std::optional<double> value() const { return extremum_.value(); }
  void reset() { extremum_.reset(); }

 private:
  Extremum extremum_;
};

}  // namespace smcbip::monitors
