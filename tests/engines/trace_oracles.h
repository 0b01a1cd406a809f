// Oracles over reference-engine traces (grep-like checks, state headers, listings), and the
// harness that runs a BIP conformance model on one engine to get such a trace.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/engines.h"
#include "tests/engines/generated_conformance.h"

namespace smcbip::tests {

// ---------------------------------------------------------------------------------------------
// Trace oracles. Patterns are POSIX basic regular expressions searched per line, unanchored, as
// `grep` without `-E` does (`.*` any string; `(`, `)`, `+`, `|` literal), following the notation
// of bip-conformance/EXPECTED.md section 1.

using Lines = std::vector<std::string>;

/// The lines of `text`, without their line terminators; a final newline adds no empty line.
Lines split_lines(std::string_view text);

/// True when some line matches the basic regular expression `pattern`.
bool has(const Lines& lines, const std::string& pattern);
/// The number of lines that match `pattern`.
std::size_t count(const Lines& lines, const std::string& pattern);
/// True when no line matches `pattern`.
bool lacks(const Lines& lines, const std::string& pattern);
/// True when one of the last `k` lines matches `pattern`.
bool tail_has(const Lines& lines, std::size_t k, const std::string& pattern);

/// One state header `[BIP ENGINE]: state #<state> and global time <time>: <summary>`.
struct StateHeader {
  std::uint64_t state = 0;
  std::string time;      // as printed, e.g. `0`, `1s500ms`
  std::string summary;   // e.g. `1 interaction:`, `deadlock!`, `time-lock at 5s!`
  std::size_t line = 0;  // index of the header in the trace
};

/// Every state header of the trace, in trace order. Only lines that *start* with the header
/// form count, so the time-safety error line (`[BIP ENGINE]: ERROR: [BIP ENGINE]: state #...`)
/// is not a header.
std::vector<StateHeader> state_headers(const Lines& lines);
/// The first header of state `n` itself (`#1` never matches `#10`), or nullopt.
std::optional<StateHeader> find_state_header(const Lines& lines, std::uint64_t n);
/// The exact summary text of the header of state `n` (the intended meaning of EXPECTED.md's
/// `S(n)`), or `<no state #n>` when the trace has none (no summary starts with `<`). A string
/// rather than an optional, so that a failed comparison prints both texts.
std::string state_header(const Lines& lines, std::uint64_t n);
/// The printed global time of the header of state `n`, or `<no state #n>`.
std::string state_time(const Lines& lines, std::uint64_t n);
/// The summary of the last state header, or `<no state header>`.
std::string last_state_header(const Lines& lines);

/// The listing lines (`[BIP ENGINE]:   [<i>] ...`) that follow the header of state `n`.
Lines listing(const Lines& lines, std::uint64_t n);
/// The `-> choose` lines, in trace order.
Lines choose_lines(const Lines& lines);

/// The `--explore` summary line: `found <S> reachable states, <D> deadlocks, <L> timelocks,
/// and <E> errors in <X> states` (each noun singular when its count is 1).
struct ExplorationSummary {
  std::uint64_t states = 0;
  std::uint64_t deadlocks = 0;
  std::uint64_t timelocks = 0;
  std::uint64_t errors = 0;
  std::uint64_t error_states = 0;
};
/// The first exploration summary of the trace, or nullopt.
std::optional<ExplorationSummary> exploration_summary(const Lines& lines);

/// Empty when `actual == expected`, else a one-paragraph description of the first difference.
std::string describe_difference(const Lines& actual, const Lines& expected);

/// A basic regular expression for the error line of run code `code` (1..7), after the messages
/// of EXPECTED.md section 2.5 (without the original's "Peri net" typo).
std::string error_line_pattern(int code);

// ---------------------------------------------------------------------------------------------
// Running conformance models.

/// The engine variants of the typed suites: the engine, and whether the model runs as the C++
/// that bipc gen generated (compiled into the tests) instead of interpreted.
template <engines::EngineKind Kind, bool Generated>
struct Variant {
  static constexpr engines::EngineKind kind = Kind;
  static constexpr bool generated = Generated;
};
using Reference = Variant<engines::EngineKind::Reference, false>;
using Optimised = Variant<engines::EngineKind::Optimised, false>;
using Multithread = Variant<engines::EngineKind::Multithread, false>;
using GeneratedReference = Variant<engines::EngineKind::Reference, true>;
using GeneratedOptimised = Variant<engines::EngineKind::Optimised, true>;
using GeneratedMultithread = Variant<engines::EngineKind::Multithread, true>;
using AllEngines = ::testing::Types<Reference, Optimised, Multithread>;
/// The conformance suites' variants: every engine on the interpreted and the generated model.
using AllModels = ::testing::Types<Reference, Optimised, Multithread, GeneratedReference,
                                   GeneratedOptimised, GeneratedMultithread>;

/// The engine's name in test instance names.
inline std::string engine_label(engines::EngineKind engine) {
  switch (engine) {
    case engines::EngineKind::Reference:
      return "Reference";
    case engines::EngineKind::Optimised:
      return "Optimised";
    case engines::EngineKind::Multithread:
      return "Multithread";
  }
  return "Unknown";
}

/// Names the typed instances after the engine (`Conformance/Reference.R03_clock_speed`).
struct EngineNames {
  template <class Engine>
  static std::string GetName(int /*index*/) {
    return (Engine::generated ? "Generated" : "") + engine_label(Engine::kind);
  }
};

/// `bip-conformance` inside the shared data folder (see tests/bipc/shared_data.h).
std::filesystem::path conformance_dir();

/// Seeds 1..kSeedCount are run for every oracle that does not depend on the wall clock: the
/// original oracles must hold for every resolution of the non-determinism.
inline constexpr std::uint64_t kSeedCount = 5;

/// One engine run: its result and its captured standard output.
struct ConformanceRun {
  engines::RunResult result;
  std::string text;
  Lines lines;
};

/// Loads `<conformance_dir>/<model>.bip` (e.g. `running/clock_speed`) and instantiates `root`
/// (e.g. `Compound()`); on front-end errors adds a test failure listing them, returns nullopt.
std::optional<bipc::ir::System> load_conformance_model(const std::string& model,
                                                       const std::string& root);

/// Runs `system` once with the builtins and the conformance externs, capturing the trace.
ConformanceRun run_conformance(const bipc::ir::System& system,
                               const engines::SimulateOptions& options);
/// The same with any model (e.g. a CompiledModel of `system`).
ConformanceRun run_conformance(const engines::Model& model,
                               const engines::SimulateOptions& options);

/// Adds a failure unless the run ended with `code` and printed the error line of that code.
void expect_run_error(const ConformanceRun& run, int code);

/// The typed fixture: skips when the shared data are absent, and runs models on `Engine`.
template <class Engine>
class ConformanceFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(conformance_dir())) {
      GTEST_SKIP() << "shared conformance data not found (set SMCBIP_SHARED_DATA)";
    }
    if (Engine::generated && generated_conformance_models().empty()) {
      GTEST_SKIP() << "no conformance model was generated: the shared data were absent when "
                      "the tests were built";
    }
  }

  /// Default options (verbose, simulated time) for this engine.
  static engines::SimulateOptions options() {
    engines::SimulateOptions result;
    result.engine = Engine::kind;
    return result;
  }

  /// Loads `model` with `root` and calls `check(run)` for runs with seeds 1..`seeds`; stops at
  /// the first seed whose checks failed, so one defect is reported once.
  template <class Check>
  void check_runs(const std::string& model, const std::string& root,
                  engines::SimulateOptions run_options, std::uint64_t seeds, Check check) {
    const std::optional<bipc::ir::System> system = load_conformance_model(model, root);
    if (!system) return;
    std::optional<engines::CompiledModel> compiled;
    if (Engine::generated) {
      const engines::CompiledModel::CodeFactory factory = find_generated_conformance(model, root);
      ASSERT_NE(factory, nullptr) << model << " with root " << root << " was not generated "
                                  << "(tests/engines/generate_conformance.sh)";
      compiled.emplace(*system, factory);
    }
    const engines::InterpretedModel interpreted(*system);
    const engines::Model& run_model =
        compiled ? static_cast<const engines::Model&>(*compiled) : interpreted;
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
      SCOPED_TRACE(model + " " + root + " with seed " + std::to_string(seed));
      run_options.seed = seed;
      check(run_conformance(run_model, run_options));
      if (::testing::Test::HasFailure()) return;
    }
  }
  /// An oracle that is a run-time error only: run with --silent, the run ends with `code` and
  /// prints its error line.
  void check_silent_error(const std::string& model, const std::string& root, int code,
                          std::uint64_t seeds = kSeedCount) {
    engines::SimulateOptions run_options = options();
    run_options.silent = true;
    check_runs(model, root, run_options, seeds,
               [code](const ConformanceRun& run) { expect_run_error(run, code); });
  }
  /// check_runs over seeds 1..kSeedCount, for oracles that do not depend on the wall clock.
  template <class Check>
  void check_runs(const std::string& model, const std::string& root,
                  const engines::SimulateOptions& run_options, Check check) {
    check_runs(model, root, run_options, kSeedCount, check);
  }
};

}  // namespace smcbip::tests
