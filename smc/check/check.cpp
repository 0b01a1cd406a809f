#include "smc/check/check.h"

#include <boost/math/distributions/normal.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <streambuf>

#include "smc/check/ordered_sampler.h"
#include "smc/stats/sampling_plans.h"
#include "smc/stats/sprt.h"

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

/// One run's answer: the formula's verdict, or the observed expression's maximum or minimum.
struct Outcome {
  Verdict verdict = Verdict::Undecided;
  double value = 0;
};

/// What one thread needs to make runs of one query: its simulator and its observer.
class Worker {
 public:
  Worker(const bipc::ir::System& system, const engines::SimulateOptions& options,
         const monitors::Query& q, const monitors::Bindings& bindings)
      : simulator_(system, options, engines::Externs::with_builtins()), sink_(&nothing_) {
    if (!simulator_.problem().empty()) throw std::invalid_argument(simulator_.problem());
    if (q.formula) {
      monitor_ = std::make_unique<monitors::RunMonitor>(*q.formula, kNanoseconds, bindings, q.run);
    } else {
      extremum_ = std::make_unique<monitors::RunExtremum>(q, kNanoseconds, bindings);
    }
  }

  Outcome run(std::uint64_t index) {
    const engines::RunStreams streams{sink_, sink_};
    if (monitor_) {
      monitor_->reset();
      simulator_.run(index, streams, monitor_.get());
      return {monitor_->verdict(), 0};
    }
    extremum_->reset();
    simulator_.run(index, streams, extremum_.get());
    return {Verdict::True, extremum_->value().value_or(std::numeric_limits<double>::quiet_NaN())};
  }

 private:
  engines::Simulator simulator_;
  NullBuffer nothing_;
  std::ostream sink_;
  std::unique_ptr<monitors::RunMonitor> monitor_;
  std::unique_ptr<monitors::RunExtremum> extremum_;
};

bool holds_at_least(monitors::Comparison c) {
  return c == monitors::Comparison::GreaterEqual || c == monitors::Comparison::Greater;
}

bool compare(double estimate, monitors::Comparison c, double theta) {
  switch (c) {
    case monitors::Comparison::GreaterEqual:
      return estimate >= theta;
    case monitors::Comparison::Greater:
      return estimate > theta;
    case monitors::Comparison::LessEqual:
      return estimate <= theta;
    case monitors::Comparison::Less:
      return estimate < theta;
  }
  return false;
}

Method method_for(const monitors::Query& q, Method asked) {
  using K = monitors::Query::Kind;
  if (q.kind == K::Expectation) return Method::Mean;
  const bool tests = asked == Method::Sprt || asked == Method::Ssp;
  if (asked == Method::Auto || (tests && q.kind == K::Estimate)) {
    return q.kind == K::Hypothesis ? Method::Sprt : Method::Pestim;
  }
  return asked;
}

/// Consumes the outcomes of one query's runs in index order and keeps its answer.
class Answer {
 public:
  /// `theta`: a hypothesis' threshold; `runs`: an expectation's number of runs.
  Answer(const monitors::Query& q, const CheckOptions& options, double theta, std::uint64_t runs,
         QueryResult& r)
      : q_(q), options_(options), theta_(theta), runs_(runs), r_(r) {}

  /// Takes one run's outcome; false once the answer is known.
  bool take(const Outcome& outcome) {
    if (outcome.verdict == Verdict::Undecided) {
      ++r_.undecided;
      if (options_.undecided == UndecidedPolicy::Error && r_.undecided > 10 &&
          r_.undecided * 100 > r_.samples + r_.undecided) {
        r_.error = std::to_string(r_.undecided) + " of " +
                   std::to_string(r_.samples + r_.undecided) +
                   " runs undecided (more than 1%): raise --max-steps, or choose --undecided";
        return false;
      }
      if (options_.undecided != UndecidedPolicy::Fail) return true;
    }
    ++r_.samples;
    return sample(outcome.verdict == Verdict::True, outcome.value);
  }

  void finish() {
    if (r_.method == Method::Mean) {
      const double n = static_cast<double>(r_.samples);
      r_.estimate = sum_ / n;
      const double variance = n > 1 ? (squares_ - n * r_.estimate * r_.estimate) / (n - 1) : 0;
      const boost::math::normal normal;
      const double z = boost::math::quantile(normal, 1 - (1 - options_.confidence) / 2);
      const double half = z * std::sqrt(std::max(0.0, variance) / n);
      r_.ci = {r_.estimate - half, r_.estimate + half};
      return;
    }
    if (q_.kind == monitors::Query::Kind::Hypothesis && !r_.verdict && r_.error.empty()) {
      r_.verdict = compare(r_.estimate, q_.comparison, theta_);
    }
  }

