#include "smc/check/query_runs.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace smcbip::smc {
namespace {

using monitors::Verdict;

// The engines count nanoseconds; models' times and bounds are in milliseconds.
constexpr monitors::TimeScale kNanoseconds{1e6, 1e9};

/// Where the runs' traces and output go: nowhere.
class NullBuffer final : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

}  // namespace

/// A string that stops growing at kMaxSavedTraceBytes: past it, the stream writing to it
/// fails and writes nothing more.
class QueryRuns::CappedText final : public std::streambuf {
 public:
  void clear() {
    text_.clear();
    cut_ = false;
  }
  const std::string& text() const { return text_; }
  bool cut() const { return cut_; }

 protected:
  int overflow(int c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char byte = traits_type::to_char_type(c);
    return xsputn(&byte, 1) == 1 ? c : traits_type::eof();
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    const std::size_t room = kMaxSavedTraceBytes - text_.size();
    const auto taken = static_cast<std::size_t>(n) <= room ? static_cast<std::size_t>(n) : room;
    text_.append(s, taken);
    if (taken < static_cast<std::size_t>(n)) cut_ = true;
    return static_cast<std::streamsize>(taken);
  }

 private:
  std::string text_;
  bool cut_ = false;
};

/// Passes each step to the observers of the points still judged, until all have decided.
class QueryRuns::Observer final : public engines::RunObserver {
 public:
  /// A new run, watched by the observers given next (their storage is kept between runs).
  void clear() { observers_.clear(); }
  void watch(engines::RunObserver* o) { observers_.push_back(o); }
  void start() { watching_.assign(observers_.begin(), observers_.end()); }

  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    std::erase_if(watching_, [&](engines::RunObserver* o) { return !o->observe(step, state); });
    return !watching_.empty();
  }

  void finish(engines::RunEnd end, int code, const std::string& message) override {
    for (engines::RunObserver* o : observers_) o->finish(end, code, message);
  }

  /// What a run observes: the one observer given, called straight by the run (a statistical
  /// check's usual case, one property), else this, which passes each step on.
  engines::RunObserver* watcher() { return observers_.size() == 1 ? observers_.front() : this; }

 private:
  std::vector<engines::RunObserver*> observers_, watching_;
};

engines::SimulateOptions run_options(const CheckOptions& options) {
  engines::SimulateOptions simulate;
  simulate.engine = options.engine;
  simulate.seed = options.seed;
  simulate.limit = options.max_steps;
  simulate.silent = true;
  return simulate;
}

std::unique_ptr<engines::Simulator> make_simulator(const bipc::ir::System& system,
                                                   const engines::PluginEntry* compiled,
                                                   const engines::SimulateOptions& options,
                                                   engines::Externs& externs) {
  std::unique_ptr<engines::Simulator> simulator;
  if (compiled) {
    compiled->register_externs(externs);
    simulator = std::make_unique<engines::Simulator>(compiled->model(), options, externs);
  } else {
    simulator = std::make_unique<engines::Simulator>(system, options, externs);
  }
  if (!simulator->problem().empty()) throw std::invalid_argument(simulator->problem());
  return simulator;
}

