// The online monitor of a path formula: it reads a run one step at a time and gives the
// verdict as soon as the steps read decide it, keeping only what the formula's windows still
// need (never the run). Semantics: PROPERTIES.md's continuous reading (a state holds from its
// step's time to the next step's; steps may share a timestamp), non-strict until, a run that
// deadlocks keeps its last state forever while its clocks grow, a run that time-locks or is cut
// short leaves undecided what its missing future could change (Kleene's three values).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bipc/errors.h"
#include "monitors/online/growing_truth.h"
#include "monitors/online/nodes.h"
#include "monitors/online/signal.h"
#include "monitors/property/ast.h"

namespace smcbip::monitors {

/// How the monitor reads a state: the values of the names and fired() of the predicates.
class StateView {
 public:
  virtual ~StateView() = default;
  /// The value of a name (Expr::Kind::Name): data, a clock, 1 or 0 for a place.
  virtual double value(const Expr& name) const = 0;
  /// Whether the step fired what `fired` (Expr::Kind::Fired) names.
  virtual bool fired(const Expr& fired) const = 0;
  /// How fast the value of a name grows after the step, per tick: a clock's rate in its units
  /// per tick; 0 for what only steps change (the default).
  virtual double slope(const Expr& /*name*/) const { return 0; }
};

enum class Verdict : std::uint8_t { False, True, Undecided };

/// How a run ended after its last step: deadlocked (its last state holds forever, time passes
/// and clocks grow), time-locked (time cannot pass its last step's: its last state, where
/// timelock holds, decides what it can, and what follows is unknown), cut short (a limit,
/// an error, a stop: what follows is unknown), or absorbed (steps go on, but none changes the
/// places or data: a formula that reads nothing else sees its last state forever, as after a
/// deadlock; for one that reads clocks, time, events or how the run ends, it is cut short).
enum class RunEnd : std::uint8_t { Deadlock, Timelock, Cut, Absorbing };

/// The time scale of bounds: ticks per unit of the model (a number without a unit) and per
/// second (numbers with s, ms, us, ns); bounds must come to whole ticks.
struct TimeScale {
  double ticks_per_unit = 1e6;  // a model in milliseconds, runs in nanoseconds
  double ticks_per_second = 1e9;
};

/// How time is read: continuously (a state holds from its step's time to the next step's), or
/// pointwise (only at steps: a window holds the steps whose times fall in it; a deadlocked run
/// has no step after its last, whose state X still reads).
enum class Reading : std::uint8_t { Continuous, Pointwise };

/// Values of the constants and parameters the formula names.
using Bindings = std::map<std::string, double>;

/// A state at a moment of its run: the language's own names (time, init, deadlock, timelock)
/// are answered from the run, the others by the state.
class Moment final : public StateView {
 public:
  /// `ticks`: the step's time; `scale` gives time in the model's unit.
  Moment(const StateView& state, online::Tick ticks, const TimeScale& scale, bool initial,
         RunEnd end_here = RunEnd::Cut);
  double value(const Expr& name) const override;
  bool fired(const Expr& fired) const override { return state_.fired(fired); }
  double slope(const Expr& name) const override;

 private:
  const StateView& state_;
  double time_, time_slope_;
  bool initial_;
  RunEnd end_;  // Deadlock or Timelock: this is the run's last state and ends so
};

/// Whether a state expression reads how the run ends (deadlock, timelock).
bool reads_run_end(const Expr& e);
/// Whether a state expression reads only places, data, constants and `init`: nothing that
/// changes in a run whose places and data no longer change (clocks, time, fired, deadlock,
/// timelock).
bool reads_places_and_data_only(const Expr& e);

/// The value of a state expression in `state`; names bound in `bindings` (constants,
/// parameters) read from there. Conditions are 1 or 0.
double evaluate(const Expr& e, const StateView& state, const Bindings& bindings);

/// x / y and x % y (C's, on whole numbers) for the operator `at`; a zero divisor, or an operand
/// of % beyond 64 bits, throws MonitorError at the operator's position.
double divide(const Expr& at, double x, double y);
double remainder(const Expr& at, double x, double y);

/// `v` (a number, or a name bound in `bindings`) as a bound in whole ticks of `scale`. Throws
/// MonitorError when it is negative, unbound or finer than a tick.
online::Tick bound_ticks(const Value& v, const TimeScale& scale, const Bindings& bindings);
/// `v` as a whole number (a step count) at least 0. Throws MonitorError.
std::int64_t bound_steps(const Value& v, const Bindings& bindings);

/// A formula the monitor cannot take: a bound not a whole number of ticks, an unbound name, a
/// division by zero. An input error at `at` in the property file (whose path the caller knows:
/// `at.file` indexes its sources).
class MonitorError : public InputError {
 public:
  MonitorError(Location at, const std::string& message)
      : InputError(message, ErrorLocation{{}, at.line, at.column}), at(at) {}
  Location at;
};

class OnlineMonitor {
 public:
  /// The monitor of `formula` (which must outlive it) on runs observed for `run` (a query's
  /// [<=T] or [#<=K]; none: as long as they last): beyond it nothing exists for the formula,
  /// so what it awaits fails and what it forbids holds. Throws MonitorError.
  OnlineMonitor(const Formula& formula, const TimeScale& scale, const Bindings& bindings,
                const Bound& run = {}, Reading reading = Reading::Continuous);
  OnlineMonitor(const OnlineMonitor& other);
  OnlineMonitor& operator=(const OnlineMonitor& other);
  OnlineMonitor(OnlineMonitor&&) noexcept = default;
  OnlineMonitor& operator=(OnlineMonitor&&) noexcept = default;
  ~OnlineMonitor();

