// Simulation runs: the scheduling loop over the shared semantics, in simulated or real time,
// with the reference engine's random choice or the stochastic race of planned dates.
#include "engines/api/simulate.h"

#include <chrono>
#include <iostream>
#include <thread>

#include "engines/detail/replay_follower.h"
#include "engines/detail/scheduler.h"
#include "engines/engine.h"
#include "engines/explore.h"
#include "engines/interactive.h"
#include "engines/trace/jsonl_trace.h"
#include "engines/trace/text_trace.h"

namespace smcbip::engines {

namespace {

using detail::Decision;
using detail::step_info;

/// The observers of one run: the caller's, and the JSON-lines writer when asked for.
class Observers : public RunObserver {
 public:
  Observers(RunObserver* user, JsonlTrace* jsonl) : user_(user), jsonl_(jsonl) {}
  bool observe(const StepInfo& step, const StateView& state) override {
    if (jsonl_) jsonl_->observe(step, state);
    return !user_ || user_->observe(step, state);
  }
  void finish(RunEnd end, int code, const std::string& message) override {
    if (jsonl_) jsonl_->finish(end, code, message);
    if (user_) user_->finish(end, code, message);
  }

 private:
  RunObserver* user_;
  JsonlTrace* jsonl_;
};

/// --interactive: the state is listed, then a person picks its item at the prompt.
class PromptPicker : public detail::ItemPicker {
 public:
  PromptPicker(std::ostream& out, std::istream* input, const std::uint64_t& steps, bool verbose)
      : out_(out), input_(input), steps_(steps), verbose_(verbose) {}
  std::optional<std::size_t> pick(const Runtime& runtime) override {
    if (verbose_) write_state(out_, runtime, steps_);
    return prompt_choice(out_, input_, runtime.items().size());
  }

 private:
  std::ostream& out_;
  std::istream* input_;
  const std::uint64_t& steps_;
  bool verbose_;
};

}  // namespace

namespace detail {

/// One run of a Simulator: the scheduler's decisions, the text trace, real time. Kept by the
/// simulator for its next run on the same streams (renew), which then costs no set-up.
class Simulation {
 public:
  /// `picker` (optional) chooses the items instead of the scheduler (a replay).
  Simulation(Simulator::Shared& shared, std::uint64_t run_index, const RunStreams& streams,
             RunObserver& observer, detail::ItemPicker* picker = nullptr)
      : shared_(shared),
        options_(shared.options),
        out_(streams.trace),
        model_out_(streams.model),
        input_(streams.input),
        observer_(&observer),
        verbose_(!options_.silent && options_.trace == TraceFormat::Text),
        picker_(streams.trace, streams.input, steps_, verbose_),
        scheduler_(shared, run_index, streams.model,
                   picker                 ? picker
                   : options_.interactive ? &picker_
                                          : nullptr),
        picked_(picker != nullptr),
        runtime_(scheduler_.runtime()),
        run_index_(run_index) {}

  /// Whether a run on `streams` can be made by this simulation (renew).
  bool writes_to(const RunStreams& streams) const {
    return &streams.trace == &out_ && &streams.model == &model_out_ && streams.input == input_;
  }
  /// Makes this simulation run `run_index` with `observer`, as a new one would (its error, as
  /// the scheduler's, is only read once a failure of the run has set it).
  void renew(std::uint64_t run_index, RunObserver& observer) {
    observer_ = &observer;
    steps_ = 0;
    run_index_ = run_index;
    scheduler_.renew(run_index);
  }

  RunResult explore() {
    if (!options_.silent) {
      line("BIP Engine (version " SMCBIP_VERSION_TEXT " )");
      out_ << "[BIP ENGINE]:\n";
      line("initialize components...");
    }
    if (!runtime_.initialize() || !runtime_.resume_atoms(0)) return runtime_error();
    const ExplorationCounts counts =
        explore_states(runtime_, options_.limit, options_.max_explored_states);
    write_exploration(out_, counts);
    return {kRunOk, counts.cut ? RunEnd::Limit : RunEnd::Deadlock, counts.states, {}, {}};
  }

