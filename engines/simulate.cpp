// Simulation runs: the scheduling loop over the shared semantics, in simulated or real time,
// with the reference engine's random choice or the stochastic race of planned dates.
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <thread>

#include "engines/engines.h"
#include "engines/explore.h"
#include "engines/interactive.h"
#include "engines/semantics/runtime.h"
#include "engines/stochastic/date_planner.h"
#include "engines/trace/jsonl_trace.h"
#include "engines/trace/text_trace.h"

namespace smcbip::engines {

namespace {

/// The date an item is planned at by the reference scheduler: uniform over the (integer
/// nanosecond) points of a bounded window; on an unbounded one the left end plus an
/// exponential delay of mean 10 ns, as the reference engine's Interval::random does.
TimeValue random_date(const Interval& interval, RandomStream& random) {
  if (interval.bounded()) return uniform_date(interval, random);
  return interval.first() +
         static_cast<TimeValue>(std::floor(-10.0 * std::log(random.uniform01_open())));
}

/// The delay floor(-10 ln u) of random_date's unbounded case, computed only when needed: the
/// scheduler mostly has to know whether it is below, at or above a given whole number of
/// nanoseconds, which comparing u with exp(-d / 10) answers without a logarithm. Near those
/// bounds (within a relative 1e-9, far above the rounding errors of exp and log) the delay is
/// computed exactly as random_date does, so the choices are the same.
class ExponentialDelay {
 public:
  static TimeValue of(double u) { return static_cast<TimeValue>(std::floor(-10.0 * std::log(u))); }
  /// The sign of of(u) - d; the bounds of the last d are kept (items mostly share it).
  int compare(double u, TimeValue d) {
    if (d < 0) return 1;  // u < 1, so the delay is never negative
    if (d != d_) {
      d_ = d;
      below_d_ = std::exp(-static_cast<double>(d) / 10.0);  // u above it: delay < d
      below_next_ = std::exp(-static_cast<double>(d + 1) / 10.0);
    }
    constexpr double kMargin = 1e-9;
    if (u > below_d_ * (1 + kMargin)) return -1;
    if (u < below_next_ * (1 - kMargin)) return 1;
    if (u < below_d_ * (1 - kMargin) && u > below_next_ * (1 + kMargin)) return 0;
    const TimeValue exact = of(u);
    return exact < d ? -1 : exact > d ? 1 : 0;
  }

 private:
  TimeValue d_ = -1;
  double below_d_ = 0, below_next_ = 0;
};

TimeValue earliest(const Interval& interval, TimeValue now) {
  return std::max(interval.first(), now);
}

RuntimeOptions runtime_options(const SimulateOptions& options) {
  RuntimeOptions r;
  r.maximal_progress = !options.disable_maximal_progress;
  r.incremental = options.engine != EngineKind::Reference;
  if (options.engine == EngineKind::Multithread) {
    r.threads =
        options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    r.parallel_min_work = options.parallel_min_work;
  }
  return r;
}

StepInfo step_info(const Item& item, const Runtime& runtime, std::uint64_t step, TimeValue at) {
  StepInfo info;
  info.step = step;
  info.time = at;
  switch (item.kind) {
    case Item::Kind::Interaction:
      info.fired = StepInfo::Fired::Interaction;
      info.connector = runtime.values()[item.value].connector;
      break;
    case Item::Kind::Internal:
      info.fired = StepInfo::Fired::Internal;
      break;
    case Item::Kind::External:
      info.fired = StepInfo::Fired::External;
      break;
  }
  if (item.kind != Item::Kind::Interaction) {
    info.atom = item.atom;
    info.port = item.port;
  }
  return info;
}

}  // namespace

struct Simulator::Shared {
  std::unique_ptr<InterpretedModel> owned;  // when built from an IR
  const Model& model;
  const bipc::ir::System& system;
  SimulateOptions options;
  Layout layout;
  StringPool strings;
  BoundFunctions functions;
  CustomDistributions custom;
  std::string problem;
  std::uint64_t seed = 0;
  bool stochastic = false;

