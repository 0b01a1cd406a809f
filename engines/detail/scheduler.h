// The scheduling of one run, shared by Simulator (whole runs with a trace) and Execution (a run
// its host drives step by step): what the run does next and doing it. Internal to engines/.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <optional>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "engines/api/simulate.h"
#include "engines/semantics/compiled_steps.h"
#include "engines/semantics/item_race.h"
#include "engines/semantics/runtime.h"
#include "engines/semantics/shared_window.h"
#include "engines/stochastic/date_planner.h"

namespace smcbip::engines {

namespace detail {
struct RunParts;
}

/// What the runs of one model share: the layout, the bound externs, the seed.
struct Simulator::Shared {
  std::unique_ptr<InterpretedModel> owned;  // when built from an IR
  const Model& model;
  const bipc::ir::System& system;
  SimulateOptions options;
  Layout layout;
  StringPool strings;
  /// The caller's extern functions, copied: `functions` points into this copy, so a registry
  /// that does not outlive the simulator (a temporary) is fine.
  Externs externs;
  BoundFunctions functions;
  CustomDistributions custom;
  std::string problem;
  std::uint64_t seed = 0;
  bool stochastic = false;
  /// options.stop_absorbing on a model where the places and data alone decide what is
  /// enabled (see SimulateOptions::stop_absorbing): runs look for absorbing states.
  bool absorbing_checks = false;
  /// A run has ended in an absorbing state: the next ones look for them from their start
  /// (SimulateOptions::absorbing_after).
  bool absorbed_once = false;
  /// Whether a run looks for absorbing states from its first step.
  bool checks_absorbing_from_start() const {
    return absorbing_checks && (options.absorbing_after == 0 || absorbed_once);
  }
  /// No extern ports or functions: the initial actions and resumes, the only other code
  /// start() runs, draw nothing and read nothing from outside, so every run starts in the same
  /// state.
  bool same_start = false;
  /// The runtimes (with their buffers) of runs that ended, for the next runs to take over
  /// rather than build their own: one run's set-up cost as much as a short run.
  std::vector<std::unique_ptr<detail::RunParts>> spare_parts;

  Shared(const Model& m, const SimulateOptions& o) : model(m), system(m.system()), options(o) {}
  Shared(std::unique_ptr<InterpretedModel> m, const SimulateOptions& o)
      : owned(std::move(m)), model(*owned), system(owned->system()), options(o) {}
  /// Builds the layout, binds (a copy of) `externs`, loads the custom distributions and fixes
  /// the seed;
  /// `problem` says what failed.
  void prepare(const Externs& externs);
};

namespace detail {

/// What a run does next, as Scheduler::decide found it.
struct Decision {
  enum class Kind : std::uint8_t {
    Fire,     // execute `item` (the `chosen`-th of the state's items) at `date`
    Receive,  // extern events no port can take arrive at `date`; then decide again
    End,      // the run ends with `end` (`code`: an Error's, see Scheduler::error())
  } kind = Kind::End;
  std::size_t chosen = 0;
  TimeValue date = 0;
  Item item;
  RunEnd end = RunEnd::Deadlock;
  int code = kRunOk;
};

/// What observers are told of the step that fires `item` at `at`, the `step`-th.
inline StepInfo step_info(const Item& item, const Runtime& runtime, std::uint64_t step,
                          TimeValue at) {
  StepInfo info;
  info.step = step;
  info.time = at;
  switch (item.kind) {
    case Item::Kind::Interaction:
      info.fired = StepInfo::Fired::Interaction;
      info.connector = runtime.values()[item.value].connector;
      return info;
    case Item::Kind::Internal:
      info.fired = StepInfo::Fired::Internal;
      break;
    case Item::Kind::External:
      info.fired = StepInfo::Fired::External;
      break;
  }
  info.atom = item.atom;
  info.port = item.port;
  return info;
}

/// Picks the item of each step instead of the random choice (--interactive).
class ItemPicker {
 public:
  virtual ~ItemPicker() = default;
  /// An index into runtime.items(); nullopt stops the run.
  virtual std::optional<std::size_t> pick(const Runtime& runtime) = 0;
  /// The date the last pick fires at, when it lies in the item's window (a replay's recorded
  /// date); otherwise, or without one, the window's earliest.
  virtual std::optional<TimeValue> date() const { return std::nullopt; }
};

/// What a run builds once and a later run of the same simulator (writing the model's output to
/// the same stream) takes over: the runtime with its buffers, the date planner, the stream they
/// draw from.
struct RunParts {
  RunParts(Simulator::Shared& shared, std::ostream& model_output);
  std::ostream* output;
  RandomStream random;
  SharedWindowChooser shared_window;
  Runtime runtime;
  DatePlanner planner;
  std::vector<TimeValue> dates;  // the stochastic race's planned dates, per item
  std::string planner_problem;   // reused: planning a date may fail with a message
  /// absorbing_checks: the places, data and pending resumes before a step, and the state whose
  /// items Scheduler::absorbing() tries (reused: a run would otherwise allocate them afresh).
  std::vector<Val> data_before;
  std::vector<std::uint8_t> marking_before, resume_before;
  RunState absorbing_probe;
  /// The state start() left the first time, when every run starts from it (see
  /// Shared::same_start): a run on the compiled step path starts from a copy.
  std::optional<RunState> initial_state;
  /// The model's compiled step path over this runtime (made once; null when it has none).
  std::unique_ptr<CompiledSteps> compiled_steps;
  bool compiled_steps_made = false;
};

/// One run's random stream, semantics and choice of items: the reference engine's random race
/// of dates (or its two-draw shortcut on a shared window), the stochastic race of planned dates,
/// or a picker's choice. In simulated time it also resumes atoms after each step; real time is
/// left to the caller (it waits, then checks time safety, which resumes).
class Scheduler {
 public:
  /// Takes over the parts a finished run left in `shared` when it wrote to `model_output`.
  Scheduler(Simulator::Shared& shared, std::uint64_t run_index, std::ostream& model_output,
            ItemPicker* picker = nullptr);
  /// Leaves its parts to the next run.
  ~Scheduler();
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  /// Initial actions and checks, and in simulated time the initial resumes; false with error()
  /// set on failure.
  bool start();
  /// start() for a run on the compiled step path, which reads the runtime's state alone (not
  /// its items): a copy of the state the first start() left when every run starts the same, so
  /// that a short run does not pay for the initial actions and items again. A path that
  /// falls back to the runtime's steps restarts it.
  bool start_state();
  /// After start_state(): whether the state is the copy it keeps, the same in every run that
  /// started so.
  bool started_from_kept_state() const;
  /// start() for run `run_index` of the seed: a new run from the initial state, which reuses
  /// the buffers the last one grew.
  bool restart(std::uint64_t run_index);
  /// Makes this scheduler run `run_index` as a new one would, before start or start_state.
  void renew(std::uint64_t run_index);
  /// Computes the current state's items and decides what comes next; the random draws of the
  /// choice happen here. The decision (decision()) holds until the next decide(); a Fire or
  /// Receive decision can be carried out until the state changes.
  [[gnu::always_inline]] inline const Decision& decide();
  /// The last decision.
  const Decision& decision() const { return decision_; }
  /// Carries out a Fire or Receive decision (a Fire counts one step); false with error() set.
  [[gnu::always_inline]] inline bool perform(const Decision& decision);

