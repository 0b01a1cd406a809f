// Round trips of the IR data encoding over real models: the project's models, the golden and
// cross-engine models of the tests, and the shared BIP conformance models.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "bipc/ir/ir_data.h"
#include "bipc/ir/model_hash.h"
#include "ir_data_test_util.h"
#include "lower_test_util.h"
#include "shared_data.h"

namespace smcbip::bipc {
namespace {

namespace fs = std::filesystem;
using ir_data_test::bip_files_in;
using ir_data_test::expect_round_trip;
using ir_data_test::load_system;
using ir_data_test::source_dir;

/// The project's models, with their default roots (each has one top compound).
std::vector<fs::path> project_models() {
  std::vector<fs::path> files = bip_files_in(source_dir() / "models");
  for (const fs::path& f : bip_files_in(source_dir() / "models" / "families")) files.push_back(f);
  return files;
}

TEST(IrDataRoundTrip, ProjectModels) {
  const std::vector<fs::path> files = project_models();
  ASSERT_GE(files.size(), 8u);
  for (const fs::path& file : files) {
    std::string messages;
    const std::optional<ir::System> system = load_system(file, "", {}, &messages);
    ASSERT_TRUE(system.has_value()) << file << "\n" << messages;
    expect_round_trip(*system, file.filename().string());
  }
}

/// A golden model's header as run_golden.sh reads it: the root and -I folders of its COMMAND
/// line, when it expects exit 0 from a run on the file itself.
struct GoldenRun {
  std::string root;  // empty: the default root
  std::vector<std::string> include_dirs;
};

/// The words of a command line, with single quotes grouping words as bash does.
std::vector<std::string> shell_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool quoted = false, in_word = false;
  for (char c : line) {
    if (c == '\'') {
      quoted = !quoted;
      in_word = true;
    } else if (c == ' ' && !quoted) {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

std::optional<GoldenRun> golden_run(const fs::path& file) {
  std::ifstream in(file);
  std::string command;
  bool exits_zero = false;
  for (std::string line; std::getline(in, line) && (line.empty() || line.starts_with("//"));) {
    if (line.starts_with("// COMMAND: ")) command = line.substr(12);
    if (line == "// EXIT: 0") exits_zero = true;
  }
  const std::vector<std::string> words = shell_words(command);
  if (!exits_zero || std::find(words.begin(), words.end(), "%s") == words.end()) {
    return std::nullopt;
  }
  GoldenRun run;
  for (std::size_t i = 0; i + 1 < words.size(); ++i) {
    if (words[i] == "--root") {
      // As the tools read it: a root without parentheses is its constructor without arguments.
      run.root = words[i + 1];
      if (run.root.find('(') == std::string::npos) run.root += "()";
    }
    if (words[i] == "-I") {
      std::string dir = words[i + 1];
      if (dir.starts_with("%d")) dir = file.parent_path().string() + dir.substr(2);
      run.include_dirs.push_back(dir);
    }
  }
  return run;
}

TEST(IrDataRoundTrip, GoldenAndCrossEngineModels) {
  std::size_t checked = 0;
  for (const char* folder : {"tests/bipc/golden/valid", "tests/bipc/golden/tools"}) {
    for (const fs::path& file : bip_files_in(source_dir() / folder)) {
      const std::optional<GoldenRun> run = golden_run(file);
      if (!run) continue;
      std::string messages;
      const std::optional<ir::System> system =
          load_system(file, run->root, run->include_dirs, &messages);
      ASSERT_TRUE(system.has_value()) << file << "\n" << messages;
      expect_round_trip(*system, file.filename().string());
      ++checked;
    }
  }
  // The cross-engine regressions of tests/engines all instantiate Top().
  for (const fs::path& file : bip_files_in(source_dir() / "tests/engines/cross_engine")) {
    std::string messages;
    const std::optional<ir::System> system = load_system(file, "Top()", {}, &messages);
    ASSERT_TRUE(system.has_value()) << file << "\n" << messages;
    expect_round_trip(*system, file.filename().string());
    ++checked;
  }
  EXPECT_GE(checked, 15u);  // 12 valid, 3 tool models that run, 2 cross-engine models
}

/// One entry of conformance.sh's root table: a model below bip-conformance and its root.
struct ConformanceRoot {
  std::string key;  // e.g. running/clock_speed
  std::string root;
};

/// The roots conformance.sh uses, read from its `declare -A roots=(` table, whose lines are
/// `  [running/clock_speed]='Compound()'` (tests/engines' generated conformance reads the same
/// table).
std::vector<ConformanceRoot> conformance_roots() {
  std::ifstream in(source_dir() / "tests/bipc/conformance.sh");
  std::vector<ConformanceRoot> roots;
  bool in_table = false;
  for (std::string line; std::getline(in, line);) {
    if (line == "declare -A roots=(") {
      in_table = true;
    } else if (in_table && line == ")") {
      break;
    } else if (in_table) {
      const std::size_t open = line.find('['), close = line.find("]='");
      if (open == std::string::npos || close == std::string::npos || !line.ends_with('\'')) {
        ADD_FAILURE() << "unexpected line in conformance.sh's root table: " << line;
        continue;
      }
      roots.push_back({line.substr(open + 1, close - open - 1),
                       line.substr(close + 3, line.size() - close - 4)});
    }
  }
  return roots;
}

TEST(IrDataRoundTrip, ConformanceModels) {
  const fs::path conformance = test::shared_data_dir() / "bip-conformance";
  if (!fs::is_directory(conformance)) {
    GTEST_SKIP() << "shared conformance data not found (set SMCBIP_SHARED_DATA)";
  }
  const std::vector<ConformanceRoot> roots = conformance_roots();
  ASSERT_GE(roots.size(), 90u) << "conformance.sh's root table not read";
  std::size_t round_trips = 0;
  for (const ConformanceRoot& r : roots) {
    const fs::path file = conformance / (r.key + ".bip");
    const std::string folder = (conformance / fs::path(r.key).parent_path()).string();
    std::string messages;
    const std::optional<ir::System> system = load_system(file, r.root, {folder}, &messages);
    if (!system) {
      // As conformance.sh: only the reference compiler's rejections, for a priority cycle.
      EXPECT_NE(messages.find("cycle"), std::string::npos) << r.key << "\n" << messages;
      continue;
    }
    expect_round_trip(*system, r.key + " " + r.root);
    ++round_trips;
  }
  RecordProperty("round_trips", std::to_string(round_trips));
  // conformance.sh expects three rejections; all the others check and must round-trip.
  EXPECT_GE(round_trips, roots.size() - 3);
}

// Constant folding can overflow to infinity: such a model must round-trip as any other.
TEST(IrDataRoundTrip, FoldedInfinity) {
  auto lowered = lower_test::lower_ok(
      "package fin\n"
      "  const data float BIG = 1e308 * 10.0\n"
      "  port type P()\n"
      "  atom type A(float g)\n"
      "    data float x = BIG\n"
      "    export port P p()\n"
      "    place S\n"
      "    initial to S\n"
      "    on p from S to S provided (x > -BIG)\n"
      "  end\n"
      "  compound type Top()\n"
      "    component A a(BIG)\n"
      "  end\n"
      "end\n",
      "Top()");
  ASSERT_TRUE(lowered->system);
  const nlohmann::json data = ir::to_data(*lowered->system);
  EXPECT_EQ(data["atoms"][0]["params"][0]["f"], "f64:7ff0000000000000");
  EXPECT_EQ(data["atom_types"][0]["data"][0]["initial_value"]["instrs"][0][5],
            "f64:7ff0000000000000");
  expect_round_trip(*lowered->system, "folded infinity");
}

TEST(IrDataBytes, SameModelGivesSameBytesAndHash) {
  for (const fs::path& file : project_models()) {
    SCOPED_TRACE(file.filename().string());
    const std::optional<ir::System> first = load_system(file, "", {});
    const std::optional<ir::System> second = load_system(file, "", {});
    ASSERT_TRUE(first && second);
    const std::vector<std::uint8_t> bytes = ir::to_bytes(*first);
    EXPECT_TRUE(ir::to_bytes(*first) == bytes) << "two encodings of one System differ";
    EXPECT_TRUE(ir::to_bytes(*second) == bytes) << "two checks of one model encode differently";
    EXPECT_EQ(ir::to_data(*first).dump(), ir::to_data(*second).dump());
    EXPECT_EQ(ir::model_hash(*first, {}), ir::model_hash(*second, {}));
  }
}

}  // namespace
}  // namespace smcbip::bipc