  /// Reads the next step: its state and its time (ticks, not before the previous step's; the
  /// first step's time is the run's start). Returns the verdict as far as known.
  Verdict step(const StateView& state, online::Tick time);
  /// The run ended after the last step read; returns the final verdict.
  Verdict end(RunEnd how);
  Verdict verdict() const { return verdict_; }
  /// Whether the verdict is final: the steps read decided it, or the run ended.
  bool over() const { return decided_; }
  /// Whether an Absorbing end decides the formula (it reads places and data only).
  bool decided_by_absorbing() const { return places_and_data_only_; }
  /// Ready for a new run.
  void reset();

  /// When the root is F or G: the first position that decides it (see Node::first_hit), for
  /// sure and possibly (they differ on runs cut short), once the verdict is known.
  online::Pos first_hit_for_sure() const { return sure_hit_; }
  online::Pos first_hit_possibly() const { return possible_hit_; }

  /// The runs held in the subformulas' signals (what the monitor remembers of the run).
  std::size_t held_runs() const;
  /// The subformulas after sharing and simplification.
  std::size_t size() const { return nodes_.size(); }

 private:
  struct Leaf {
    std::size_t node = 0;
    const Expr* predicate = nullptr;  // null: a constant
    bool negated = false;             // a predicate's negation, or a constant's value
    bool grows = false;               // reads clocks or time: may change between steps
    bool reads_end = false;           // reads deadlock or timelock
  };
  /// A leaf's truth along the last step read: as it holds if the run goes on, and if the run
  /// deadlocks or time-locks there (for leaves that read how it ends).
  struct Pending {
    std::vector<TruthChange> going_on, deadlock, timelock;
  };
  class Builder;

  /// Every leaf's value of the last step read, up to `end`, as the run goes on or ends.
  void emit_leaves(online::Pos end, RunEnd how = RunEnd::Cut);
  /// A leaf's truth along the last step (or its value at the step, `pointwise_`).
  void compute(const Leaf& leaf, const StateView& state, online::Tick time, RunEnd how,
               std::vector<TruthChange>& out) const;
  void advance();
  /// The root's value at the first position, once known.
  const online::Run* root_run();
  /// The verdict of a run cut short after the last step when what follows reads `unknown`
  /// at every leaf (false: what holds for sure; true: what may hold), and the root's first
  /// hit then. It finishes the run in the monitor's state.
  Verdict finish_cut(bool unknown, online::Pos& hit);
  void decide(Verdict verdict);
  /// The observation ended with `end`, its last position: the verdict is then known.
  void finish_observation(online::Pos end);

  // The formula as built (operands before what reads them; the root last) and its blank
  // signals, copied by reset.
  std::vector<std::unique_ptr<online::Node>> blank_nodes_;
  online::Signals blank_signals_;
  std::vector<Leaf> leaves_;
  std::size_t root_ = 0, root_reader_ = 0;
  Bindings bindings_;
  TimeScale scale_;
  bool pointwise_ = false;
  bool reads_steps_ = false;          // some node counts steps (X, step bounds): segments are kept
  bool places_and_data_only_ = true;  // every leaf reads_places_and_data_only
  online::Tick time_bound_ = online::kNever;  // in half ticks
  std::int64_t step_bound_ = std::numeric_limits<std::int64_t>::max();

  std::vector<std::unique_ptr<online::Node>> nodes_;
  online::Signals signals_;
  std::vector<Pending> pending_;  // per leaf: its truth along the last step read
  bool started_ = false;
  std::int64_t steps_ = 0;  // the steps read
  online::Tick origin_ = 0;
  online::Pos last_{};  // the last step's first position
  Verdict verdict_ = Verdict::Undecided;
  bool decided_ = false;
  online::Pos sure_hit_ = online::kForever, possible_hit_ = online::kForever;
};

}  // namespace smcbip::monitors