  Shared(const Model& m, const SimulateOptions& o) : model(m), system(m.system()), options(o) {}
  Shared(std::unique_ptr<InterpretedModel> m, const SimulateOptions& o)
      : owned(std::move(m)), model(*owned), system(owned->system()), options(o) {}
};

namespace {

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

class Simulation {
 public:
  Simulation(Simulator::Shared& shared, std::uint64_t run_index, const RunStreams& streams,
             RunObserver& observer)
      : shared_(shared),
        options_(shared.options),
        out_(streams.trace),
        input_(streams.input),
        observer_(observer),
        random_(shared.seed, run_index),
        runtime_(shared.model, shared.layout, shared.functions, shared.strings, streams.model,
                 random_, runtime_options(shared.options)),
        planner_(shared.system, shared.custom, random_, shared.options.unbounded_mean),
        verbose_(!options_.silent && options_.trace == TraceFormat::Text) {}

  RunResult explore() {
    if (!options_.silent) {
      line("BIP Engine (version " SMCBIP_VERSION_TEXT " )");
      out_ << "[BIP ENGINE]:\n";
      line("initialize components...");
    }
    if (!runtime_.initialize() || !runtime_.resume_atoms(0)) return error();
    const ExplorationCounts counts = explore_states(runtime_, options_.limit);
    write_exploration(out_, counts);
    return {kRunOk, RunEnd::Deadlock, counts.states, {}};
  }

