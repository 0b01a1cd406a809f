// The online monitor of a path formula: it reads a run one step at a time and gives the
// verdict as soon as the steps read decide it, keeping only what the formula's windows still
// need (never the run). Semantics: PROPERTIES.md's continuous reading (a state holds from its
// step's time to the next step's; steps may share a timestamp), non-strict until, a run that
// deadlocks keeps its last state forever, a run cut short leaves undecided what its missing
// future could change (Kleene's three values).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

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
};

enum class Verdict : std::uint8_t { False, True, Undecided };

/// How a run ended after its last step: deadlocked (its last state holds forever), or cut
/// short (a time-lock, a limit, an error: what follows is unknown).
enum class RunEnd : std::uint8_t { Deadlock, Cut };

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

/// The value of a state expression in `state`; names bound in `bindings` (constants,
/// parameters) read from there. Conditions are 1 or 0.
double evaluate(const Expr& e, const StateView& state, const Bindings& bindings);

/// `v` (a number, or a name bound in `bindings`) as a bound in whole ticks of `scale`. Throws
/// MonitorError when it is negative, unbound or finer than a tick.
online::Tick bound_ticks(const Value& v, const TimeScale& scale, const Bindings& bindings);
/// `v` as a whole number (a step count) at least 0. Throws MonitorError.
std::int64_t bound_steps(const Value& v, const Bindings& bindings);

/// A formula the monitor cannot take: a bound not a whole number of ticks, an unbound name.
class MonitorError : public std::runtime_error {
 public:
  MonitorError(Location at, const std::string& message) : std::runtime_error(message), at(at) {}
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
  };
  class Builder;

  /// Every leaf's value of the last step read, up to `end`.
  void emit_leaves(online::Pos end);
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
  bool holds(const Leaf& leaf, const StateView& state) const;

  // The formula as built (operands before what reads them; the root last) and its blank
  // signals, copied by reset.
  std::vector<std::unique_ptr<online::Node>> blank_nodes_;
  online::Signals blank_signals_;
  std::vector<Leaf> leaves_;
  std::size_t root_ = 0, root_reader_ = 0;
  Bindings bindings_;
  bool reads_steps_ = false;  // some node counts steps (X, step bounds): segments are kept
  online::Tick time_bound_ = online::kNever;  // in half ticks
  std::int64_t step_bound_ = std::numeric_limits<std::int64_t>::max();

  std::vector<std::unique_ptr<online::Node>> nodes_;
  online::Signals signals_;
  std::vector<bool> pending_;  // per leaf: its value in the last step read
  bool started_ = false;
  std::int64_t steps_ = 0;  // the steps read
  online::Tick origin_ = 0;
  online::Pos last_{};  // the last step's first position
  Verdict verdict_ = Verdict::Undecided;
  bool decided_ = false;
  online::Pos sure_hit_ = online::kForever, possible_hit_ = online::kForever;
};

}  // namespace smcbip::monitors