  RunResult run() {
    if (verbose_) {
      line("BIP Engine (version " SMCBIP_VERSION_TEXT " )");
      line("");
      line("initialize components...");
      line(picked_ ? std::string("following a recorded trace")
                   : "random scheduling based on seed=" + std::to_string(shared_.seed));
    }
    // Only real time reads the platform clock (a system call's worth of time per run).
    if (options_.real_time) start_ = std::chrono::steady_clock::now();
    CompiledSteps* steps = compiled_steps();
    if (!(steps ? scheduler_.start_state() : scheduler_.start())) return error();
    if (options_.real_time && !real_time_after_step()) return error_result_;
    if (!observe(StepInfo{})) return stopped();
    if (steps) {
      if (const std::optional<RunEnd> how = run_compiled(*steps)) return end(*how);
      if (std::optional<RunResult> result = replay_quietly(steps_)) return std::move(*result);
    }
    for (;;) {
      const Decision& decision = scheduler_.decide();
      if (decision.kind == Decision::Kind::End) return finish(decision);
      if (decision.kind == Decision::Kind::Receive) {
        if (options_.real_time) wait_until(decision.date);
        if (!scheduler_.perform(decision)) return error();
        continue;
      }
      // Only the text trace shows every item: other runs never have them listed.
      if (verbose_) {
        if (!options_.interactive) write_state(out_, runtime_, steps_);
        line("-> choose [" + std::to_string(decision.chosen) + "] " +
             item_text(runtime_, decision.item, false) + " at global time " +
             format_time(decision.date));
      }
      const StepInfo info = step_info(decision.item, runtime_, steps_ + 1, decision.date);
      if (options_.real_time) wait_until(decision.date);
      if (!scheduler_.perform(decision)) return error();
      steps_ = scheduler_.steps();
      if (options_.real_time && !real_time_after_step()) return error_result_;
      if (!observe(info)) return stopped();
    }
  }

 private:
  void line(const std::string& text) { out_ << kEnginePrefix << text << "\n"; }
  void header(const std::string& summary) {
    if (verbose_) {
      line("state #" + std::to_string(steps_) + " and global time " +
           format_time(runtime_.state().now) + ": " + summary);
    }
  }

  /// The model's compiled step path, when it has one and this run can take it: an engine that
  /// takes it (the optimised one), in simulated time, without a text trace or a prompt.
  CompiledSteps* compiled_steps() {
    if (!engine_of(options_.engine).takes_compiled_steps() || options_.real_time ||
        options_.interactive || picked_ || verbose_ || options_.disable_maximal_progress) {
      return nullptr;
    }
    return scheduler_.compiled_steps();
  }

  /// The run on the compiled step path: how it ends (well: the path reports no error), not yet
  /// told to the observer; nullopt when it leaves the path (nothing observed of the step it
  /// could not make).
  std::optional<RunEnd> run_compiled(CompiledSteps& steps) {
    DatePlanner* planner = shared_.stochastic ? &scheduler_.planner() : nullptr;
    // Absorbing states are looked for from step options_.absorbing_after on, as the scheduler
    // looks for them.
    const bool absorbing_checks = shared_.absorbing_checks;
    bool checking = shared_.checks_absorbing_from_start();
    if (!steps.begin({runtime_, scheduler_.random(), planner, options_.asap, options_.first_enabled,
                      scheduler_.started_from_kept_state(), checking})) {
      return std::nullopt;
    }
    StepInfo info;
    for (;;) {
      switch (steps.step(options_.limit && steps_ >= *options_.limit, info)) {
        case CompiledSteps::Outcome::Fired:
          info.step = ++steps_;
          if (!observe(info)) return RunEnd::Stopped;
          // A step that kept the places and data may have reached an absorbing state: the
          // scheduler, which tells, replays the run and goes on from there.
          if (checking) {
            if (steps.step_kept_state()) return std::nullopt;
          } else if (absorbing_checks && steps_ >= options_.absorbing_after) {
            steps.check_kept_state();
            checking = true;
          }
          continue;
        case CompiledSteps::Outcome::Deadlock:
          return RunEnd::Deadlock;
        case CompiledSteps::Outcome::Timelock:
          return RunEnd::Timelock;
        case CompiledSteps::Outcome::Limit:
          return RunEnd::Limit;
        case CompiledSteps::Outcome::Beyond:
          return std::nullopt;
      }
    }
  }

