// Consuming one query point's run outcomes, in run-index order, into its answer: a hypothesis
// test's verdict or an estimate with its interval.
#pragma once

#include <cstdint>
#include <optional>

#include "monitors/monitors.h"
#include "smc/check/check.h"
#include "smc/stats/interval_estimation.h"
#include "smc/stats/sampling_plans.h"
#include "smc/stats/sprt.h"

namespace smcbip::smc {

/// One run's answer for one point: the formula's verdict, or the observed expression's
/// maximum or minimum (then the verdict is True, or Undecided when the run observed nothing).
struct Outcome {
  monitors::Verdict verdict = monitors::Verdict::Undecided;
  double value = 0;
};

/// The method a query is answered with when `asked` (Auto: SPRT for hypotheses, PESTIM for
/// estimates; tests asked of estimates fall back to PESTIM; expectations take the mean).
Method method_for(const monitors::Query& q, Method asked);

/// Takes the outcomes of one point's runs in index order and keeps its answer in `result`.
class Answer {
 public:
  /// `options`: what this point is judged at (α already split, method chosen); `theta`: a
  /// hypothesis' threshold; `runs`: an expectation's number of runs.
  Answer(const monitors::Query& q, const CheckOptions& options, double theta, std::uint64_t runs,
         QueryResult& result);

  /// Takes the outcome of run `index`, which ended as `end` (with `failure`, the model's
  /// error, for an Error end); false once the answer is known, or given up (result's error).
  bool take(const Outcome& outcome, std::uint64_t index, engines::RunEnd end,
            const std::string& failure);
  /// Completes the answer once no more outcomes come.
  void finish();

  /// The runs a fixed-size method needs (0 for a sequential one).
  std::uint64_t target() const;
  /// SPRT: where the log-likelihood ratio stands between the threshold that accepts (0) and
  /// the one that rejects (1); -1 for other methods.
  double test_position() const;

 private:
  bool sample(bool satisfied, double value);
  /// Counts an undecided run; false when the query gives up on it.
  bool undecided(std::uint64_t index, engines::RunEnd end, const std::string& failure);
  void finish_mean();

  const monitors::Query* q_;
  CheckOptions options_;
  double theta_;
  std::uint64_t runs_;
  QueryResult* r_;
  std::optional<Sprt> sprt_;
  std::optional<SamplingPlan> plan_;
  std::optional<std::uint64_t> chernoff_n_;  // the runs Pestim and Band make, once computed
  std::optional<SequentialInterval> interval_;
  std::optional<BayesianInterval> bayes_;
  std::uint64_t successes_ = 0;
  double sum_ = 0, squares_ = 0;
};

}  // namespace smcbip::smc
