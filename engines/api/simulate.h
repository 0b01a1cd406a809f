// The engines: run a checked BIP system (its IR) with the reference, optimised or multithread
// scheduler, untimed, in simulated or real time, or stochastically, and report the run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "bipc/exit_codes.h"
#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/api/run_observer.h"

namespace smcbip::engines {

enum class EngineKind : std::uint8_t { Reference, Optimised, Multithread };
enum class TraceFormat : std::uint8_t { Text, Jsonl };

/// Run codes of the reference engine (`smcbip simulate` exits with them), plus sysexits codes
/// for the tool's own usage and input errors, so that the two never collide.
enum RunCode : int {
  kRunOk = 0,  // normal end: deadlock, time-lock, limit
  kNonDeterministicNet = 1,
  kNonOneSafeNet = 2,
  kCycleInPriorities = 3,
  kCycleInAtomPriorities = 4,
  kInvariantViolation = 5,
  kUnexpectedEvent = 6,
  kTimeSafetyViolation = 7,
  kUsageError = exit_codes::kRunUsageError,
  kInputError = exit_codes::kRunInputError,
  kInternalError = exit_codes::kRunInternalError,
};

/// Options of one simulation, as `smcbip simulate` takes them.
struct SimulateOptions {
  EngineKind engine = EngineKind::Reference;
  unsigned threads = 0;                  // multithread engine; 0: all cores
  std::size_t parallel_min_work = 1000;  // multithread engine: see RuntimeOptions
  std::optional<std::uint64_t> seed;     // none: drawn from the platform's entropy
  std::uint64_t run_index = 0;           // with the seed, selects the run's random stream
  std::optional<std::uint64_t> limit;    // stop after this many steps
  bool real_time = false;
  bool asap = false;
  bool first_enabled = false;
  bool relaxed = false;  // real time: report time-safety violations without stopping
  bool disable_maximal_progress = false;
  bool interactive = false;
  std::string replay;  // a JSON-lines trace to follow (replay.h), or empty
  bool silent = false;
  bool explore = false;
  /// --explore keeps every state it finds: at most this many (0.7 GB for the 10 atoms of
  /// models/families/rendezvous_10.bip; larger states take more), then it stops.
  std::uint64_t max_explored_states = 2'000'000;
  TraceFormat trace = TraceFormat::Text;
  /// The race of planned dates (BIP.md): none decides from the model (on when it has a
  /// @stochastic port), true forces it on timed models without one.
  std::optional<bool> stochastic;
  /// Stochastic mode: mean delay of an item whose window has no right end (exponential).
  TimeValue unbounded_mean = 1'000'000;  // 1 ms
  /// End a run with RunEnd::Absorbing in a state it can no longer leave: every item enabled
  /// there keeps the places and data as they are (PRISM's simulator stops its paths there).
  /// Only on models whose guards and actions read no clock and call no extern function, and
  /// that have no extern port: there the places and data alone decide what is enabled.
  bool stop_absorbing = false;
  /// stop_absorbing: runs look for absorbing states once they have made this many steps (0:
  /// from the start), and from the start once a run of the simulator has ended in one. Looking
  /// costs a little on every step, so runs that mostly end by a bound of their own look only
  /// when they last, or when the model has shown it has such states.
  std::uint64_t absorbing_after = 0;
};

/// The result of a run: its code (RunCode), how it ended, and the number of steps executed.
struct RunResult {
  int code = kRunOk;
  RunEnd end = RunEnd::Deadlock;
  std::uint64_t steps = 0;
  std::string message;  // the error, when code is not kRunOk
  std::string where;    // the error's `file:line:column` in the model, when known
};

/// `where: message`, or the message alone when where is empty: how observers and traces see a
/// run's error.
inline std::string located_message(const std::string& where, const std::string& message) {
  return where.empty() ? message : where + ": " + message;
}

/// Where a run writes and reads: the trace, the model's own output (printf), the prompt's input.
struct RunStreams {
  std::ostream& trace;
  std::ostream& model;
  std::istream* input = nullptr;  // --interactive
};

/// Runs one system many times (run indices select the random streams), keeping what does not
/// change between runs. One simulator per thread.
struct ReplayScript;
namespace detail {
class Simulation;
}  // namespace detail

class Simulator {
 public:
  /// Runs the system interpreted from its IR.
  Simulator(const bipc::ir::System& system, const SimulateOptions& options, const Externs& externs);
  /// Runs a model (interpreted or compiled); it must outlive the simulator.
  Simulator(const Model& model, const SimulateOptions& options, const Externs& externs);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  /// Empty when the system can run; otherwise why not (run() then returns kInputError).
  const std::string& problem() const;
  /// Whether runs race planned dates (stochastic mode).
  bool stochastic() const;
  /// One run with the stream (seed, run_index); `observer` (optional) sees every step.
  RunResult run(std::uint64_t run_index, const RunStreams& streams,
                RunObserver* observer = nullptr);
  /// A run that follows `script` (replay.h): each step fires the interaction the trace names,
  /// and each state reached must be the recorded one; a trace that cannot be followed ends the
  /// run with kInputError, `where` the trace's `file:line`. The trace is written as the options
  /// say.
  RunResult replay(const ReplayScript& script, const RunStreams& streams);
  /// The seed in use (drawn from the platform when the options have none).
  std::uint64_t seed() const;

  struct Shared;  // what the runs share (layout, bound externs); defined in simulate.cpp

 private:
  void prepare(const Externs& externs);
  std::unique_ptr<Shared> shared_;
  /// The last run's simulation, for the next run on the same streams (declared after shared_:
  /// it gives its parts back to shared_ when destroyed).
  std::unique_ptr<detail::Simulation> kept_;
};

/// Runs `system` once (run index options.run_index) and writes its trace and the model's own
/// output to `out`. Errors of the model at run time are written as reference-engine error lines
/// and returned as codes. `input` is read by --interactive.
RunResult simulate(const bipc::ir::System& system, const SimulateOptions& options,
                   const Externs& externs, std::ostream& out, std::istream* input = nullptr);

}  // namespace smcbip::engines
