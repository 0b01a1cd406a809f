// One run of a model judged for every point of a query (each value of its parameters) at once:
// the points share the run, so a sweep costs one simulation per run index, not one per point.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "engines/api/plugin.h"
#include "engines/engines.h"
#include "monitors/monitors.h"
#include "smc/check/answer.h"

namespace smcbip::smc {

/// A query with the points it is judged at.
struct QueryPoints {
  const monitors::Query* query = nullptr;
  std::size_t index = 0;                   // in its file
  std::vector<monitors::Bindings> points;  // constants and parameters
  /// Set when F[0,t]/G[0,t] is judged for every value of t by one critical bound.
  std::optional<std::string> swept;
};

/// One run's outcome for each point of its query, and its trace when traces are kept.
struct RunOutcomes {
  std::vector<Outcome> points;
  std::string trace;
  bool trace_cut = false;  // the trace outgrew kMaxSavedTraceBytes: `trace` holds its start
  engines::RunEnd end = engines::RunEnd::Stopped;  // how the run ended
  std::string failure;                             // the error the run ended in, if it did
};

/// How the runs of a query are made: the engine, seed and step limit of `options`, silent.
engines::SimulateOptions run_options(const CheckOptions& options);

/// A simulator of the model, or of the generated model of `compiled` when given (its externs
/// registered into `externs`, which must outlive it). Throws std::invalid_argument when the
/// model cannot run.
std::unique_ptr<engines::Simulator> make_simulator(const bipc::ir::System& system,
                                                   const engines::PluginEntry* compiled,
                                                   const engines::SimulateOptions& options,
                                                   engines::Externs& externs);

/// Makes runs of a query's model on one thread and judges them for its points.
class QueryRuns {
 public:
  /// Throws std::invalid_argument when the model cannot run.
  /// With `compiled`, runs are made by the generated model of that plugin.
  QueryRuns(const bipc::ir::System& system, const engines::PluginEntry* compiled,
            const engines::SimulateOptions& options, const QueryPoints& query);
  ~QueryRuns();

  /// Run `index`, judged for the points whose `done` flag is clear (the others get Undecided);
  /// it stops once every one of them is decided. Its outcomes and (when `options.silent` was
  /// false) its trace go to `made`, whose storage is reused.
  void run(std::uint64_t index, const std::atomic<bool>* done, RunOutcomes& made);

 private:
  class Observer;
  class CappedText;

  /// Whether the runs of `q` end in absorbing states (engines::SimulateOptions::stop_absorbing):
  /// the formula reads places and data only, at every point.
  bool stops_when_absorbed(const monitors::Query& q,
                           const std::vector<monitors::Bindings>& points) const;
  /// Whether the runs of `q` have a bound: the query's own, or its formula's at some point.
  static bool bounded(const monitors::Query& q, const std::vector<monitors::Bindings>& points);

  engines::Externs externs_;
  std::unique_ptr<engines::Simulator> simulator_;
  const QueryPoints& query_;
  std::vector<std::unique_ptr<monitors::RunMonitor>> monitors_;  // path formulas, per point
  std::vector<std::unique_ptr<monitors::RunExtremum>> extrema_;  // expectations, per point
  std::unique_ptr<monitors::RunCriticalBound> sweep_;            // all points at once
  std::vector<double> swept_values_;  // the swept parameter's value at each point
  std::vector<char> judged_;          // this run: the points watched
  std::unique_ptr<Observer> observer_;
  std::unique_ptr<std::streambuf> nothing_;
  std::ostream sink_;
  bool traced_;
  std::unique_ptr<CappedText> trace_text_;  // at most kMaxSavedTraceBytes
  std::ostream trace_;
};

}  // namespace smcbip::smc
