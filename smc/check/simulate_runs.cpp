// The trajectories of simulate queries (see simulate_runs.h).
#include "smc/check/simulate_runs.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace smcbip::smc {
namespace {

// The engines count nanoseconds; models' times and bounds are in milliseconds.
constexpr monitors::TimeScale kNanoseconds{1e6, 1e9};

/// Records the expressions of one run.
class Recorder final : public engines::RunObserver {
 public:
  Recorder(const monitors::Query& q, const monitors::Bindings& point) : q_(q), point_(point) {
    if (q.run.kind == monitors::Bound::Kind::Time) {
      until_ = monitors::bound_ticks(q.run.high, kNanoseconds, point);
    } else {
      steps_ = monitors::bound_steps(q.run.high, point);
    }
    lines_.resize(q.series.size());
  }

  void start(std::vector<std::vector<double>>& points) {
    points_ = &points;
    points_->clear();
    started_ = false;
  }

  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    const auto index = static_cast<std::int64_t>(step.step);
    if (index > steps_) return false;
    if (started_ && step.time > until_) {
      grown_point(until_);
      return false;
    }
    if (started_ && step.time > last_) grown_point(step.time);
    const monitors::EngineState view(step, state);
    const monitors::Moment moment(view, step.time, kNanoseconds, index == 0);
    std::vector<double> point{ms(step.time)};
    for (std::size_t i = 0; i < q_.series.size(); ++i) {
      lines_[i].compute(*q_.series[i], moment, point_, horizon(step.time));
      point.push_back(lines_[i].at(0));
    }
    points_->push_back(std::move(point));
    started_ = true;
    last_ = step.time;
    return index < steps_;
  }

  void finish(engines::RunEnd end, int, const std::string&) override {
    if (started_ && end == engines::RunEnd::Deadlock && until_ != kNone) grown_point(until_);
  }

 private:
  static constexpr engines::TimeValue kNone = std::numeric_limits<engines::TimeValue>::max();

  static double ms(engines::TimeValue t) { return static_cast<double>(t) / 1e6; }
  double horizon(engines::TimeValue t) const {
    return until_ == kNone ? std::numeric_limits<double>::infinity()
                           : static_cast<double>(until_ - t);
  }

  /// The last state's values grown to `t`, when some expression grows.
  void grown_point(engines::TimeValue t) {
    std::vector<double> point{ms(t)};
    bool grew = false;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      const double v = lines_[i].at(static_cast<double>(t - last_));
      grew = grew || v != points_->back()[i + 1];
      point.push_back(v);
    }
    if (grew || t == until_) points_->push_back(std::move(point));
  }

  const monitors::Query& q_;
  const monitors::Bindings& point_;
  engines::TimeValue until_ = kNone;
  std::int64_t steps_ = std::numeric_limits<std::int64_t>::max();
  std::vector<monitors::Trajectory> lines_;
  std::vector<std::vector<double>>* points_ = nullptr;
  bool started_ = false;
  engines::TimeValue last_ = 0;
};

QueryResult simulate_at(const bipc::ir::System& system, const monitors::Query& q,
                        const monitors::Bindings& point, const CheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  QueryResult r;
  r.method = Method::Auto;
  engines::Externs externs = engines::Externs::with_builtins();
  const std::unique_ptr<engines::Simulator> simulator =
      make_simulator(system, options.compiled, run_options(options), externs);
  auto made = std::make_shared<Trajectories>();
  for (const auto& e : q.series) made->series.push_back(to_string(*e));
  const auto runs =
      static_cast<std::uint64_t>(q.runs.is_name() ? point.at(q.runs.name) : q.runs.number);
  Recorder recorder(q, point);
  made->runs.resize(runs);
  for (std::uint64_t i = 0; i < runs; ++i) {
    recorder.start(made->runs[i]);
    std::ostringstream nothing;
    const engines::RunResult result =
        simulator->run(i, engines::RunStreams{nothing, nothing}, &recorder);
    if (result.end == engines::RunEnd::Error) {
      r.error = "run " + std::to_string(i) + " ended in an error: " + result.message;
      break;
    }
  }
  r.samples = runs;
  r.trajectories = std::move(made);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

std::vector<QueryResult> simulate_trajectories(const bipc::ir::System& system,
                                               const QueryPoints& query,
                                               const CheckOptions& options) {
  std::vector<QueryResult> results;
  for (const monitors::Bindings& point : query.points) {
    results.push_back(simulate_at(system, *query.query, point, options));
    results.back().query = query.index;
  }
  return results;
}

}  // namespace smcbip::smc