  RunResult run() {
    if (verbose_) {
      line("BIP Engine (version " SMCBIP_VERSION_TEXT " )");
      line("");
      line("initialize components...");
      line("random scheduling based on seed=" + std::to_string(shared_.seed));
    }
    start_ = std::chrono::steady_clock::now();
    if (!runtime_.initialize()) return error();
    // The reference engine resumes pending atoms (initial `resume`) before the first step.
    if (!after_step(0)) return error_result_;
    if (!observe(StepInfo{})) return stopped();
    for (;;) {
      if (!runtime_.compute_items()) return error();
      const std::optional<TimeValue> arrival = runtime_.next_unexpected_arrival();
      if (runtime_.item_count() == 0) {
        if (!arrival || !runtime_.wait_interval().contains(*arrival)) return finish_without_items();
        if (!receive_unexpected_events(*arrival)) return error();
        continue;
      }
      if (options_.limit && steps_ >= *options_.limit) {
        header("stop (reached limit of " + std::to_string(*options_.limit) + " states)");
        return end({kRunOk, RunEnd::Limit, steps_, {}});
      }
      std::optional<std::pair<std::size_t, TimeValue>> choice = choose();
      if (!choice) return ended_ ? *ended_ : timelock();
      const auto [chosen, date] = *choice;
      if (arrival && *arrival <= date) {
        if (!receive_unexpected_events(*arrival)) return error();
        continue;
      }
      // Only the text trace shows every item: other runs never have them listed.
      const Item item = runtime_.item(chosen);
      if (verbose_) {
        if (!options_.interactive) write_state(out_, runtime_, steps_);
        line("-> choose [" + std::to_string(chosen) + "] " + item_text(runtime_, item, false) +
             " at global time " + format_time(date));
      }
      const StepInfo info = step_info(item, runtime_, steps_ + 1, date);
      if (options_.real_time) wait_until(date);
      if (!runtime_.execute(item, date)) return error();
      ++steps_;
      if (!after_step(date)) return error_result_;
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

  /// Extern events that no port can take arrive at `date` (in real time, once it has come).
  bool receive_unexpected_events(TimeValue date) {
    if (options_.real_time) wait_until(date);
    return runtime_.receive_unexpected_events(date);
  }

  bool observe(const StepInfo& info) {
    const StateView view(shared_.system, shared_.layout, runtime_.state(), shared_.strings);
    return observer_.observe(info, view);
  }

  RunResult end(RunResult result) {
    observer_.finish(result.end, result.code, result.message);
    ended_ = result;
    return result;
  }

  RunResult stopped() { return end({kRunOk, RunEnd::Stopped, steps_, {}}); }

  RunResult fail(int code, const std::string& message) {
    if (options_.trace == TraceFormat::Text || code == kTimeSafetyViolation) {
      line("ERROR: " + message);
    }
    error_result_ = {code, RunEnd::Error, steps_, message};
    return end(error_result_);
  }

  RunResult error() { return fail(runtime_.error().code, runtime_.error().message); }

  /// Resumes pending atoms after a step (simulated time) or checks time safety (real time).
  bool after_step(TimeValue date) {
    if (!options_.real_time) {
      if (runtime_.resume_atoms(date)) return true;
      error_result_ = error();
      return false;
    }
    if (!runtime_.compute_items()) {
      error_result_ = error();
      return false;
    }
    return check_time_safety();
  }

  RunResult finish_without_items() {
    const Interval w = runtime_.wait_interval();
    if (w.right == kPlusInfinity) {
      header("deadlock!");
      return end({kRunOk, RunEnd::Deadlock, steps_, {}});
    }
    return timelock();
  }

  RunResult timelock() {
    const Interval w = runtime_.wait_interval();
    header(std::string("time-lock ") + (w.right_open ? "right before " : "at ") +
           format_time(w.right) + "!");
    return end({kRunOk, RunEnd::Timelock, steps_, {}});
  }

  std::optional<std::pair<std::size_t, TimeValue>> choose() {
    if (options_.interactive) {
      if (verbose_) write_state(out_, runtime_, steps_);
      const std::optional<std::size_t> picked =
          prompt_choice(out_, input_, runtime_.items().size());
      if (!picked) {
        stopped();
        return std::nullopt;
      }
      const Interval& window = runtime_.items()[*picked].constraint.interval;
      return std::pair{*picked, earliest(window, runtime_.state().now)};
    }
    if (shared_.stochastic) return race();
    if (auto choice = shared_window_choice()) return choice;
    return std::pair{random_choice()};
  }

  /// random_choice when every item has the same window (untimed models), in two draws instead
  /// of one per item. The race is then symmetric: its winner is uniform among the n items and
  /// independent of the winning date. On the window [now, +inf) the dates are now + floor(E_i),
  /// the E_i i.i.d. exponential of mean 10 ns, so the earliest is now + floor(min E_i) and
  /// min E_i is exponential of mean 10/n; --first-enabled keeps the winner's own date (mean
  /// 10). On the window {now}, and with --asap, every date is now. Other windows: nullopt.
  std::optional<std::pair<std::size_t, TimeValue>> shared_window_choice() {
    if (!shared_.layout.untimed) return std::nullopt;
    const TimeValue now = runtime_.state().now;
    const Interval& window = runtime_.items_window();
    const bool open_ended = window == Interval::from(now);
    if (!open_ended && !(window == Interval::point(now))) return std::nullopt;
    const std::size_t n = runtime_.item_count();
    const auto chosen = static_cast<std::size_t>(random_.below(n));
    if (options_.asap || !open_ended) return std::pair{chosen, now};
    const double mean = options_.first_enabled ? 10.0 : 10.0 / static_cast<double>(n);
    const double delay = std::floor(-mean * std::log(random_.uniform01_open()));
    return std::pair{chosen, now + static_cast<TimeValue>(delay)};
  }

  /// The reference scheduler: every item draws a date in its window, the earliest wins.
  std::pair<std::size_t, TimeValue> random_choice() {
    const auto& items = runtime_.items();
    const TimeValue now = runtime_.state().now;
    std::size_t best = 0, ties = 0;
    TimeValue best_criterion = kPlusInfinity, best_date = now;
    ExponentialDelay delay;
    for (std::size_t i = 0; i < items.size(); ++i) {
      const Interval& interval = items[i].constraint.interval;
      if (!options_.asap && !options_.first_enabled && !interval.bounded()) {
        // The planned date is the criterion: often decided without its logarithm.
        const TimeValue first = interval.first();
        const double u = random_.uniform01_open();
        const int order = i == 0 ? -1 : delay.compare(u, best_criterion - first);
        if (order < 0) {
          best = i;
          ties = 1;
          best_criterion = best_date = first + ExponentialDelay::of(u);
        } else if (order == 0 && random_.below(++ties) == 0) {
          best = i;
          best_date = best_criterion;
        }
        continue;
      }
      const TimeValue planned =
          options_.asap ? earliest(interval, now) : random_date(interval, random_);
      const TimeValue criterion = options_.first_enabled ? earliest(interval, now) : planned;
      if (i == 0 || criterion < best_criterion) {
        best = i;
        ties = 1;
        best_criterion = criterion;
        best_date = planned;
      } else if (criterion == best_criterion && random_.below(++ties) == 0) {
        best = i;
        best_date = planned;
      }
    }
    return {best, std::max(best_date, now)};
  }

  /// Stochastic mode: the earliest planned date that lies in its item's window wins.
  std::optional<std::pair<std::size_t, TimeValue>> race() {
    std::string problem;
    if (!planner_.plan(runtime_, dates_, problem)) {
      fail(kInputError, problem);
      return std::nullopt;
    }
    std::optional<std::pair<std::size_t, TimeValue>> best = earliest_in_window();
    if (!best) {
      planner_.replan_within_windows(runtime_, dates_);
      best = earliest_in_window();
    }
    return best;
  }

  std::optional<std::pair<std::size_t, TimeValue>> earliest_in_window() {
    const auto& items = runtime_.items();
    std::optional<std::pair<std::size_t, TimeValue>> best;
    std::uint64_t ties = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (!items[i].constraint.interval.contains(dates_[i])) continue;
      if (!best || dates_[i] < best->second) {
        best = std::pair{i, dates_[i]};
        ties = 1;
      } else if (dates_[i] == best->second && random_.below(++ties) == 0) {
        best->first = i;
      }
    }
    return best;
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
        error_result_ = {kTimeSafetyViolation, RunEnd::Error, steps_, "time-safety violation"};
        end(error_result_);
        return false;
      }
    }
    if (!runtime_.resume_atoms(t)) {
      error_result_ = error();
      return false;
    }
    return true;
  }

