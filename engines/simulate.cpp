// One simulation run: the reference engine's scheduling loop over the shared semantics.
#include <chrono>
#include <cmath>
#include <random>
#include <thread>

#include "engines/engines.h"
#include "engines/explore.h"
#include "engines/semantics/runtime.h"
#include "engines/trace/text_trace.h"

namespace smcbip::engines {

namespace {

/// The date an item is planned at: uniform over the (integer nanosecond) points of a bounded
/// window; on an unbounded one the left end plus an exponential delay of mean 10 ns, as the
/// reference engine's Interval::random does.
TimeValue random_date(const Interval& interval, RandomStream& random) {
  const TimeValue first = interval.first();
  if (interval.bounded()) {
    const TimeValue last = interval.last();
    if (last <= first) return first;
    return first + static_cast<TimeValue>(random.below(static_cast<std::uint64_t>(last - first) + 1));
  }
  return first + static_cast<TimeValue>(std::floor(-10.0 * std::log(random.uniform01_open())));
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
    r.threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  }
  return r;
}

class Simulation {
 public:
  Simulation(const bipc::ir::System& system, const SimulateOptions& options, const Layout& layout,
             const BoundFunctions& functions, StringPool& strings, std::ostream& out,
             std::uint64_t seed)
      : options_(options),
        out_(out),
        seed_(seed),
        random_(seed, options.run_index),
        runtime_(system, layout, functions, strings, out, random_, runtime_options(options)),
        verbose_(!options.silent && options.trace == TraceFormat::Text) {}

  RunResult explore() {
    if (!options_.silent) {
      line("BIP Engine (version " SMCBIP_VERSION_TEXT " )");
      out_ << "[BIP ENGINE]:\n";
      line("initialize components...");
    }
    if (!runtime_.initialize() || !runtime_.resume_atoms(0)) return error();
    const ExplorationCounts counts = explore_states(runtime_);
    write_exploration(out_, counts);
    return {kRunOk, RunEnd::Deadlock, counts.states, {}};
  }

  RunResult run() {
    if (verbose_) {
      line("BIP Engine (version " SMCBIP_VERSION_TEXT " )");
      line("");
      line("initialize components...");
      line("random scheduling based on seed=" + std::to_string(seed_));
    }
    start_ = std::chrono::steady_clock::now();
    if (!runtime_.initialize()) return error();
    // The reference engine resumes pending atoms (initial `resume`) before the first step.
    if (options_.real_time) {
      if (!runtime_.compute_items()) return error();
      if (!check_time_safety()) return error_result_;
    } else if (!runtime_.resume_atoms(0)) {
      return error();
    }
    for (;;) {
      if (!runtime_.compute_items()) return error();
      const auto& items = runtime_.items();
      if (items.empty()) return finish_without_items();
      if (options_.limit && steps_ >= *options_.limit) {
        header("stop (reached limit of " + std::to_string(*options_.limit) + " states)");
        return {kRunOk, RunEnd::Limit, steps_, {}};
      }
      const auto [chosen, date] = choose();
      if (verbose_) {
        write_state(out_, runtime_, steps_);
        line("-> choose [" + std::to_string(chosen) + "] " +
             item_text(runtime_, items[chosen], false) + " at global time " + format_time(date));
      }
      const Item item = items[chosen];
      if (options_.real_time) wait_until(date);
      if (!runtime_.execute(item, date)) return error();
      ++steps_;
      if (options_.real_time) {
        if (!runtime_.compute_items()) return error();
        if (!check_time_safety()) return error_result_;
      } else if (!runtime_.resume_atoms(date)) {
        return error();
      }
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

  RunResult error() {
    const ModelError& e = runtime_.error();
    line("ERROR: " + e.message);
    return {e.code, RunEnd::Error, steps_, e.message};
  }

  RunResult finish_without_items() {
    const Interval w = runtime_.wait_interval();
    if (w.right == kPlusInfinity) {
      header("deadlock!");
      return {kRunOk, RunEnd::Deadlock, steps_, {}};
    }
    header(std::string("time-lock ") + (w.right_open ? "right before " : "at ") +
           format_time(w.right) + "!");
    return {kRunOk, RunEnd::Timelock, steps_, {}};
  }

  /// The item to execute and its date: the earliest planned date (or earliest possible start),
  /// ties broken uniformly. Draws what random_date draws for every item, in item order.
  std::pair<std::size_t, TimeValue> choose() {
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

  TimeValue platform_now() const {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now() - start_)
        .count();
  }

  void wait_until(TimeValue date) {
    std::this_thread::sleep_until(start_ + std::chrono::nanoseconds(date));
  }

  /// Real time: the platform clock must still be inside the waiting and resume windows.
  bool check_time_safety() {
    const TimeValue t = platform_now();
    const Interval allowed = runtime_.wait_interval().intersect(runtime_.resume_window());
    if (!allowed.contains(t) && !(options_.relaxed && t >= allowed.right)) {
      out_ << kEnginePrefix << "ERROR: " << kEnginePrefix << "state #" << steps_
           << " and global time " << format_time(t)
           << ": violation of the following timing constraints:\n";
      for (const std::string& text : runtime_.late_constraints(t)) {
        out_ << kEnginePrefix << "  " << text << "\n";
      }
      error_result_ = {kTimeSafetyViolation, RunEnd::Error, steps_, "time-safety violation"};
      return false;
    }
    if (!runtime_.resume_atoms(t)) {
      error_result_ = error();
      return false;
    }
    return true;
  }

  const SimulateOptions& options_;
  std::ostream& out_;
  std::uint64_t seed_;
  RandomStream random_;
  Runtime runtime_;
  bool verbose_;
  std::uint64_t steps_ = 0;
  std::chrono::steady_clock::time_point start_;
  RunResult error_result_;
};

}  // namespace

RunResult simulate(const bipc::ir::System& system, const SimulateOptions& options,
                   const Externs& externs, std::ostream& out, std::istream* /*input*/) {
  Layout layout;
  if (std::string problem = build_layout(system, layout); !problem.empty()) {
    return {kInputError, RunEnd::Error, 0, problem};
  }
  StringPool strings;
  BoundFunctions functions;
  bind_functions(system, externs, strings, functions);
  const std::uint64_t seed = options.seed ? *options.seed : std::random_device{}();
  Simulation simulation(system, options, layout, functions, strings, out, seed);
  return options.explore ? simulation.explore() : simulation.run();
}

}  // namespace smcbip::engines
