// ST23 file management on host files: the bundled mission with its repository root moved to a
// fresh temporary folder. Expected reports follow ECSS-E-ST-70-41C 6.1 (a refused start is
// [1,4], a failed execution [1,8]) and 6.23; the files are checked on the host directly.
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "services_test_support.h"

namespace smcbip::pus::services::testing {
namespace {

namespace fs = std::filesystem;

FixedBytes<kMaxFileString> text(std::string_view s) {
  FixedBytes<kMaxFileString> out;
  for (char c : s) out.push_back(static_cast<std::uint8_t>(c));
  return out;
}

FileRequest request(std::string_view repository, std::string_view file,
                    std::uint64_t max_size = 0) {
  FileRequest f;
  f.repository = text(repository);
  f.file = text(file);
  f.max_size = max_size;
  return f;
}

class PusServicesFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("pus_files_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
             "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "logs");
    fs::create_directories(root_ / "copies");
    mission_ = bundled_mission();
    mission_.file_repository = root_.string();
    app_ = std::make_unique<Application>(mission_, Config{}, 0);
  }
  void TearDown() override { fs::remove_all(root_); }

  std::vector<Telemetry> send(std::uint8_t subtype, const FileRequest& f) {
    app_->receive(tc_bytes(23, subtype, f, sequence_++), 10);
    return drain(app_->tm());
  }

  fs::path root_;
  mission::Mission mission_;
  std::unique_ptr<Application> app_;
  std::uint16_t sequence_ = 0;
};

TEST_F(PusServicesFiles, CreateReportCopyDelete) {
  EXPECT_EQ(kinds(send(1, request("logs", "a.bin", 100))), (Kinds{{1, 1}, {1, 3}, {1, 7}}));
  EXPECT_EQ(fs::file_size(root_ / "logs" / "a.bin"), 100U);

  const auto report = send(3, request("logs", "a.bin"));
  EXPECT_EQ(kinds(report), (Kinds{{1, 1}, {1, 3}, {23, 4}, {1, 7}}));
  const auto attributes = only(report, 23, 4);
  ASSERT_EQ(attributes.size(), 1U);
  EXPECT_EQ(attributes[0].header.destination_id, 7);  // the TC's source
  EXPECT_EQ(std::get<FileRequest>(attributes[0].data), request("logs", "a.bin", 100));

  std::ofstream(root_ / "logs" / "b.txt") << "hello";
  FileRequest copy = request("logs", "b.txt");
  copy.operation_id = 3;
  copy.target_repository = text("copies");
  copy.target_file = text("b.txt");
  EXPECT_EQ(kinds(send(14, copy)), (Kinds{{1, 1}, {1, 3}, {1, 7}}));
  std::ifstream copied(root_ / "copies" / "b.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(copied), {}), "hello");

  EXPECT_EQ(kinds(send(2, request("logs", "a.bin"))), (Kinds{{1, 1}, {1, 3}, {1, 7}}));
  EXPECT_FALSE(fs::exists(root_ / "logs" / "a.bin"));
}

TEST_F(PusServicesFiles, TheHostsRefusalsFailTheCompletionWithErrno) {
  // Deleting what is not there, creating what is, copying onto an existing file, a missing
  // repository: [1,8] code 9 (FileRefused) with the errno.
  auto failed = only(send(2, request("logs", "none")), 1, 8);
  ASSERT_EQ(failed.size(), 1U);
  EXPECT_EQ(failure_of(failed[0]), std::make_pair(std::uint64_t{9}, std::uint32_t{ENOENT}));
  send(1, request("", "top", 1));
  failed = only(send(1, request("", "top", 1)), 1, 8);
  ASSERT_EQ(failed.size(), 1U);
  EXPECT_EQ(failure_of(failed[0]), std::make_pair(std::uint64_t{9}, std::uint32_t{EEXIST}));
  FileRequest copy = request("", "top");
  copy.target_file = text("top");
  failed = only(send(14, copy), 1, 8);
  ASSERT_EQ(failed.size(), 1U);
  EXPECT_EQ(failure_of(failed[0]), std::make_pair(std::uint64_t{9}, std::uint32_t{EEXIST}));
  failed = only(send(1, request("nowhere", "x", 1)), 1, 8);
  ASSERT_EQ(failed.size(), 1U);
  EXPECT_EQ(failure_of(failed[0]), std::make_pair(std::uint64_t{9}, std::uint32_t{ENOENT}));
  // A repository is not a file.
  failed = only(send(2, request("", "logs")), 1, 8);
  ASSERT_EQ(failed.size(), 1U);
  EXPECT_EQ(failure_of(failed[0]), std::make_pair(std::uint64_t{9}, std::uint32_t{EISDIR}));
}

TEST_F(PusServicesFiles, PathsLeavingTheRootAreRefusedAtStart) {
  // [1,4] code 5 (InvalidArgument), datum the field: 1 repository, 2 file, 3 and 4 the target's.
  const auto refused = [&](std::uint8_t subtype, const FileRequest& f) {
    const auto failed = only(send(subtype, f), 1, 4);
    EXPECT_EQ(failed.size(), 1U);
    return failed.empty() ? std::make_pair(std::uint64_t{0}, std::uint32_t{0})
                          : failure_of(failed[0]);
  };
  EXPECT_EQ(refused(3, request("..", "mission.json")), std::make_pair(std::uint64_t{5}, 1U));
  EXPECT_EQ(refused(3, request("logs/../..", "x")), std::make_pair(std::uint64_t{5}, 1U));
  EXPECT_EQ(refused(3, request("/etc", "passwd")), std::make_pair(std::uint64_t{5}, 1U));
  EXPECT_EQ(refused(3, request("logs//x", "y")), std::make_pair(std::uint64_t{5}, 1U));
  EXPECT_EQ(refused(2, request("logs", "..")), std::make_pair(std::uint64_t{5}, 2U));
  EXPECT_EQ(refused(2, request("", "../x")), std::make_pair(std::uint64_t{5}, 2U));
  EXPECT_EQ(refused(2, request("", "")), std::make_pair(std::uint64_t{5}, 2U));
  EXPECT_EQ(refused(2, request("", std::string_view("a\0b", 3))),
            std::make_pair(std::uint64_t{5}, 2U));
  FileRequest copy = request("logs", "b");
  copy.target_repository = text("/tmp");
  copy.target_file = text("b");
  EXPECT_EQ(refused(14, copy), std::make_pair(std::uint64_t{5}, 3U));
  copy.target_repository = text("copies");
  copy.target_file = text("../b");
  EXPECT_EQ(refused(14, copy), std::make_pair(std::uint64_t{5}, 4U));
  // Over the size [23,1] may reserve: the datum is the size.
  EXPECT_EQ(refused(1, request("logs", "big", kMaxCreatedFileSize + 1)),
            std::make_pair(std::uint64_t{5}, static_cast<std::uint32_t>(kMaxCreatedFileSize + 1)));
  EXPECT_FALSE(fs::exists(root_.parent_path() / "x"));
}

TEST(PusServicesFilesOff, WithoutARepositoryST23IsNotProvided) {
  auto app = application();
  app->receive(tc_bytes(23, 3, request("", "x")), 0);
  const auto failed = only(drain(app->tm()), 1, 4);
  ASSERT_EQ(failed.size(), 1U);
  EXPECT_EQ(failure_of(failed[0]), std::make_pair(std::uint64_t{3}, std::uint32_t{23}));
}

}  // namespace
}  // namespace smcbip::pus::services::testing