  std::uint64_t steps() const { return steps_; }
  /// Why the run failed (after start, decide or perform reported an error).
  const ModelError& error() const { return error_; }
  /// Records the runtime's error as error() after a direct use of runtime() failed; false.
  bool record_error();
  Runtime& runtime() { return runtime_; }
  const Runtime& runtime() const { return runtime_; }
  /// The run's random stream (a compiled step path draws from it in the scheduler's stead).
  RandomStream& random() { return random_; }
  /// The stochastic race's date planner (a compiled step path draws with it, keeping its own
  /// plans).
  DatePlanner& planner() { return planner_; }
  /// The model's compiled step path over runtime(), made by the first run that asks and kept
  /// by the next ones; null when the model has none.
  CompiledSteps* compiled_steps();

 private:
  /// absorbing_checks: the places, data and pending resumes before a step, to tell whether it
  /// changed them.
  void remember_discrete_state();
  bool discrete_state_kept(const RunState& state) const;
  /// An Error end with the runtime's error.
  const Decision& fail();
  const Decision& end(RunEnd end, int code = kRunOk);
  const Decision& receive(TimeValue arrival);
  [[gnu::always_inline]] inline std::optional<std::pair<std::size_t, TimeValue>> choose(
      bool& failed);
  [[gnu::always_inline]] inline std::optional<std::pair<std::size_t, TimeValue>>
  shared_window_choice();
  [[gnu::always_inline]] inline std::pair<std::size_t, TimeValue> random_choice();
  [[gnu::always_inline]] inline std::optional<std::pair<std::size_t, TimeValue>> race(bool& failed);
  [[gnu::always_inline]] inline std::optional<std::pair<std::size_t, TimeValue>>
  earliest_in_window();
  /// Whether every item of the current state (its items computed) keeps its places, data and
  /// pending resumes; the runtime is left in that state, its items computed again (`failed`
  /// when that fails, with the runtime's error).
  bool absorbing(bool& failed);