  /// Beyond the compiled path: the run starts again on the scheduler, whose first `observed`
  /// steps (those the compiled path made and observed) are not observed again; nullopt when it
  /// has made them and goes on.
  std::optional<RunResult> replay_quietly(std::uint64_t observed) {
    if (!scheduler_.restart(run_index_)) return error();
    while (scheduler_.steps() < observed) {
      const Decision& decision = scheduler_.decide();
      if (decision.kind == Decision::Kind::End) return finish(decision);
      if (!scheduler_.perform(decision)) return error();
    }
    return std::nullopt;
  }

  bool observe(const StepInfo& info) {
    const RunState& state = runtime_.state();
    const StateView view(shared_.system, shared_.layout, state, shared_.strings, state.data.data(),
                         state.marking.data());
    return observer_->observe(info, view);
  }

  RunResult end(RunResult result) {
    // Without a place, the message as it is: a run that ends well builds no string.
    if (result.where.empty()) {
      observer_->finish(result.end, result.code, result.message);
    } else {
      observer_->finish(result.end, result.code, located_message(result.where, result.message));
    }
    return result;
  }

  /// A run that ends well: built in place (a statistical check ends many short runs so).
  RunResult end(RunEnd how) {
    RunResult result{kRunOk, how, steps_, {}, {}};
    observer_->finish(how, kRunOk, result.message);
    return result;
  }

  RunResult stopped() { return end(RunEnd::Stopped); }

  RunResult fail(const ModelError& error) {
    if (options_.trace == TraceFormat::Text || error.code == kTimeSafetyViolation) {
      line("ERROR: " + error.message);
    }
    error_result_ = {error.code, RunEnd::Error, steps_, error.message, error.where};
    return end(error_result_);
  }

  /// The scheduler's error (steps_ counts the steps before the failing one).
  RunResult error() {
    steps_ = scheduler_.steps();
    return fail(scheduler_.error());
  }
  RunResult runtime_error() { return fail(runtime_.error()); }

  /// How the run ends after an End decision.
  RunResult finish(const Decision& decision) {
    switch (decision.end) {
      case RunEnd::Deadlock:
        header("deadlock!");
        return end(RunEnd::Deadlock);
      case RunEnd::Timelock: {
        const Interval w = runtime_.wait_interval();
        header(std::string("time-lock ") + (w.right_open ? "right before " : "at ") +
               format_time(w.right) + "!");
        return end(RunEnd::Timelock);
      }
      case RunEnd::Limit:
        header("stop (reached limit of " + std::to_string(*options_.limit) + " states)");
        return end(RunEnd::Limit);
      case RunEnd::Stopped:
        return stopped();
      case RunEnd::Absorbing:
        header("absorbing state!");
        return end(RunEnd::Absorbing);
      case RunEnd::Error:
        break;
    }
    return error();
  }

  /// Real time: after a step (and initially) the platform clock must still be inside the
  /// waiting and resume windows, where pending atoms resume.
  bool real_time_after_step() {
    if (!runtime_.compute_items()) {
      error_result_ = runtime_error();
      return false;
    }
    return check_time_safety();
  }

  TimeValue platform_now() const {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() -
                                                                start_)
        .count();
  }

  void wait_until(TimeValue date) {
    std::this_thread::sleep_until(start_ + std::chrono::nanoseconds(date));
  }

  /// Real time: the platform clock must still be inside the waiting and resume windows. With
  /// --relaxed a late platform is reported as a warning and the run goes on from the platform time.
  bool check_time_safety() {
    const TimeValue t = platform_now();
    const Interval allowed = runtime_.wait_interval().intersect(runtime_.resume_window());
    if (!allowed.contains(t)) {
      const bool tolerated = options_.relaxed && t >= allowed.right;
      out_ << kEnginePrefix << (tolerated ? "WARNING: " : "ERROR: ") << kEnginePrefix << "state #"
           << steps_ << " and global time " << format_time(t)
           << ": violation of the following timing constraints:\n";
      for (const std::string& text : runtime_.late_constraints(t)) {
        out_ << kEnginePrefix << "  " << text << "\n";
      }
      if (!tolerated) {
        error_result_ = {kTimeSafetyViolation, RunEnd::Error, steps_, "time-safety violation", {}};
        end(error_result_);
        return false;
      }
    }
    if (!runtime_.resume_atoms(t)) {
      error_result_ = runtime_error();
      return false;
    }
    return true;
  }

