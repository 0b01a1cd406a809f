#include "smc/check/check.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "bipc/output_file.h"
#include "smc/check/answer.h"
#include "smc/check/compare.h"
#include "smc/check/ordered_sampler.h"
#include "smc/check/query_runs.h"
#include "smc/check/remote_runs.h"
#include "smc/check/simulate_runs.h"

namespace smcbip::smc {
namespace {

/// The points' `done` flags, alone on their cache lines: every worker reads them at every run,
/// and a neighbour that the consumer writes at every run (an answer's counts) would make each
/// of those reads a cache miss.
class DoneFlags {
 public:
  explicit DoneFlags(std::size_t points)
      : storage_(std::make_unique<std::atomic<bool>[]>(points + 2 * kLine)) {}
  std::atomic<bool>* get() const { return storage_.get() + kLine; }

 private:
  static_assert(sizeof(std::atomic<bool>) == 1);
  static constexpr std::size_t kLine = 64;  // bytes of a cache line
  std::unique_ptr<std::atomic<bool>[]> storage_;
};

double value_of(const monitors::Value& v, const monitors::Bindings& bindings) {
  return v.is_name() ? bindings.at(v.name) : v.number;
}

/// Keeps run `index`'s trace in `folder`; on failure every open answer gets the error.
bool save_trace(const std::string& folder, std::size_t query, std::uint64_t index,
                const std::string& trace, std::vector<QueryResult>& results) {
  const std::string path =
      folder + "/query-" + std::to_string(query + 1) + "-run-" + std::to_string(index) + ".jsonl";
  std::string error;
  if (bipc::write_file_atomically(path, trace, error)) return true;
  for (QueryResult& r : results) {
    if (r.error.empty()) r.error = "--save-traces: " + error;
  }
  return false;
}

/// Why `A[] phi` and `E<> phi` get no statistical answer, and what answers them.
std::string exact_only(const monitors::Query& q) {
  const bool all = q.kind == monitors::Query::Kind::Invariant;
  return std::string(all ? "A[] phi asks whether phi holds in every reachable state"
                         : "E<> phi asks whether phi holds in some reachable state") +
         ", which sampled runs cannot show: it is answered exactly by the invariant prover "
         "(smcbip prove); statistically, " +
         (all ? "P>=1 [ G phi ]" : "P>0 [ F phi ]") + " tests the runs";
}

/// Up to when the first times of F phi are watched (ms): the run's time bound or F's, the
/// nearer; 0 for a query that is no estimate of F phi within a time bound (none are kept).
double first_hit_horizon(const monitors::Query& q, const monitors::Bindings& b) {
  if (q.kind != monitors::Query::Kind::Estimate || !q.formula ||
      q.formula->kind != monitors::Formula::Kind::Finally) {
    return 0;
  }
  // The engines count nanoseconds; models' times and bounds are in milliseconds.
  constexpr monitors::TimeScale kNanoseconds{1e6, 1e9};
  double horizon = std::numeric_limits<double>::infinity();
  const monitors::Bound* bounds[] = {&q.run, &q.formula->bound};
  for (const monitors::Bound* bound : bounds) {
    if (bound->kind != monitors::Bound::Kind::Time) continue;
    const auto ticks = static_cast<double>(monitors::bound_ticks(bound->high, kNanoseconds, b));
    horizon = std::min(horizon, ticks / 1e6);
  }
  return std::isfinite(horizon) ? horizon : 0;
}

/// What each point of a query is judged at.
CheckOptions point_options(const monitors::Query& q, const QueryPoints& query,
                           const CheckOptions& options, bool simultaneous) {
  CheckOptions o = options;
  if (query.swept) {
    o.method = Method::Band;
    if (q.kind == monitors::Query::Kind::Hypothesis) o.alpha = std::min(o.alpha, o.beta);
    return o;
  }
  o.method = method_for(q, options.method);
  if (simultaneous && query.points.size() > 1) {
    const auto k = static_cast<double>(query.points.size());
    o.alpha /= k;
    o.beta /= k;
    o.confidence = 1 - (1 - o.confidence) / k;
  }
  return o;
}

std::vector<QueryResult> answer(const bipc::ir::System& system, const QueryPoints& query,
                                const CheckOptions& options, bool simultaneous) {
  const auto start = std::chrono::steady_clock::now();
  const monitors::Query& q = *query.query;
  const std::size_t n = query.points.size();
  const CheckOptions judged = point_options(q, query, options, simultaneous);
  std::vector<QueryResult> results(n);
  for (std::size_t p = 0; p < n; ++p) {
    QueryResult& r = results[p];
    r.method = judged.method;
    r.alpha = q.kind == monitors::Query::Kind::Expectation ? 1 - judged.confidence : judged.alpha;
    r.split = simultaneous && !query.swept ? n : 1;
    if (options.first_hits && !query.swept)
      r.first_hit_horizon = first_hit_horizon(q, query.points[p]);
  }
  if (q.kind == monitors::Query::Kind::Invariant || q.kind == monitors::Query::Kind::Reachable) {
    for (QueryResult& r : results) r.error = exact_only(q);
    return results;
  }
  if (q.kind == monitors::Query::Kind::Compare) {
    return compare_probabilities(system, query, judged);
  }
  if (q.kind == monitors::Query::Kind::Simulate)
    return simulate_trajectories(system, query, options);
  if (q.kind == monitors::Query::Kind::Expectation && !q.pr_form) {
    for (QueryResult& r : results) {
      r.error = "E=? [ ... ] needs a run bound and a number of runs here: write E[<=T; N](...)";
    }
    return results;
  }
  engines::SimulateOptions simulate = run_options(options);
  simulate.silent = options.save_traces.empty();
  simulate.trace = engines::TraceFormat::Jsonl;
  const bool serving = options.remote && options.remote->serving();
  const unsigned threads = serving ? 1u : std::max(1u, options.threads);
  std::vector<std::unique_ptr<QueryRuns>> workers;
  for (unsigned w = 0; w < threads; ++w) {
    workers.push_back(std::make_unique<QueryRuns>(system, options.compiled, simulate, query));
  }

  using K = monitors::Query::Kind;
  std::vector<Answer> answers;
  for (std::size_t p = 0; p < n; ++p) {
    const monitors::Bindings& b = query.points[p];
    const double theta = q.kind == K::Hypothesis ? value_of(q.threshold, b) : 0;
    const auto runs =
        q.kind == K::Expectation ? static_cast<std::uint64_t>(value_of(q.runs, b)) : 0;
    answers.emplace_back(q, judged, theta, runs, results[p]);
  }
  // Set by the consumer once a point's answer is known; workers then stop judging it.
  const DoneFlags done_flags(n);
  std::atomic<bool>* const done = done_flags.get();
  std::size_t open = n;
  std::uint64_t consumed = 0;
  auto reported = start;
  const auto report = [&] {
    const auto now = std::chrono::steady_clock::now();
    if (now - reported < std::chrono::milliseconds(100)) return;
    reported = now;
    Progress p;
    p.query = query.index;
    p.points = n;
    p.open = open;
    p.runs = consumed;
    p.seconds = std::chrono::duration<double>(now - start).count();
    for (std::size_t i = 0; i < n; ++i) {
      if (done[i].load(std::memory_order_relaxed)) continue;
      p.target = answers[i].target();
      p.estimate = results[i].estimate;
      p.test_position = answers[i].test_position();
      break;
    }
    options.progress(p);
  };
  if (serving) {
    options.remote->serve(n, done, [&](std::uint64_t index, RunOutcomes& made) {
      workers[0]->run(index, done, made);
    });
    return results;
  }
  std::string first_failure;  // why a run ended in an error, for queries that fail for it
  const auto consume = [&](const RunOutcomes& outcomes) {
    if (!outcomes.failure.empty() && first_failure.empty()) {
      first_failure = "run " + std::to_string(consumed) + " ended in an error: " + outcomes.failure;
    }
    if (!options.save_traces.empty() && outcomes.trace_cut) {
      for (QueryResult& r : results) {
        if (r.error.empty()) {
          r.error = "--save-traces: the trace of run " + std::to_string(consumed) +
                    " is larger than " + std::to_string(kMaxSavedTraceBytes >> 20) +
                    " MiB; lower --max-steps";
        }
      }
      return false;
    }
    if (!options.save_traces.empty() &&
        !save_trace(options.save_traces, query.index, consumed, outcomes.trace, results)) {
      return false;
    }
    for (std::size_t p = 0; p < n; ++p) {
      if (done[p].load(std::memory_order_relaxed) ||
          answers[p].take(outcomes.points[p], consumed, outcomes.end, outcomes.failure)) {
        continue;
      }
      done[p].store(true, std::memory_order_relaxed);
      --open;
    }
    // Reading the clock costs little next to a run, but only every 64th run asks.
    if (++consumed % 64 == 0 && options.progress) report();
    return open > 0;
  };
  if (options.remote) {
    const std::string failed = options.remote->consume(n, done, consume);
    for (std::size_t p = 0; p < n && !failed.empty(); ++p) {
      if (results[p].error.empty() && !done[p].load()) results[p].error = failed;
    }
  } else {
    OrderedSampler<RunOutcomes> sampler(threads,
                                        [&](unsigned w, std::uint64_t index, RunOutcomes& made) {
                                          workers[w]->run(index, done, made);
                                        });
    sampler.run(0, consume);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (std::size_t p = 0; p < n; ++p) {
    answers[p].finish();
    results[p].seconds = seconds;
    if (!results[p].error.empty() && !first_failure.empty() &&
        results[p].why_undecided.error == 0) {
      results[p].error += " (" + first_failure + ")";
    }
  }
  return results;
}

/// The parameter `q` sweeps by a critical bound, when exploring with the Auto method.
std::optional<std::string> band_parameter(
    const monitors::Query& q, const std::map<std::string, std::vector<double>>& parameters,
    const std::vector<monitors::Bindings>& points) {
  if (!q.formula || points.size() < 2) return std::nullopt;
  std::optional<std::string> swept;
  for (const auto& [name, values] : parameters) {
    if (!points.front().contains(name)) continue;
    if (swept) return std::nullopt;  // a grid over several parameters
    swept = name;
  }
  const auto names = [&](const monitors::Value& v) { return swept && v.name == *swept; };
  if (!swept || names(q.run.high) || names(q.threshold) ||
      !monitors::has_critical_bound(*q.formula, *swept)) {
    return std::nullopt;
  }
  return swept;
}

std::vector<QueryResult> answer_all(const bipc::ir::System& system,
                                    const monitors::PropertyFile& file, const CheckOptions& options,
                                    bool simultaneous) {
  std::vector<QueryResult> results;
  const auto parameters = monitors::parameter_values(file);
  for (std::size_t i = 0; i < file.queries.size(); ++i) {
    QueryPoints query;
    query.query = &file.queries[i];
    query.index = i;
    query.points = monitors::query_bindings(file, file.queries[i]);
    if (simultaneous && options.method == Method::Auto) {
      query.swept = band_parameter(*query.query, parameters, query.points);
    }
    std::vector<QueryResult> answered = answer(system, query, options, simultaneous);
    for (std::size_t p = 0; p < answered.size(); ++p) {
      QueryResult& r = answered[p];
      r.query = i;
      for (const auto& [name, value] : query.points[p]) {
        if (parameters.contains(name)) r.parameters[name] = value;
      }
      results.push_back(std::move(r));
    }
  }
  return results;
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
    case Method::Band:
      return "dkw";
    case Method::Paired:
      return "paired sprt";
    case Method::Auto:
      break;
  }
  return "auto";
}

std::vector<QueryResult> check_properties(const bipc::ir::System& system,
                                          const monitors::PropertyFile& file,
                                          const CheckOptions& options) {
  return answer_all(system, file, options, false);
}

std::vector<QueryResult> explore_properties(const bipc::ir::System& system,
                                            const monitors::PropertyFile& file,
                                            const CheckOptions& options) {
  return answer_all(system, file, options, true);
}

}  // namespace smcbip::smc
