// Every ASN.1 data view of the real TASTE designs in ../shared/data reads and resolves cleanly,
// and hostile input gives a bounded number of errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/taste2bip/asn1_test_support.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip::asn1 {
namespace {

namespace fs = std::filesystem;
using testing::Read;

const fs::path kData = test::shared_data_dir();
using test::file_text;

std::vector<fs::path> asn_files_under(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".asn") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Reads `paths` into one view, resolves it and returns the diagnostics.
std::string read_and_resolve(const std::vector<fs::path>& paths, Read& r) {
  for (const fs::path& path : paths) {
    std::uint32_t file = r.files.add(path.string());
    read_asn1(file_text(path), file, r.view, r.diags);
  }
  r.resolved();
  return r.errors();
}

TEST(Asn1RealFiles, EsrocosWatchdogDataViewWithItsTypes) {
  fs::path model = kData / "esrocos-mc_watchdog" / "TasteModel";
  if (!fs::exists(model)) GTEST_SKIP() << "no ../shared/data/esrocos-mc_watchdog in this clone";
  Read r;
  EXPECT_EQ(read_and_resolve(asn_files_under(model), r), "");
  ASSERT_EQ(r.view.modules.size(), 5u);
  // TASTE-ExtendedTypes: T-String ::= T-StringP{numT-String}, a parameterized OCTET STRING.
  auto string_type = r.view.find_type("T-String", "Base-Types");
  ASSERT_TRUE(string_type.has_value());
  const Type& t_string = r.view.type(*string_type)->type;
  EXPECT_EQ(t_string.bip, BipData::Extern);
  EXPECT_TRUE(t_string.arguments[0].resolved);
  EXPECT_EQ(t_string.arguments[0].integer, 60);
  auto int32 = r.view.find_type("T-Int32", "TASTE-Dataview");
  ASSERT_TRUE(int32.has_value());
  EXPECT_EQ(r.view.modules[int32->module].name, "TASTE-BasicTypes");
  EXPECT_EQ(r.view.type(*int32)->type.bip, BipData::Int);
  EXPECT_EQ(r.view.find_value("numBase-JointTrajectory", "Base-Types")->value, "200");
  // Base-JointTrajectory ::= Base-JointTrajectoryP{numBase-JointTrajectory}, a SEQUENCE
  // (SIZE(1..maxBase-JointTrajectory)) OF Base-JointState; numBase-JointTrajectory is 200.
  const Type* instance = r.type("Base-JointTrajectory");
  ASSERT_NE(instance, nullptr);
  const Type* generic = r.type("Base-JointTrajectoryP");
  ASSERT_NE(generic, nullptr);
  EXPECT_EQ(bound_integer(r.view, generic->size.ranges[0].upper, instance), 200);
  std::size_t types = 0;
  for (const Module& m : r.view.modules) {
    for (const TypeAssignment& a : m.types) {
      EXPECT_NE(a.type.bip, BipData::Unknown) << a.name;
      ++types;
    }
  }
  EXPECT_GT(types, 100u);
}

TEST(Asn1RealFiles, EveryTasteDataViewReadsAndResolves) {
  fs::path taste = kData / "taste";
  if (!fs::exists(taste)) GTEST_SKIP() << "no ../shared/data/taste in this clone";
  fs::path basic_types = taste / "esa-kazoo" / "taste-types.asn";
  std::size_t files = 0, types = 0;
  for (const fs::path& path : asn_files_under(taste)) {
    SCOPED_TRACE(path.string());
    std::vector<fs::path> paths{path};
    std::string text = file_text(path);
    // TASTE-BasicTypes comes with the toolchain: the folder's copy, or kazoo's.
    if (text.find("FROM TASTE-BasicTypes") != std::string::npos &&
        text.find("TASTE-BasicTypes DEFINITIONS") == std::string::npos) {
      fs::path local = path.parent_path() / "taste-types.asn";
      paths.push_back(fs::exists(local) ? local : basic_types);
    }
    Read r;
    EXPECT_EQ(read_and_resolve(paths, r), "");
    EXPECT_FALSE(r.view.modules.empty());
    for (const Module& m : r.view.modules) {
      for (const TypeAssignment& a : m.types) {
        EXPECT_NE(a.type.bip, BipData::Unknown) << a.name;
        ++types;
      }
    }
    ++files;
  }
  EXPECT_GE(files, 50u);
  EXPECT_GT(types, 200u);
}

TEST(Asn1RealFiles, DemoUnprotectedHasEveryKind) {
  fs::path path = kData / "taste" / "esa-kazoo" / "Demo_Unprotected" / "DataView.asn";
  if (!fs::exists(path)) GTEST_SKIP() << "no ../shared/data/taste in this clone";
  Read r;
  ASSERT_EQ(read_and_resolve({path, kData / "taste" / "esa-kazoo" / "taste-types.asn"}, r), "");
  EXPECT_EQ(r.type("MyInteger")->bip, BipData::Int);  // ::= T-UInt8, imported
  EXPECT_EQ(r.type("MyReal")->bip, BipData::Float);
  EXPECT_EQ(r.type("MyBool")->bip, BipData::Bool);
  EXPECT_EQ(r.type("MyEnum")->bip, BipData::Int);
  EXPECT_EQ(r.type("MySeq")->bip, BipData::Extern);
  EXPECT_EQ(r.type("MySeq")->components[2].type.bip, BipData::Int);
  EXPECT_EQ(r.type("MyChoice")->bip, BipData::Extern);
  EXPECT_EQ(r.type("MySeqOf")->size.ranges[0].upper.integer, 2);
  EXPECT_EQ(r.type("MyOctStr")->kind, TypeKind::OctetString);
  EXPECT_EQ(r.view.find_value("myVar")->value, "{ hello, world }");
}

// --- robustness ----------------------------------------------------------------------------

TEST(Asn1Robustness, DeepNestingIsCappedWithOneError) {
  std::string text = "M DEFINITIONS ::= BEGIN\nT ::= ";
  for (int i = 0; i < 100000; ++i) text += "SEQUENCE { a ";
  text += "INTEGER";
  Read r;
  r.add(text).resolved();
  EXPECT_EQ(r.diags.error_count(), 1u);
  EXPECT_NE(r.errors().find("types nested deeper than 200 levels"), std::string::npos);
}

TEST(Asn1Robustness, DeepBracesInValuesAndSequenceOfChains) {
  std::string text = "M DEFINITIONS ::= BEGIN\nv T ::= ";
  text += std::string(100000, '{') + std::string(100000, '}');
  text += "\nT ::= ";
  for (int i = 0; i < 100000; ++i) text += "SEQUENCE OF ";
  Read r;
  r.add(text).resolved();
  EXPECT_LE(r.diags.error_count(), 20u);
  EXPECT_TRUE(r.diags.has_errors());
}

TEST(Asn1Robustness, MegabyteOfNulsGivesOneError) {
  Read r;
  r.add(std::string(1 << 20, '\0')).resolved();
  EXPECT_EQ(r.errors(), "t0.asn:1:1: error: unexpected character in ASN.1 text\n");
}

TEST(Asn1Robustness, GarbageBytesGiveABoundedNumberOfErrors) {
  std::string text;
  std::uint32_t state = 12345;
  for (int i = 0; i < 200000; ++i) {
    state = state * 1103515245u + 12345u;  // a fixed linear congruential sequence
    text += static_cast<char>((state >> 16) & 0xff);
  }
  Read r;
  r.add(text).resolved();
  EXPECT_GE(r.diags.error_count(), 1u);
  EXPECT_LE(r.diags.error_count(), 21u);
}

TEST(Asn1Robustness, LongReferenceChainsAndCyclesDoNotRecurse) {
  std::string text = "M DEFINITIONS ::= BEGIN\n";
  for (int i = 0; i < 50000; ++i) {
    text += "T" + std::to_string(i) + " ::= T" + std::to_string(i + 1) + "\n";
  }
  text += "T50000 ::= T0\nEND\n";
  Read r;
  r.add(text).resolved();
  EXPECT_EQ(r.diags.error_count(), 1u);
  EXPECT_EQ(r.type("T7")->bip, BipData::Unknown);
}

TEST(Asn1Robustness, ResolutionErrorsAreBoundedPerFile) {
  std::string body;
  for (int i = 0; i < 1000; ++i) body += "T" + std::to_string(i) + " ::= Unknown\n";
  Read r;
  r.add(testing::module(body)).resolved();
  EXPECT_EQ(r.diags.error_count(), 20u);
  EXPECT_EQ(r.diags.all().back().message,
            "too many errors in this file: the others are not reported");
}

TEST(Asn1Robustness, ReaderAndResolverShareTheErrorBudget) {
  std::string body;
  for (int i = 0; i < 15; ++i) body += "S" + std::to_string(i) + " ::= SEQUENCE { a }\n";
  for (int i = 0; i < 15; ++i) body += "T" + std::to_string(i) + " ::= Unknown\n";
  Read r;
  r.add(testing::module(body)).resolved();
  EXPECT_EQ(r.diags.error_count(), 20u);
}

}  // namespace
}  // namespace smcbip::taste2bip::asn1