  Simulator::Shared& shared_;
  const SimulateOptions& options_;
  std::ostream& out_;
  std::istream* input_;
  RunObserver& observer_;
  RandomStream random_;
  Runtime runtime_;
  DatePlanner planner_;
  bool verbose_;
  std::uint64_t steps_ = 0;
  std::vector<TimeValue> dates_;
  std::chrono::steady_clock::time_point start_;
  RunResult error_result_;
  std::optional<RunResult> ended_;  // set once the run has ended (error, stop)
};

}  // namespace

Simulator::Simulator(const bipc::ir::System& system, const SimulateOptions& options,
                     const Externs& externs)
    : shared_(std::make_unique<Shared>(std::make_unique<InterpretedModel>(system), options)) {
  prepare(externs);
}

Simulator::Simulator(const Model& model, const SimulateOptions& options, const Externs& externs)
    : shared_(std::make_unique<Shared>(model, options)) {
  prepare(externs);
}

void Simulator::prepare(const Externs& externs) {
  Shared& s = *shared_;
  const bipc::ir::System& system = s.system;
  const SimulateOptions& options = s.options;
  s.problem = build_layout(system, s.layout);
  if (s.problem.empty()) bind_functions(system, externs, s.strings, s.functions);
  if (s.problem.empty()) s.problem = load_custom_distributions(system, s.custom);
  s.seed = options.seed ? *options.seed : std::random_device{}();
  s.stochastic = options.stochastic.value_or(has_stochastic_ports(system));
}

Simulator::~Simulator() = default;

const std::string& Simulator::problem() const { return shared_->problem; }
bool Simulator::stochastic() const { return shared_->stochastic; }
std::uint64_t Simulator::seed() const { return shared_->seed; }

RunResult Simulator::run(std::uint64_t run_index, const RunStreams& streams,
                         RunObserver* observer) {
  if (!shared_->problem.empty()) return {kInputError, RunEnd::Error, 0, shared_->problem};
  std::optional<JsonlTrace> jsonl;
  if (shared_->options.trace == TraceFormat::Jsonl && !shared_->options.silent) {
    jsonl.emplace(streams.trace, shared_->layout);
  }
  Observers observers(observer, jsonl ? &*jsonl : nullptr);
  Simulation simulation(*shared_, run_index, streams, observers);
  return shared_->options.explore ? simulation.explore() : simulation.run();
}

RunResult simulate(const bipc::ir::System& system, const SimulateOptions& options,
                   const Externs& externs, std::ostream& out, std::istream* input) {
  Simulator simulator(system, options, externs);
  return simulator.run(options.run_index, RunStreams{out, out, input});
}

int run_simulation(const Model& model, const SimulateOptions& options, const Externs& externs,
                   const std::string& tool) {
  std::ios::sync_with_stdio(false);
  // A JSON-lines trace keeps stdout for the trace: the model's own output goes to stderr.
  std::ostream& model_output = options.trace == TraceFormat::Jsonl ? std::cerr : std::cout;
  Simulator simulator(model, options, externs);
  const RunResult run =
      simulator.run(options.run_index, RunStreams{std::cout, model_output, &std::cin});
  std::cout.flush();
  if (run.code == kInputError || run.code == kInternalError || run.code == kUsageError) {
    std::cerr << tool << ": error: " << run.message << "\n";
  }
  return run.code;
}

}  // namespace smcbip::engines
