// The engines: run a checked BIP system (its IR) with the reference, optimised or multithread
// scheduler, untimed, in simulated or real time, or stochastically, and report the run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "bipc/ir/ir.h"
#include "engines/externs.h"

namespace smcbip::engines {

enum class EngineKind : std::uint8_t { Reference, Optimised, Multithread };
enum class TraceFormat : std::uint8_t { Text, Jsonl };

/// Run codes of the reference engine (`smcbip simulate` exits with them), plus sysexits codes
/// for the tool's own usage and input errors, so that the two never collide.
enum RunCode : int {
  kRunOk = 0,                  // normal end: deadlock, time-lock, limit
  kNonDeterministicNet = 1,
  kNonOneSafeNet = 2,
  kCycleInPriorities = 3,
  kCycleInAtomPriorities = 4,
  kInvariantViolation = 5,
  kUnexpectedEvent = 6,
  kTimeSafetyViolation = 7,
  kUsageError = 64,            // EX_USAGE
  kInputError = 65,            // EX_DATAERR
  kInternalError = 70,         // EX_SOFTWARE
};

/// How a run ended when it ended normally.
enum class RunEnd : std::uint8_t { Deadlock, Timelock, Limit, Stopped, Error };

/// Options of one simulation, as `smcbip simulate` takes them.
struct SimulateOptions {
  EngineKind engine = EngineKind::Reference;
  unsigned threads = 0;  // multithread engine; 0: all cores
  std::size_t parallel_min_work = 1000;  // multithread engine: see RuntimeOptions
  std::optional<std::uint64_t> seed;  // none: drawn from the platform's entropy
  std::uint64_t run_index = 0;        // with the seed, selects the run's random stream
  std::optional<std::uint64_t> limit;  // stop after this many steps
  bool real_time = false;
  bool asap = false;
  bool first_enabled = false;
  bool relaxed = false;  // real time: report time-safety violations without stopping
  bool disable_maximal_progress = false;
  bool interactive = false;
  bool silent = false;
  bool explore = false;
  TraceFormat trace = TraceFormat::Text;
};

/// The result of a run: its code (RunCode), how it ended, and the number of steps executed.
struct RunResult {
  int code = kRunOk;
  RunEnd end = RunEnd::Deadlock;
  std::uint64_t steps = 0;
  std::string message;  // the error, when code is not kRunOk
};

/// Runs `system` once and writes its trace (and the model's own output) to `out`. Errors of the
/// model at run time are written as reference-engine error lines and returned as codes.
/// `input` is read by --interactive.
RunResult simulate(const bipc::ir::System& system, const SimulateOptions& options,
                   const Externs& externs, std::ostream& out, std::istream* input = nullptr);

}  // namespace smcbip::engines
