// `smcbip check`'s work: every query of a property file answered from runs of a model, by
// hypothesis tests (SPRT, single sampling plan) or estimates (PESTIM, sequential confidence
// interval, Bayesian interval), each run judged by the online monitor.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/plugin.h"
#include "engines/engines.h"
#include "monitors/monitors.h"
#include "smc/stats/interval_estimation.h"

namespace smcbip::smc {

class RemoteRuns;

/// Band: PESTIM's runs judged for every value of a monotone parameter at once, with DKW's
/// simultaneous band (explore).
/// Paired: the SPRT on runs judged for two formulas, which compares their probabilities.
enum class Method : std::uint8_t { Auto, Sprt, Ssp, Pestim, Ci, Bayes, Mean, Band, Paired };

/// How runs the monitor leaves undecided count: as failures, not at all (another run is
/// drawn, until kMaxSkippedRuns of them outnumber the decided ones), or not at all up to 1% of
/// the runs; beyond these bounds the query gives up with an error. A run that ended in a model
/// error is never counted as a failure: under Fail the query gives up with that error. An
/// expectation has no value for an undecided run: under Fail it gives up too.
enum class UndecidedPolicy : std::uint8_t { Fail, Skip, Error };

/// Under UndecidedPolicy::Skip a query gives up once this many runs were undecided and they
/// outnumber the decided ones, rather than draw runs forever.
inline constexpr std::uint64_t kMaxSkippedRuns = 1000;

/// With --save-traces, a run's trace is kept in memory until its answer counts it: a larger
/// trace ends the query with an error rather than exhaust memory (lower --max-steps).
inline constexpr std::size_t kMaxSavedTraceBytes = std::size_t{64} << 20;

/// The runs of a point left undecided, by how they ended (the engines' RunEnd).
struct UndecidedRuns {
  std::uint64_t limit = 0;     // cut by the step limit (--max-steps)
  std::uint64_t timelock = 0;  // time could not progress
  std::uint64_t error = 0;     // the model failed (its message in first_error)
  std::uint64_t ended = 0;     // a deadlock, or a stop, before the formula was decided
  std::uint64_t first_error_run = 0;
  std::string first_error;  // the first model error, empty if none
};

/// Why runs were undecided, for a message: "12 at the step limit (--max-steps 20) ...".
std::string undecided_text(const UndecidedRuns& runs, std::uint64_t max_steps);

/// Where a query's answer stands while its runs are made (for a progress display).
struct Progress {
  std::size_t query = 0;             // index in the file
  std::size_t points = 1, open = 1;  // the query's points, and those not answered yet
  std::uint64_t runs = 0;            // made and consumed so far
  std::uint64_t target = 0;          // runs a fixed-size method needs (0: sequential)
  double estimate = 0;               // of the first open point
  double seconds = 0;                // since the query started
  /// SPRT: where the first open point's log-likelihood ratio stands between the threshold
  /// that accepts (0) and the one that rejects (1); negative when there is none.
  double test_position = -1;
};

struct CheckOptions {
  Method method = Method::Auto;  // Auto: SPRT for hypotheses, PESTIM for estimates
  double alpha = 0.05, beta = 0.05, delta = 0.01;
  double confidence = 0.95;  // Bayesian coverage, expectations' intervals
  std::uint64_t seed = 1;
  unsigned threads = 1;
  std::uint64_t max_steps = 1'000'000;  // per run
  UndecidedPolicy undecided = UndecidedPolicy::Error;
  engines::EngineKind engine = engines::EngineKind::Optimised;
  /// Runs the model `bipc gen` compiled into this plugin rather than interpreting the IR (the
  /// same model: its hash must be the IR's, which the caller checks); null: the interpreter.
  const engines::PluginEntry* compiled = nullptr;
  /// A folder to keep the trace of every run an answer took (JSON lines, as `smcbip simulate
  /// --trace jsonl` writes them, each ending where its verdicts were known), named
  /// query-<q>-run-<i>.jsonl with q counted from 1 in the file and i the run index; empty: none.
  std::string save_traces;
  /// Keep, for each estimate of F phi, when phi first held in each run (check --plot).
  bool first_hits = false;
  /// Runs made by other processes (MPI): null for the threads of this one. On a worker
  /// process check_properties serves runs and its results mean nothing.
  RemoteRuns* remote = nullptr;
  /// Called now and then (about ten times a second) while a query's runs are made.
  std::function<void(const Progress&)> progress;
};

/// The trajectories of a simulate query: per run, its points in time order, each the time (in
/// the model's unit, milliseconds) and then one value per expression. Where an expression
/// grows between two steps (a clock), the point just before the later step shows its value
/// there, so that lines between points follow it.
struct Trajectories {
  std::vector<std::string> series;                     // the expressions, as echoed
  std::vector<std::vector<std::vector<double>>> runs;  // run, point, {time, values...}
};

struct QueryResult {
  std::size_t query = 0;
  monitors::Bindings parameters;
  Method method = Method::Auto;  // the one used
  double estimate = 0;
  Interval ci;
  std::optional<bool> verdict;  // hypotheses
  std::uint64_t samples = 0, undecided = 0;
  UndecidedRuns why_undecided;  // how the undecided runs ended
  double seconds = 0;
  /// What the point was judged at: its α (for a band, the whole band's α) and the number of
  /// points of its sweep that α was split over (1: not split).
  double alpha = 0;
  std::size_t split = 1;
  std::string error;  // why the query has no answer (too many undecided runs)
  std::shared_ptr<const Trajectories> trajectories;  // simulate queries
  /// Estimates of F phi with CheckOptions::first_hits: when phi first held in each run that
  /// satisfied it (ms), and up to when runs were watched (the run or F's bound).
  std::vector<double> first_hits;
  double first_hit_horizon = 0;
};

const char* method_name(Method method);

/// Answers every query of `file` (names resolved against `system`) in file order, once per
/// value of the parameters it names. Runs are numbered from 0 for each query; the same seed
/// gives the same answers and sample counts for any number of threads. Throws
/// monitors::MonitorError (bounds) and std::invalid_argument (what the model cannot run).
std::vector<QueryResult> check_properties(const bipc::ir::System& system,
                                          const monitors::PropertyFile& file,
                                          const CheckOptions& options);

/// Answers every query as check_properties does, but with a guarantee for each query's whole
/// sweep at once rather than point by point. F[0,t] phi and G[0,t] phi over one parameter t
/// (and the Auto method) are judged for every t from one set of runs, each estimate within
/// DKW's simultaneous band; any other sweep splits α (and β, and 1 - confidence) evenly over
/// its points. The points of a query always share their runs.
std::vector<QueryResult> explore_properties(const bipc::ir::System& system,
                                            const monitors::PropertyFile& file,
                                            const CheckOptions& options);

}  // namespace smcbip::smc
