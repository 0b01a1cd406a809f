// Engines cross-run on the same seed (Spot's ltlcross idea): the optimised scheduler must print
// the reference engine's text trace byte for byte, on the conformance models, the scalable
// model families and random models.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "tests/engines/random_model.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

constexpr std::uint64_t kCrossSeeds = 3;
constexpr std::uint64_t kStepLimit = 300;

/// The system of `file` with root `root`, or nullopt when the front end rejects it.
std::optional<bipc::ir::System> load_quietly(const std::filesystem::path& file,
                                             const std::string& root) {
  bipc::FrontendOptions options;
  options.file = file.string();
  options.include_dirs = {file.parent_path().string()};
  options.root = root;
  bipc::FrontendResult result = bipc::run_frontend(options, true);
  if (!result.system || result.diags.has_errors()) return std::nullopt;
  return std::move(result.system);
}

/// Adds a failure naming the first differing line unless the run of `options` with `engine`
/// prints the trace of `expected`.
void expect_same_run(const ConformanceRun& expected, engines::EngineKind engine,
                     const bipc::ir::System& system, engines::SimulateOptions options) {
  options.engine = engine;
  const ConformanceRun run = run_conformance(system, options);
  EXPECT_EQ(run.result.code, expected.result.code);
  EXPECT_EQ(run.result.steps, expected.result.steps);
  EXPECT_EQ(describe_difference(run.lines, expected.lines), "");
}

/// Adds a failure naming the first differing line unless the optimised engine (and, with
/// `multithread`, the multithread one) prints the reference engine's trace for seeds
/// 1..kCrossSeeds; verbose runs in simulated time, so the traces hold every choice. The text
/// trace lists every item at every step; the JSON-lines trace shows only the chosen one, which
/// the optimised and multithread engines then find without listing the items (on untimed
/// models).
void expect_same_traces(const bipc::ir::System& system, engines::SimulateOptions options,
                        bool multithread = false) {
  using engines::EngineKind;
  options.limit = kStepLimit;
  for (std::uint64_t seed = 1; seed <= kCrossSeeds; ++seed) {
    options.seed = seed;
    for (engines::TraceFormat format : {engines::TraceFormat::Text, engines::TraceFormat::Jsonl}) {
      SCOPED_TRACE("seed " + std::to_string(seed) +
                   (format == engines::TraceFormat::Text ? ", text" : ", JSON lines"));
      options.trace = format;
      options.engine = EngineKind::Reference;
      const ConformanceRun reference = run_conformance(system, options);
      expect_same_run(reference, EngineKind::Optimised, system, options);
      if (multithread && format == engines::TraceFormat::Jsonl) {
        engines::SimulateOptions parallel = options;
        parallel.threads = 2;
        parallel.parallel_min_work = 0;  // atoms fire on the pool even when cheap
        expect_same_run(reference, EngineKind::Multithread, system, parallel);
      }
    }
    if (::testing::Test::HasFailure()) return;
  }
}

/// One row of the summary table of bip-conformance/EXPECTED.md (section 5).
struct ConformanceCase {
  std::string model;  // e.g. `running/clock_speed`
  std::string root;
  engines::SimulateOptions options;
};

/// The text between the first pair of backquotes of `cell`, or "".
std::string quoted(const std::string& cell) {
  const std::size_t open = cell.find('`');
  const std::size_t close = open == std::string::npos ? open : cell.find('`', open + 1);
  return close == std::string::npos ? "" : cell.substr(open + 1, close - open - 1);
}

/// The model cell's path (`R/x, flattened ...` names `running/x`), or "".
std::string model_path(const std::string& cell) {
  const std::string name = cell.substr(0, cell.find_first_of(" ,"));
  if (name.starts_with("R/")) return "running/" + name.substr(2);
  if (name.starts_with("M/")) return "running_multithread_extra/" + name.substr(2);
  if (name.starts_with("C/")) return "compile_only/" + name.substr(2);
  return "";
}

std::vector<std::string> table_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, '|');) {
    const std::size_t first = cell.find_first_not_of(' ');
    const std::size_t last = cell.find_last_not_of(' ');
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  return cells;
}

