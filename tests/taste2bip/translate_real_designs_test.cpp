// Every real TASTE design of ../shared/data translates to BIP that the front end accepts, or is
// refused with located errors for a construct the translation leaves out (the README lists them).
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "engines/engines.h"
#include "taste2bip/translate/package.h"
#include "taste2bip/translate/read_design.h"
#include "tests/engines/temp_model.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip {
namespace {

namespace fs = std::filesystem;

/// The designs refused, by interface view (relative to the data folder), with what the first
/// error says. Every other design must translate.
const std::map<std::string, std::string> kRefused = {
    {"taste/esa-spacecreator/iv_remote_control/interfaceview.xml",
     "delegates to none of its functions"},
};

std::vector<fs::path> interface_views(const fs::path& data) {
  std::vector<fs::path> out;
  for (const auto& entry : fs::recursive_directory_iterator(data)) {
    const std::string name = entry.path().filename().string();
    if (name == "InterfaceView.aadl" || name == "interfaceview.xml") out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// "" when the design translates to BIP the front end accepts; else its first diagnostic.
std::string translate_file(const fs::path& view, bool& located) {
  bipc::SourceFiles files;
  bipc::Diagnostics diags;
  std::vector<std::string> notes;
  DesignFiles paths;
  paths.interface_view = view.string();
  std::optional<Packages> packages;
  if (auto design = read_design(paths, files, diags, notes)) {
    packages = translate(*design, {}, diags);
  }
  if (packages) {
    const std::string problems = bipc_diagnostics(packages->nominal, "taste");
    EXPECT_EQ(problems, "") << view;
    return problems;
  }
  diags.sort_by_location();
  located = !diags.all().empty() && diags.all().front().location.line > 0;
  return diags.format(files);
}

TEST(TranslateRealDesigns, EachTranslatesOrIsRefusedAtALocatedConstruct) {
  const fs::path data = test::shared_data_dir();
  if (!fs::exists(data / "taste")) GTEST_SKIP() << "no ../shared/data/taste in this clone";
  std::size_t translated = 0, refused = 0;
  for (const fs::path& view : interface_views(data)) {
    const std::string key = fs::relative(view, data).generic_string();
    bool located = false;
    const std::string problems = translate_file(view, located);
    const auto expected = kRefused.find(key);
    std::cout << (problems.empty() ? "translated " : "refused    ") << key << "\n";
    if (expected == kRefused.end()) {
      EXPECT_EQ(problems, "") << key;
      translated += problems.empty();
      continue;
    }
    ++refused;
    EXPECT_TRUE(located) << key << ": " << problems;
    EXPECT_NE(problems.find(expected->second), std::string::npos) << key << ": " << problems;
  }
  EXPECT_EQ(refused, kRefused.size());
  EXPECT_GE(translated, 25u);
}

TEST(TranslateRealDesigns, TheWatchdogWithDrawnExecutionTimesNeverStopsTime) {
  // Its Watchdog serves a cyclic and a sporadic interface: a call that comes while the other one
  // runs (its execution time drawn in the WCET bounds) must wait, not stop time.
  const fs::path view =
      test::shared_data_dir() / "esrocos-mc_watchdog" / "TasteModel" / "InterfaceView.aadl";
  if (!fs::exists(view)) GTEST_SKIP() << "no ../shared/data/esrocos-mc_watchdog in this clone";
  bipc::SourceFiles files;
  bipc::Diagnostics diags;
  std::vector<std::string> notes;
  DesignFiles paths;
  paths.interface_view = view.string();
  auto design = read_design(paths, files, diags, notes);
  ASSERT_TRUE(design) << diags.format(files);
  PackageOptions options;
  options.wcet = Wcet::Uniform;
  const auto packages = translate(*design, options, diags);
  ASSERT_TRUE(packages) << diags.format(files);
  const auto system = tests::load_model_text(packages->nominal, "Syst()");
  ASSERT_TRUE(system);
  engines::SimulateOptions run;
  run.seed = 1;
  run.limit = 3000;  // some 5 s of the scenario, past the first time the two calls met
  engines::Simulator simulator(*system, run, engines::Externs::with_builtins());
  for (std::uint64_t i = 0; i < 5; ++i) {
    std::ostringstream trace, output;
    const engines::RunResult r = simulator.run(i, engines::RunStreams{trace, output});
    EXPECT_EQ(r.code, engines::kRunOk) << r.message;
    EXPECT_EQ(r.end, engines::RunEnd::Limit) << "run " << i;
  }
}

}  // namespace
}  // namespace smcbip::taste2bip
