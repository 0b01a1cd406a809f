// The SDL processes of real designs translated: ESROCOS's watchdog (each function's process
// with its system_structure.pr and the design's data view) and OpenGEODE's test suite, each
// process either translated and accepted by bipc, or refused with located errors.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/taste2bip/sdl_atom_design_support.h"

namespace smcbip::taste2bip::test {
namespace {

const fs::path kData = shared_data_dir();

TEST(SdlAtomRealFiles, WatchdogProcessesTranslateAndCheck) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  const fs::path model = kData / "esrocos-mc_watchdog" / "TasteModel";
  std::vector<fs::path> asn = files_with(model / "types", ".asn");
  asn.push_back(model / "DataView.asn");
  std::size_t translated = 0;
  for (const char* function : {"joystickdriver", "cmddispatcher", "logger", "blsclient"}) {
    const std::vector<ProcessResult> results = translate_folder(model / function, asn);
    ASSERT_EQ(results.size(), 1u) << function;
    EXPECT_TRUE(results[0].ok) << function << ": " << results[0].message;
    EXPECT_EQ(results[0].process, function);
    translated += results[0].ok ? 1 : 0;
  }
  EXPECT_EQ(translated, 4u);
}

TEST(SdlAtomRealFiles, OpenGeodeTestSuiteTranslatesOrIsRefusedWithLocations) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  const fs::path suite = kData / "taste" / "esa-opengeode-testsuite";
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(suite)) {
    if (entry.is_directory()) folders.push_back(entry.path());
  }
  std::sort(folders.begin(), folders.end());
  std::size_t translated = 0, refused = 0;
  for (const fs::path& folder : folders) {
    const std::vector<ProcessResult> results = translate_folder(folder, files_with(folder, ".asn"));
    for (const ProcessResult& r : results) {
      std::cout << folder.filename().string() << "/" << r.file << " " << r.process << ": "
                << (r.ok ? "translated" : r.message) << "\n";
      if (r.ok) {
        ++translated;
        continue;
      }
      ++refused;
      // A refusal names its place in a file: `file:line:column: error: ...`.
      EXPECT_NE(r.message.find(": error: "), std::string::npos) << r.message;
      EXPECT_EQ(r.message.rfind("bipc: ", 0), std::string::npos) << r.message;
    }
  }
  std::cout << translated << " processes translated, " << refused << " refused\n";
  EXPECT_GE(translated, 24u);  // what the translation achieved when this test was written
}

/// Each process of `system` with one action of one input transition removed, translated: an
/// atom or an error, never a crash or a silent failure. Returns the number of mutants.
std::size_t translate_mutants(const sdl::System& system, const std::vector<sdl::Block>& blocks,
                              const asn1::DataView& view) {
  std::size_t mutants = 0;
  for (const sdl::Block& b : blocks) {
    mutants += translate_mutants(system, b.blocks, view);
    for (const sdl::Process& p : b.processes) {
      bipc::Diagnostics diags;
      const auto signature = sdl_system_signature(system, p.name, view, diags);
      if (!signature || p.is_referenced) continue;
      for (std::size_t s = 0; s < p.body.states.size(); ++s) {
        for (std::size_t i = 0; i < p.body.states[s].inputs.size(); ++i) {
          for (std::size_t k = 0; k < p.body.states[s].inputs[i].transition.actions.size(); ++k) {
            sdl::Process mutant = p;
            auto& actions = mutant.body.states[s].inputs[i].transition.actions;
            actions.erase(actions.begin() + static_cast<std::ptrdiff_t>(k));
            bipc::Diagnostics mutant_diags;
            const auto atom = sdl_atom(*signature, mutant, {}, view, mutant_diags);
            EXPECT_TRUE(atom.has_value() || mutant_diags.has_errors()) << p.name;
            ++mutants;
          }
        }
      }
    }
  }
  return mutants;
}

TEST(SdlAtomRealFiles, MutantsTranslateOrAreRefused) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  std::size_t mutants = 0;
  for (const auto& entry : fs::directory_iterator(kData / "taste" / "esa-opengeode-testsuite")) {
    if (!entry.is_directory()) continue;
    bipc::Diagnostics diags;
    asn1::DataView view;
    for (const fs::path& a : files_with(entry.path(), ".asn")) {
      asn1::read_asn1(file_text(a), 0, view, diags);
    }
    asn1::resolve(view, diags);
    for (const fs::path& pr : files_with(entry.path(), ".pr")) {
      const sdl::SdlFile file = sdl::read_sdl(file_text(pr), 1, diags);
      for (const sdl::System& s : file.systems) mutants += translate_mutants(s, s.blocks, view);
    }
  }
  EXPECT_GE(mutants, 50u);
}

TEST(SdlAtomRealFiles, TasteDesignsWithInterfaceViews) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no ../shared/data in this clone";
  std::vector<fs::path> designs;
  for (const char* group : {"esa-kazoo", "n7space-TASTE-SAMV71-RTEMS-Tests"}) {
    for (const auto& entry : fs::directory_iterator(kData / "taste" / group)) {
      const fs::path d = entry.path();
      const bool has_view =
          fs::exists(d / "InterfaceView.aadl") || fs::exists(d / "interfaceview.xml");
      if (entry.is_directory() && has_view && !files_below(d, ".pr").empty()) designs.push_back(d);
    }
  }
  std::sort(designs.begin(), designs.end());
  std::size_t translated = 0, refused = 0;
  for (const fs::path& design : designs) {
    for (const ProcessResult& r : translate_design(design)) {
      std::cout << design.filename().string() << "/" << r.file << " " << r.process << ": "
                << (r.ok ? "translated" : r.message) << "\n";
      (r.ok ? translated : refused) += 1;
      if (!r.ok) {
        EXPECT_EQ(r.message.rfind("bipc: ", 0), std::string::npos) << r.message;
      }
    }
  }
  std::cout << translated << " functions translated, " << refused << " refused\n";
  EXPECT_GE(translated, 14u);  // what the translation achieved when this test was written
}

}  // namespace
}  // namespace smcbip::taste2bip::test