/// The cases of the summary table that run in simulated time. A row whose every run uses
/// `--real-time` follows the wall clock, so its trace depends on the machine's speed; the other
/// options of a row are kept, except those that only shape the output or the step limit.
std::vector<ConformanceCase> simulated_time_cases() {
  std::ifstream in(conformance_dir() / "EXPECTED.md");
  std::vector<ConformanceCase> cases;
  std::set<std::pair<std::string, std::string>> seen;
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> cells = table_cells(line);
    // | Id | Test | Model | Root | Options | Exit | Oracle |
    if (cells.size() < 8 || cells[1].size() != 3) continue;
    ConformanceCase c{model_path(cells[3]), quoted(cells[4]), {}};
    const std::string& flags = cells[5];
    const bool simulated_run =
        flags.find("--real-time") == std::string::npos || flags.find("a: ") != std::string::npos;
    if (c.model.empty() || c.root.empty() || !simulated_run) continue;
    if (flags.find("not run") != std::string::npos) continue;
    c.options.disable_maximal_progress =
        flags.find("--disable-maximal-progress") != std::string::npos;
    c.options.asap = flags.find("--asap") != std::string::npos;
    c.options.first_enabled = flags.find("--first-enabled") != std::string::npos;
    if (seen.insert({c.model, c.root + flags}).second) cases.push_back(c);
  }
  return cases;
}

/// Whether the model's own code sleeps, so that even a simulated-time run waits on the wall
/// clock (and takes seconds).
bool sleeps(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str().find("sleep(") != std::string::npos;
}

TEST(CrossEngine, ConformanceModels) {
  if (!std::filesystem::exists(conformance_dir())) {
    GTEST_SKIP() << "shared conformance data not found (set SMCBIP_SHARED_DATA)";
  }
  std::size_t run = 0;
  std::string skipped;
  for (const ConformanceCase& c : simulated_time_cases()) {
    const std::filesystem::path file = conformance_dir() / (c.model + ".bip");
    if (sleeps(file)) {
      skipped += " " + c.model + " (sleeps)";
      continue;
    }
    const std::optional<bipc::ir::System> system = load_quietly(file, c.root);
    if (!system) {
      skipped += " " + c.model + " (rejected by the front end)";
      continue;
    }
    SCOPED_TRACE(c.model + " " + c.root);
    expect_same_traces(*system, c.options);
    if (HasFailure()) return;
    ++run;
  }
  RecordProperty("skipped_models", skipped);
  // Most rows of the table run in simulated time; a parser that found none tests nothing.
  EXPECT_GE(run, 50u) << "skipped:" << skipped;
}

/// Cross-runs every `.bip` of a source folder with root `Top()`.
void expect_same_traces_in(const std::filesystem::path& dir) {
  std::size_t run = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".bip") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const std::optional<bipc::ir::System> system = load_quietly(entry.path(), "Top()");
    ASSERT_TRUE(system.has_value()) << "front end rejected " << entry.path();
    expect_same_traces(*system, {});
    if (::testing::Test::HasFailure()) return;
    ++run;
  }
  EXPECT_GT(run, 0u) << "no model in " << dir;
}

TEST(CrossEngine, ModelFamilies) {
  expect_same_traces_in(std::filesystem::path(SMCBIP_SOURCE_DIR) / "models/families");
}

// Models written against the optimised scheduler's shortcuts, each saying which one it pins.
TEST(CrossEngine, CacheRegressions) {
  expect_same_traces_in(std::filesystem::path(SMCBIP_SOURCE_DIR) / "tests/engines/cross_engine");
}

/// A scratch directory of this test, removed at the end.
class CrossEngineRandom : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("smcbip_cross_engine_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  std::filesystem::path dir_;
};

/// Shapes varied by seed so that every switch is on and off across the models; more atoms and
/// connectors than the generator's own test, so that executions leave most connectors alone.
RandomModelOptions cross_options(std::uint64_t seed) {
  RandomModelOptions options;
  options.seed = seed;
  options.atoms = 2 + static_cast<int>(seed % 11);
  options.max_places = 1 + static_cast<int>(seed % 5);
  options.max_ports = 1 + static_cast<int>(seed % 4);
  options.connectors = 1 + static_cast<int>(seed % 9);
  options.priorities = seed % 3 != 0;
  options.clocks = seed % 2 == 0;
  options.data = seed % 5 != 0;
  options.hierarchy = seed % 4 != 1;
  return options;
}

TEST_F(CrossEngineRandom, RandomModels) {
  constexpr std::uint64_t kModels = 120;
  for (std::uint64_t seed = 1; seed <= kModels; ++seed) {
    const std::string name = "cross_" + std::to_string(seed);
    const std::filesystem::path file = dir_ / (name + ".bip");
    const std::string text = random_bip_package(cross_options(seed), name);
    {
      std::ofstream out(file);
      out << text;
      ASSERT_TRUE(out.good()) << "cannot write " << file;
    }
    SCOPED_TRACE("random model " + std::to_string(seed) + ":\n" + text);
    const std::optional<bipc::ir::System> system = load_quietly(file, "Root()");
    ASSERT_TRUE(system.has_value()) << "front end rejected the random model";
    expect_same_traces(*system, {}, /*multithread=*/true);
    if (HasFailure()) return;
  }
}

}  // namespace
}  // namespace smcbip::tests