  Simulator::Shared& shared_;
  const SimulateOptions& options_;
  std::ostream& out_;
  const std::ostream& model_out_;
  std::istream* input_;
  RunObserver* observer_;
  bool verbose_;
  std::uint64_t steps_ = 0;  // the scheduler's, as of the last step observed
  PromptPicker picker_;
  detail::Scheduler scheduler_;
  bool picked_;
  Runtime& runtime_;
  std::uint64_t run_index_;
  std::chrono::steady_clock::time_point start_;
  RunResult error_result_;
};

}  // namespace detail

Simulator::Simulator(const bipc::ir::System& system, const SimulateOptions& options,
                     const Externs& externs)
    : shared_(std::make_unique<Shared>(std::make_unique<InterpretedModel>(system), options)) {
  prepare(externs);
}

Simulator::Simulator(const Model& model, const SimulateOptions& options, const Externs& externs)
    : shared_(std::make_unique<Shared>(model, options)) {
  prepare(externs);
}

void Simulator::prepare(const Externs& externs) { shared_->prepare(externs); }

Simulator::~Simulator() = default;

const std::string& Simulator::problem() const { return shared_->problem; }
bool Simulator::stochastic() const { return shared_->stochastic; }
std::uint64_t Simulator::seed() const { return shared_->seed; }

RunResult Simulator::run(std::uint64_t run_index, const RunStreams& streams,
                         RunObserver* observer) {
  if (!shared_->problem.empty()) return {kInputError, RunEnd::Error, 0, shared_->problem, {}};
  std::optional<JsonlTrace> jsonl;
  if (shared_->options.trace == TraceFormat::Jsonl && !shared_->options.silent) {
    jsonl.emplace(streams.trace, shared_->layout, shared_->seed, run_index);
  }
  Observers observers(observer, jsonl ? &*jsonl : nullptr);
  // The caller's observer alone is called directly: a statistical check observes every step.
  RunObserver& watching = jsonl || !observer ? observers : *observer;
  if (shared_->options.explore) {
    detail::Simulation simulation(*shared_, run_index, streams, watching);
    return simulation.explore();
  }
  // `observers` lives for this run only: a simulation that watches it is not kept.
  if (&watching == &observers) {
    detail::Simulation simulation(*shared_, run_index, streams, watching);
    return simulation.run();
  }
  if (kept_ && kept_->writes_to(streams)) {
    kept_->renew(run_index, watching);
  } else {
    kept_.reset();
    kept_ = std::make_unique<detail::Simulation>(*shared_, run_index, streams, watching);
  }
  return kept_->run();
}

RunResult Simulator::replay(const ReplayScript& script, const RunStreams& streams) {
  if (!shared_->problem.empty()) return {kInputError, RunEnd::Error, 0, shared_->problem, {}};
  std::optional<JsonlTrace> jsonl;
  if (shared_->options.trace == TraceFormat::Jsonl && !shared_->options.silent) {
    jsonl.emplace(streams.trace, shared_->layout, shared_->seed, shared_->options.run_index);
  }
  detail::ReplayFollower follower(script);
  Observers observers(&follower, jsonl ? &*jsonl : nullptr);
  detail::Simulation simulation(*shared_, shared_->options.run_index, streams, observers,
                                &follower);
  const RunResult result = simulation.run();
  return follower.failure() ? *follower.failure() : result;
}

RunResult simulate(const bipc::ir::System& system, const SimulateOptions& options,
                   const Externs& externs, std::ostream& out, std::istream* input) {
  Simulator simulator(system, options, externs);
  return simulator.run(options.run_index, RunStreams{out, out, input});
}

}  // namespace smcbip::engines
