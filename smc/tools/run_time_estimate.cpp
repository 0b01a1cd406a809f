// The pilot and run counts behind `smcbip check --compile auto`.
#include "smc/tools/run_time_estimate.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>

#include "smc/check/answer.h"
#include "smc/check/query_runs.h"
#include "smc/stats/sampling_plans.h"

namespace smcbip::tools {

namespace {

using Kind = monitors::Query::Kind;

double value_of(const monitors::Value& v, const monitors::Bindings& bindings) {
  return v.is_name() ? bindings.at(v.name) : v.number;
}

/// Wald's approximation of the SPRT's average sample number where it is largest: at the p
/// for which a run's expected log-ratio step is 0, E[N] = -a b / E[Z^2] with a and b the
/// thresholds (Wald 1947, Sequential Analysis, ch. 3).
double sprt_largest_average(double theta, double delta, double alpha, double beta) {
  const double p0 = std::min(1.0, theta + delta), p1 = std::max(0.0, theta - delta);
  const double accept = std::log(beta / (1 - alpha)), reject = std::log((1 - beta) / alpha);
  // At p0 = 1 one failure rejects, at p1 = 0 one success accepts: the other kind of run
  // decides alone, after this many of them.
  if (p1 <= 0 && p0 >= 1) return 1;
  if (p0 >= 1) return accept / std::log(p1);
  if (p1 <= 0) return reject / -std::log(1 - p0);
  const double on_success = std::log(p1 / p0), on_failure = std::log((1 - p1) / (1 - p0));
  const double p = on_failure / (on_failure - on_success);
  const double step2 = p * on_success * on_success + (1 - p) * on_failure * on_failure;
  return -accept * reject / step2;
}

/// Whether the pilot can time runs of `q` (one QueryRuns judges it).
bool piloted(const monitors::Query& q) {
  return q.kind == Kind::Estimate || q.kind == Kind::Hypothesis ||
         (q.kind == Kind::Expectation && q.pr_form);
}

/// Seconds per interpreted run of `q`: runs 0, 1, ... for about kPilotSeconds, at most `limit`.
double time_runs(const bipc::ir::System& system, const monitors::PropertyFile& file,
                 const monitors::Query& q, std::size_t index, const smc::CheckOptions& options,
                 std::uint64_t limit) {
  smc::QueryPoints query;
  query.query = &q;
  query.index = index;
  query.points = monitors::query_bindings(file, q);
  engines::SimulateOptions simulate = smc::run_options(options);
  simulate.silent = true;
  smc::QueryRuns runs(system, nullptr, simulate, query);
  const auto done = std::make_unique<std::atomic<bool>[]>(query.points.size());
  smc::RunOutcomes made;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0;
  std::uint64_t made_runs = 0;
  while (made_runs < std::max<std::uint64_t>(limit, 1) &&
         (made_runs == 0 || elapsed < kPilotSeconds)) {
    runs.run(made_runs++, done.get(), made);
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return elapsed / static_cast<double>(made_runs);
}

}  // namespace

std::uint64_t expected_runs(const monitors::PropertyFile& file, const monitors::Query& q,
                            const smc::CheckOptions& options, bool explore, bool& sequential) {
  if (q.kind == Kind::Invariant || q.kind == Kind::Reachable) return 0;
  const std::vector<monitors::Bindings> points = monitors::query_bindings(file, q);
  const double split = explore && points.size() > 1 ? static_cast<double>(points.size()) : 1;
  const double alpha = options.alpha / split, beta = options.beta / split;
  double most = 0;
  for (const monitors::Bindings& b : points) {
    if (q.kind == Kind::Simulate || q.kind == Kind::Expectation) {
      most = std::max(most, q.pr_form || q.kind == Kind::Simulate ? value_of(q.runs, b) : 0);
      continue;
    }
    if (q.kind == Kind::Compare) {
      // Each pair of runs counts once; about half of them differ at p = 1/2.
      sequential = true;
      most = std::max(most, 4 * sprt_largest_average(0.5, options.delta, alpha, beta));
      continue;
    }
    const double theta = q.kind == Kind::Hypothesis ? value_of(q.threshold, b) : 0;
    switch (smc::method_for(q, options.method)) {
      case smc::Method::Ssp:
        most = std::max(most, static_cast<double>(
                                  smc::single_sampling_plan(theta, options.delta, alpha, beta).n));
        break;
      case smc::Method::Sprt:
        sequential = true;
        most = std::max(most, sprt_largest_average(theta, options.delta, alpha, beta));
        break;
      case smc::Method::Ci:
      case smc::Method::Bayes:
        sequential = true;
        [[fallthrough]];
      default:
        most = std::max(most, static_cast<double>(smc::chernoff_samples(options.delta, alpha)));
        break;
    }
  }
  return static_cast<std::uint64_t>(std::ceil(most));
}

RunTimeEstimate estimate_run_time(const bipc::ir::System& system,
                                  const monitors::PropertyFile& file,
                                  const smc::CheckOptions& options, bool explore) {
  RunTimeEstimate estimate;
  const monitors::Query* pilot = nullptr;
  std::size_t pilot_index = 0;
  std::uint64_t pilot_runs = 0;
  for (std::size_t i = 0; i < file.queries.size(); ++i) {
    const monitors::Query& q = file.queries[i];
    const std::uint64_t runs = expected_runs(file, q, options, explore, estimate.sequential);
    estimate.runs += runs;
    if (pilot == nullptr && runs > 0 && piloted(q)) {
      pilot = &q;
      pilot_index = i;
      pilot_runs = runs;
    }
  }
  if (pilot == nullptr) return estimate;
  try {
    estimate.run_seconds = time_runs(system, file, *pilot, pilot_index, options, pilot_runs);
  } catch (const std::exception&) {
    return estimate;  // the check reports what the model or query cannot do
  }
  estimate.seconds =
      estimate.run_seconds * static_cast<double>(estimate.runs) / std::max(1u, options.threads);
  return estimate;
}

}  // namespace smcbip::tools