  Simulator::Shared& shared_;
  const SimulateOptions& options_;
  ItemPicker* picker_;
  std::unique_ptr<RunParts> parts_;
  RandomStream& random_;
  SharedWindowChooser& shared_window_;
  Runtime& runtime_;
  DatePlanner& planner_;
  std::vector<TimeValue>& dates_;
  std::string& planner_problem_;
  std::uint64_t steps_ = 0;
  ModelError error_;
  Decision decision_;
  // absorbing_checks: the last step changed no place, data or pending resume.
  bool idle_step_ = false;
  // absorbing_checks, from step options.absorbing_after on: the steps tell whether they did.
  bool checks_absorbing_ = false;
};

// The per-step functions are inlined into each scheduler loop (Simulator's, Execution's), as they
// were when the loop had them to itself: calls, and the copies of what they return, cost a few
// percent of an optimised step.

inline std::optional<std::pair<std::size_t, TimeValue>> Scheduler::choose(bool& failed) {
  if (picker_) {
    const std::optional<std::size_t> picked = picker_->pick(runtime_);
    if (!picked) return std::nullopt;
    const Interval& window = runtime_.items()[*picked].constraint.interval;
    const std::optional<TimeValue> wanted = picker_->date();
    if (wanted && *wanted >= runtime_.state().now && window.contains(*wanted)) {
      return std::pair{*picked, *wanted};
    }
    return std::pair{*picked, earliest(window, runtime_.state().now)};
  }
  if (shared_.stochastic) return race(failed);
  if (auto choice = shared_window_choice()) return choice;
  return std::pair{random_choice()};
}

/// random_choice when every item has the same window (untimed models): SharedWindowChooser
/// on the windows [now, +inf) and {now}; nullopt on other windows.
inline std::optional<std::pair<std::size_t, TimeValue>> Scheduler::shared_window_choice() {
  if (!shared_.layout.untimed) return std::nullopt;
  const TimeValue now = runtime_.state().now;
  const Interval& window = runtime_.items_window();
  const bool open_ended = window == Interval::from(now);
  if (!open_ended && !(window == Interval::point(now))) return std::nullopt;
  const SharedWindowChoice choice = shared_window_.choose(
      runtime_.item_count(), now, open_ended, options_.asap, options_.first_enabled, random_);
  return std::pair{choice.chosen, choice.date};
}

/// The reference scheduler: every item draws a date in its window, the earliest wins.
inline std::pair<std::size_t, TimeValue> Scheduler::random_choice() {
  const auto& items = runtime_.items();
  return random_race(
      items.size(), [&](std::size_t i) -> const Interval& { return items[i].constraint.interval; },
      runtime_.state().now, options_.asap, options_.first_enabled, random_);
}

/// Stochastic mode: the earliest planned date that lies in its item's window wins.
inline std::optional<std::pair<std::size_t, TimeValue>> Scheduler::race(bool& failed) {
  if (!planner_.plan(runtime_, dates_, planner_problem_)) {
    error_ = {kInputError, planner_problem_, {}};
    failed = true;
    return std::nullopt;
  }
  std::optional<std::pair<std::size_t, TimeValue>> best = earliest_in_window();
  if (!best) {
    planner_.replan_within_windows(runtime_, dates_);
    best = earliest_in_window();
  }
  if (best) planner_.fired(runtime_, runtime_.items()[best->first]);
  return best;
}

inline std::optional<std::pair<std::size_t, TimeValue>> Scheduler::earliest_in_window() {
  const auto& items = runtime_.items();
  return engines::earliest_in_window(
      items.size(), [&](std::size_t i) -> const Interval& { return items[i].constraint.interval; },
      [&](std::size_t i) { return dates_[i]; }, random_);
}

inline const Decision& Scheduler::decide() {
  if (!runtime_.compute_items()) return fail();
  const std::optional<TimeValue> arrival = runtime_.next_unexpected_arrival();
  if (runtime_.item_count() == 0) {
    if (!arrival || !runtime_.wait_interval().contains(*arrival)) {
      const bool deadlock = runtime_.wait_interval().right == kPlusInfinity;
      return end(deadlock ? RunEnd::Deadlock : RunEnd::Timelock);
    }
    return receive(*arrival);
  }
  if (idle_step_ && !arrival) {
    idle_step_ = false;
    bool failed = false;
    if (absorbing(failed)) {
      shared_.absorbed_once = true;
      return end(RunEnd::Absorbing);
    }
    if (failed) return fail();
  }
  if (options_.limit && steps_ >= *options_.limit) return end(RunEnd::Limit);
  bool failed = false;
  const std::optional<std::pair<std::size_t, TimeValue>> choice = choose(failed);
  if (failed) return end(RunEnd::Error, error_.code);
  if (!choice) return end(picker_ ? RunEnd::Stopped : RunEnd::Timelock);
  if (arrival && *arrival <= choice->second) return receive(*arrival);
  decision_.kind = Decision::Kind::Fire;
  decision_.chosen = choice->first;
  decision_.date = choice->second;
  // Built in place from the returned item (an assignment would copy it): Item is trivially
  // destructible.
  static_assert(std::is_trivially_destructible_v<Item>);
  ::new (&decision_.item) Item(runtime_.item(choice->first));
  return decision_;
}

inline bool Scheduler::perform(const Decision& decision) {
  if (decision.kind == Decision::Kind::Receive) {
    return runtime_.receive_unexpected_events(decision.date) || record_error();
  }
  if (checks_absorbing_) remember_discrete_state();
  if (!runtime_.execute(decision.item, decision.date)) return record_error();
  ++steps_;
  if (!options_.real_time && !runtime_.resume_atoms(decision.date)) return record_error();
  if (checks_absorbing_) {
    idle_step_ = discrete_state_kept(runtime_.state());
  } else if (shared_.absorbing_checks && steps_ >= options_.absorbing_after) {
    checks_absorbing_ = true;
  }
  return true;
}

}  // namespace detail

}  // namespace smcbip::engines