QueryRuns::QueryRuns(const bipc::ir::System& system, const engines::PluginEntry* compiled,
                     const engines::SimulateOptions& options, const QueryPoints& query)
    : externs_(engines::Externs::with_builtins()),
      query_(query),
      observer_(std::make_unique<Observer>()),
      nothing_(std::make_unique<NullBuffer>()),
      sink_(nothing_.get()),
      traced_(!options.silent),
      trace_text_(std::make_unique<CappedText>()),
      trace_(trace_text_.get()) {
  const monitors::Query& q = *query.query;
  if (query.swept) {
    double largest = 0;
    for (const monitors::Bindings& b : query.points) {
      swept_values_.push_back(b.at(*query.swept));
      largest = std::max(largest, swept_values_.back());
    }
    sweep_ = std::make_unique<monitors::RunCriticalBound>(
        *q.formula, *query.swept, largest, kNanoseconds, query.points.front(), q.run);
    simulator_ = make_simulator(system, compiled, options, externs_);
    return;
  }
  for (const monitors::Bindings& b : query.points) {
    if (q.formula) {
      monitors_.push_back(
          std::make_unique<monitors::RunMonitor>(*q.formula, kNanoseconds, b, q.run));
    } else {
      extrema_.push_back(std::make_unique<monitors::RunExtremum>(q, kNanoseconds, b));
    }
  }
  engines::SimulateOptions runs = options;
  runs.stop_absorbing = stops_when_absorbed(q, query.points);
  // A bounded formula ends most runs by itself: only the runs that last look for absorbing
  // states (a run absorbed early would otherwise loop in its state up to the bound).
  constexpr std::uint64_t kLastingRun = 1000;
  runs.absorbing_after = bounded(q, query.points) ? kLastingRun : 0;
  simulator_ = make_simulator(system, compiled, runs, externs_);
}

bool QueryRuns::stops_when_absorbed(const monitors::Query& q,
                                    const std::vector<monitors::Bindings>& points) const {
  // PRISM's simulator ends a path in a state it cannot leave, for the unbounded operators that
  // would otherwise run to the step limit; a bounded formula would run to its bound. The state
  // holds forever there, which decides any formula over places and data.
  if (!q.formula || monitors_.empty()) return false;
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (!monitors_[p]->decided_by_absorbing()) return false;
  }
  return true;
}

bool QueryRuns::bounded(const monitors::Query& q, const std::vector<monitors::Bindings>& points) {
  if (!q.formula || q.run.kind != monitors::Bound::Kind::None) return true;
  return std::any_of(points.begin(), points.end(), [&](const monitors::Bindings& b) {
    return monitors::horizon(*q.formula, kNanoseconds, b).bounded;
  });
}

QueryRuns::~QueryRuns() = default;

void QueryRuns::run(std::uint64_t index, const std::atomic<bool>* done, RunOutcomes& made) {
  const std::size_t n = query_.points.size();
  observer_->clear();
  if (sweep_) {
    sweep_->reset();
    observer_->watch(sweep_.get());
  }
  // Read once: the consumer may close a point while the run is made.
  judged_.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    judged_[p] = !sweep_ && !done[p].load(std::memory_order_relaxed);
    if (!judged_[p]) continue;
    if (monitors_.empty()) {
      extrema_[p]->reset();
      observer_->watch(extrema_[p].get());
    } else {
      monitors_[p]->reset();
      observer_->watch(monitors_[p].get());
    }
  }
  observer_->start();
  trace_text_->clear();
  trace_.clear();
  const engines::RunResult result = simulator_->run(
      index, engines::RunStreams{traced_ ? trace_ : sink_, sink_}, observer_->watcher());

  if (traced_) made.trace = trace_text_->text();
  made.trace_cut = traced_ && trace_text_->cut();
  made.end = result.end;
  // As the run's observers were told it: located where the model gave a place.
  if (result.end != engines::RunEnd::Error) {
    made.failure.clear();
  } else if (result.where.empty()) {
    made.failure = result.message;
  } else {
    made.failure = engines::located_message(result.where, result.message);
  }
  std::vector<Outcome>& outcomes = made.points;
  outcomes.assign(n, Outcome{});
  for (std::size_t p = 0; p < n; ++p) {
    if (sweep_) {
      outcomes[p].verdict = sweep_->verdict(swept_values_[p]);
    } else if (!judged_[p]) {
      continue;
    } else if (!monitors_.empty()) {
      outcomes[p].verdict = monitors_[p]->verdict();
      outcomes[p].value = monitors_[p]->first_hit_ms();
    } else {
      // An expectation: a run cut short before its bound has no value, and is undecided as
      // a path formula's run would be.
      const std::optional<double> value = extrema_[p]->value();
      outcomes[p] = {value ? Verdict::True : Verdict::Undecided,
                     value.value_or(std::numeric_limits<double>::quiet_NaN())};
    }
  }
}

}  // namespace smcbip::smc