 private:
  bool sample(bool satisfied, double value) {
    switch (r_.method) {
      case Method::Sprt: {
        if (!sprt_) sprt_.emplace(theta_, options_.delta, options_.alpha, options_.beta);
        const Decision d = sprt_->add(satisfied);
        r_.estimate = ratio(sprt_->successes(), sprt_->samples());
        if (d == Decision::Undecided) return true;
        r_.verdict = (d == Decision::AtLeast) == holds_at_least(q_.comparison);
        return false;
      }
      case Method::Ssp: {
        if (!plan_)
          plan_ = single_sampling_plan(theta_, options_.delta, options_.alpha, options_.beta);
        successes_ += satisfied;
        r_.estimate = ratio(successes_, r_.samples);
        if (r_.samples < plan_->n) return true;
        r_.verdict = (successes_ > plan_->c) == holds_at_least(q_.comparison);
        return false;
      }
      case Method::Pestim: {
        const std::uint64_t n = chernoff_samples(options_.delta, options_.alpha);
        successes_ += satisfied;
        r_.estimate = ratio(successes_, r_.samples);
        r_.ci = {std::max(0.0, r_.estimate - options_.delta),
                 std::min(1.0, r_.estimate + options_.delta)};
        return r_.samples < n;
      }
      case Method::Ci: {
        if (!interval_) interval_.emplace(options_.delta, options_.alpha);
        const bool done = interval_->add(satisfied);
        r_.estimate = interval_->estimate();
        r_.ci = interval_->interval();
        return !done;
      }
      case Method::Bayes: {
        if (!bayes_) bayes_.emplace(options_.delta, options_.confidence);
        const bool done = bayes_->add(satisfied);
        r_.estimate = bayes_->estimate();
        r_.ci = bayes_->interval();
        return !done;
      }
      case Method::Mean:
      case Method::Auto:
        break;
    }
    sum_ += value;
    squares_ += value * value;
    return r_.samples < runs_;
  }

  static double ratio(std::uint64_t x, std::uint64_t n) {
    return n == 0 ? 0.0 : static_cast<double>(x) / static_cast<double>(n);
  }

  const monitors::Query& q_;
  const CheckOptions& options_;
  double theta_;
  std::uint64_t runs_;
  QueryResult& r_;
  std::optional<Sprt> sprt_;
  std::optional<SamplingPlan> plan_;
  std::optional<SequentialInterval> interval_;
  std::optional<BayesianInterval> bayes_;
  std::uint64_t successes_ = 0;
  double sum_ = 0, squares_ = 0;
};

double value_of(const monitors::Value& v, const monitors::Bindings& bindings) {
  return v.is_name() ? bindings.at(v.name) : v.number;
}

QueryResult answer(const bipc::ir::System& system, const monitors::Query& q,
                   const monitors::Bindings& bindings, const CheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  QueryResult r;
  r.method = method_for(q, options.method);
  if (q.kind == monitors::Query::Kind::Expectation && !q.pr_form) {
    r.error = "E=? [ ... ] needs a run bound and a number of runs here: write E[<=T; N](...)";
    return r;
  }
  engines::SimulateOptions simulate;
  simulate.engine = options.engine;
  simulate.seed = options.seed;
  simulate.limit = options.max_steps;
  simulate.silent = true;
  std::vector<std::unique_ptr<Worker>> workers;
  const unsigned threads = std::max(1u, options.threads);
  for (unsigned w = 0; w < threads; ++w) {
    workers.push_back(std::make_unique<Worker>(system, simulate, q, bindings));
  }
  using K = monitors::Query::Kind;
  const double theta = q.kind == K::Hypothesis ? value_of(q.threshold, bindings) : 0;
  const auto runs =
      q.kind == K::Expectation ? static_cast<std::uint64_t>(value_of(q.runs, bindings)) : 0;
  Answer a(q, options, theta, runs, r);
  OrderedSampler<Outcome> sampler(
      threads, [&](unsigned w, std::uint64_t index) { return workers[w]->run(index); });
  sampler.run(0, [&](const Outcome& o) { return a.take(o); });
  a.finish();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

const char* method_name(Method method) {
  switch (method) {
    case Method::Sprt:
      return "sprt";
    case Method::Ssp:
      return "ssp";
    case Method::Pestim:
      return "pestim";
    case Method::Ci:
      return "ci";
    case Method::Bayes:
      return "bayes";
    case Method::Mean:
      return "mean";
    case Method::Auto:
      break;
  }
  return "auto";
}

std::vector<QueryResult> check_properties(const bipc::ir::System& system,
                                          const monitors::PropertyFile& file,
                                          const CheckOptions& options) {
  std::vector<QueryResult> results;
  const auto parameters = monitors::parameter_values(file);
  for (std::size_t i = 0; i < file.queries.size(); ++i) {
    for (const monitors::Bindings& bindings : monitors::query_bindings(file, file.queries[i])) {
      QueryResult r = answer(system, file.queries[i], bindings, options);
      r.query = i;
      for (const auto& [name, value] : bindings) {
        if (parameters.contains(name)) r.parameters[name] = value;
      }
      results.push_back(std::move(r));
    }
  }
  return results;
}

}  // namespace smcbip::smc
