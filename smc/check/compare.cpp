// The comparison of two probabilities (see compare.h).
#include "smc/check/compare.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include "smc/check/ordered_sampler.h"

namespace smcbip::smc {
namespace {

using monitors::Verdict;

// The engines count nanoseconds; models' times and bounds are in milliseconds.
constexpr monitors::TimeScale kNanoseconds{1e6, 1e9};

/// Without runs where exactly one formula holds (two probabilities both 0, both 1, or formulas
/// that agree on every run), no number of runs tells them apart: the test stops here.
constexpr std::uint64_t kMaxRuns = 1000000;

struct PairOutcome {
  Verdict left = Verdict::Undecided, right = Verdict::Undecided;
  std::string failure;
};

/// Makes runs of the model on one thread and judges each for both formulas.
class PairRuns final : public engines::RunObserver {
 public:
  PairRuns(const bipc::ir::System& system, const engines::PluginEntry* compiled,
           const engines::SimulateOptions& options, const monitors::Query& q,
           const monitors::Bindings& point)
      : externs_(engines::Externs::with_builtins()),
        left_(*q.formula, kNanoseconds, point, q.run),
        right_(*q.other, kNanoseconds, point, q.other_run) {
    simulator_ = make_simulator(system, compiled, options, externs_);
  }

  void run(std::uint64_t index, PairOutcome& made) {
    left_.reset();
    right_.reset();
    left_open_ = right_open_ = true;
    failure_.clear();
    std::ostringstream nothing;
    simulator_->run(index, engines::RunStreams{nothing, nothing}, this);
    made.left = left_.verdict();
    made.right = right_.verdict();
    made.failure = failure_;
  }

  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    if (left_open_) left_open_ = left_.observe(step, state);
    if (right_open_) right_open_ = right_.observe(step, state);
    return left_open_ || right_open_;
  }
  void finish(engines::RunEnd end, int code, const std::string& message) override {
    if (end == engines::RunEnd::Error) failure_ = message;
    left_.finish(end, code, message);
    right_.finish(end, code, message);
  }

 private:
  engines::Externs externs_;
  std::unique_ptr<engines::Simulator> simulator_;
  monitors::RunMonitor left_, right_;
  bool left_open_ = true, right_open_ = true;
  std::string failure_;
};

/// Wald's SPRT on the runs where exactly one formula holds.
class PairedTest {
 public:
  explicit PairedTest(const CheckOptions& o)
      : up_(std::log((0.5 + o.delta) / (0.5 - o.delta))),
        down_(std::log((0.5 - o.delta) / (0.5 + o.delta))),
        accept_larger_(std::log((1 - o.beta) / o.alpha)),
        accept_smaller_(std::log(o.beta / (1 - o.alpha))) {}

  /// Takes one run's pair; false once decided.
  bool take(bool left, bool right) {
    if (left && !right) ratio_ += up_;
    if (right && !left) ratio_ += down_;
    return ratio_ > accept_smaller_ && ratio_ < accept_larger_;
  }
  /// Once decided: whether the left probability is the larger.
  bool left_larger() const { return ratio_ >= accept_larger_; }

 private:
  double up_, down_, accept_larger_, accept_smaller_;
  double ratio_ = 0;  // the log-likelihood ratio of "left larger" against "right larger"
};

bool holds_when_left_larger(monitors::Comparison c) {
  return c == monitors::Comparison::GreaterEqual || c == monitors::Comparison::Greater;
}

QueryResult compare_at(const bipc::ir::System& system, const monitors::Query& q,
                       const monitors::Bindings& point, const CheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  QueryResult r;
  r.method = Method::Paired;
  r.alpha = options.alpha;
  if (!(options.delta > 0 && options.delta < 0.5)) {
    r.error = "the comparison needs 0 < delta < 0.5";
    return r;
  }
  const engines::SimulateOptions simulate = run_options(options);
  const unsigned threads = std::max(1u, options.threads);
  std::vector<std::unique_ptr<PairRuns>> workers;
  for (unsigned w = 0; w < threads; ++w) {
    workers.push_back(std::make_unique<PairRuns>(system, options.compiled, simulate, q, point));
  }
  PairedTest test(options);
  std::uint64_t left = 0, right = 0, runs = 0;
  std::string failure;
  bool decided = false;
  const auto consume = [&](const PairOutcome& o) {
    if (!o.failure.empty() && failure.empty()) failure = o.failure;
    const bool undecided = o.left == Verdict::Undecided || o.right == Verdict::Undecided;
    if (undecided) {
      ++r.undecided;
      if (options.undecided == UndecidedPolicy::Skip) return r.undecided < kMaxRuns;
      if (options.undecided == UndecidedPolicy::Error && r.undecided * 100 > runs + 100) {
        return false;
      }
    }
    ++runs;
    const bool a = o.left == Verdict::True, b = o.right == Verdict::True;
    left += a;
    right += b;
    if (!undecided || options.undecided == UndecidedPolicy::Fail) {
      decided = !test.take(a, b);
    }
    return !decided && runs < kMaxRuns;
  };
  OrderedSampler<PairOutcome> sampler(
      threads, [&](unsigned w, std::uint64_t i, PairOutcome& o) { workers[w]->run(i, o); });
  sampler.run(0, consume);
  r.samples = runs;
  r.estimate = runs == 0 ? 0
                         : (static_cast<double>(left) - static_cast<double>(right)) /
                               static_cast<double>(runs);
  if (decided) {
    r.verdict = test.left_larger() == holds_when_left_larger(q.comparison);
  } else if (r.undecided > 0 && runs < kMaxRuns) {
    r.error = std::to_string(r.undecided) + " runs undecided" +
              (failure.empty() ? std::string() : " (a run ended in an error: " + failure + ")");
  } else {
    r.error = "no decision after " + std::to_string(runs) + " runs: the two probabilities are " +
              "equal or too close to tell apart (" + std::to_string(left) + " and " +
              std::to_string(right) + " runs held each formula)";
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

std::vector<QueryResult> compare_probabilities(const bipc::ir::System& system,
                                               const QueryPoints& query,
                                               const CheckOptions& options) {
  std::vector<QueryResult> results;
  for (const monitors::Bindings& point : query.points) {
    results.push_back(compare_at(system, *query.query, point, options));
    results.back().query = query.index;
  }
  return results;
}

}  // namespace smcbip::smc
