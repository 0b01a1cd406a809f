// Tests of package loading (`use` resolution, search path, cycles) and of the real BIP inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "shared_data.h"

namespace smcbip::bipc {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class ParseLoader : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() / ("smcbip_parse_loader_" + std::string(info->name()) + "_" +
                                         std::to_string(std::random_device{}()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string write(const std::string& relative, const std::string& text) {
    fs::path path = root_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path.string();
  }
  std::string path(const std::string& relative) const { return (root_ / relative).string(); }

  static std::vector<std::string> names(const LoadedModel& model) {
    std::vector<std::string> result;
    for (const auto& package : model.packages) result.push_back(package->name.text());
    return result;
  }

  fs::path root_;
};

TEST_F(ParseLoader, ResolvesUsesTransitivelyDependenciesFirst) {
  std::string main = write("main.bip", "package main use a.b use c end");
  write("a/b.bip", "package a.b use c end");
  write("inc/c.bip", "package c use d.e end");
  write("inc/d.e.bip", "package d.e end");
  Diagnostics diags;
  LoadedModel model = load(main, {path("inc")}, diags);
  EXPECT_FALSE(diags.has_errors()) << diags.format(model.files);
  EXPECT_EQ(names(model), (std::vector<std::string>{"d.e", "c", "a.b", "main"}));
  ASSERT_NE(model.main, nullptr);
  EXPECT_EQ(model.main->name.text(), "main");
  EXPECT_EQ(model.main->path, main);
  ASSERT_EQ(model.main->used_packages.size(), 2u);
  EXPECT_EQ(model.main->used_packages[0]->name.text(), "a.b");
  EXPECT_EQ(model.main->used_packages[1]->name.text(), "c");
  // `c` is loaded once, though used twice.
  EXPECT_EQ(model.main->used_packages[0]->used_packages.at(0), model.main->used_packages[1]);
  EXPECT_EQ(model.files.paths.size(), 4u);
  EXPECT_EQ(model.files.paths[0], main);
  EXPECT_EQ(model.files.paths[1], path("a/b.bip"));
}

TEST_F(ParseLoader, UsingFileFolderComesBeforeSearchPath) {
  std::string main = write("m/main.bip", "package main use x end");
  write("m/x.bip", "package x end");
  write("inc/x.bip", "package x use missing end");
  Diagnostics diags;
  LoadedModel model = load(main, {path("inc")}, diags);
  EXPECT_FALSE(diags.has_errors()) << diags.format(model.files);
  EXPECT_EQ(model.packages.at(0)->path, path("m/x.bip"));
}

TEST_F(ParseLoader, MissingPackageIsReportedAtTheUse) {
  std::string main = write("main.bip", "package main\n  use x.y\nend");
  Diagnostics diags;
  LoadedModel model = load(main, {path("inc")}, diags);
  ASSERT_EQ(diags.error_count(), 1u);
  const Diagnostic& error = diags.all()[0];
  EXPECT_EQ(error.location.line, 2u);
  EXPECT_EQ(error.location.column, 7u);
  EXPECT_EQ(error.message, "cannot find package 'x.y' (searched: " + path("x/y.bip") + ", " +
                               path("x.y.bip") + ", " + path("inc/x/y.bip") + ", " +
                               path("inc/x.y.bip") + ")");
  EXPECT_EQ(model.packages.size(), 1u);
}

TEST_F(ParseLoader, CyclicUseIsAnError) {
  std::string main = write("a.bip", "package a use b end");
  write("b.bip", "package b\n  use a\nend");
  Diagnostics diags;
  LoadedModel model = load(main, {}, diags);
  ASSERT_EQ(diags.error_count(), 1u);
  const Diagnostic& error = diags.all()[0];
  EXPECT_EQ(model.files.path(error.location.file), path("b.bip"));
  EXPECT_EQ(error.location.line, 2u);
  EXPECT_NE(error.message.find("cyclic"), std::string::npos);
  EXPECT_EQ(error.message, "cyclic 'use' of package 'a' (a -> b -> a)");
  EXPECT_EQ(names(model), (std::vector<std::string>{"b", "a"}));
}

TEST_F(ParseLoader, DeclaredNameMustMatchTheUse) {
  std::string main = write("main.bip", "package main use x end");
  write("x.bip", "package y end");
  Diagnostics diags;
  LoadedModel model = load(main, {}, diags);
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(model.files.path(diags.all()[0].location.file), path("x.bip"));
  EXPECT_EQ(diags.all()[0].location.column, 9u);
  EXPECT_NE(diags.all()[0].message.find("declares package 'y'"), std::string::npos);
}

TEST_F(ParseLoader, UnreadableFile) {
  Diagnostics diags;
  LoadedModel model = load(path("nothing.bip"), {}, diags);
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.all()[0].message, "cannot open file");
  EXPECT_EQ(diags.all()[0].location.line, 1u);
  EXPECT_EQ(diags.all()[0].location.column, 1u);
  EXPECT_EQ(model.files.path(diags.all()[0].location.file), path("nothing.bip"));
  EXPECT_EQ(model.main, nullptr);
  EXPECT_TRUE(model.packages.empty());
}

TEST_F(ParseLoader, SyntaxErrorsOfUsedPackagesPointIntoTheirFile) {
  std::string main = write("main.bip", "package main use x end");
  write("x.bip", "package x\n  foo\nend");
  Diagnostics diags;
  LoadedModel model = load(main, {}, diags);
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.format(model.files).substr(0, path("x.bip").size() + 5), path("x.bip") + ":2:3:");
  EXPECT_EQ(model.packages.size(), 2u);
}

// ---------------------------------------------------------------------------------------------
// The real inputs: the reference compiler's conformance models and the ESROCOS watchdog.

fs::path shared_data() { return smcbip::bipc::test::shared_data_dir(); }

std::vector<fs::path> bip_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".bip") files.push_back(entry);
  }
  std::sort(files.begin(), files.end());
  return files;
}

void expect_all_load_cleanly(const fs::path& dir, const std::vector<std::string>& search_dirs) {
  std::vector<fs::path> files = bip_files(dir);
  EXPECT_FALSE(files.empty()) << dir;
  for (const fs::path& file : files) {
    Diagnostics diags;
    LoadedModel model = load(file.string(), search_dirs, diags);
    EXPECT_TRUE(diags.all().empty()) << diags.format(model.files);
    ASSERT_NE(model.main, nullptr) << file;
    EXPECT_EQ(model.main->name.text(), file.stem().string());
  }
}

TEST(ParseRealModels, ConformanceAndEsrocosModelsParseCleanly) {
  const fs::path data = shared_data();
  if (!fs::is_directory(data / "bip-conformance")) {
    GTEST_SKIP() << "shared BIP data not found (set SMCBIP_SHARED_DATA)";
  }
  const fs::path conformance = data / "bip-conformance";
  expect_all_load_cleanly(conformance / "running", {});
  expect_all_load_cleanly(conformance / "compile_only", {(conformance / "compile_only").string()});
  expect_all_load_cleanly(conformance / "running_multithread_extra", {});
  expect_all_load_cleanly(data / "esrocos-mc_watchdog" / "BipModel" / "sources", {});
}

}  // namespace
}  // namespace smcbip::bipc
