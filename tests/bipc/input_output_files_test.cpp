// Output files written whole through their links and never over FIFOs, devices or folders;
// input files read only when regular and of bounded size.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "bipc/errors.h"
#include "bipc/input_file.h"
#include "bipc/output_file.h"

namespace smcbip::bipc {
namespace {

namespace fs = std::filesystem;

class Files : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "io_files.XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string contents(const std::string& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  /// The names in the folder: a temporary left behind would show.
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {}));
  }

  fs::path dir_;
};

TEST_F(Files, WritesThroughASymbolicLinkToItsTarget) {
  std::ofstream(path("target.csv")) << "old";
  fs::create_symlink("target.csv", path("link.csv"));
  std::string error;
  ASSERT_TRUE(write_file_atomically(path("link.csv"), "new", error)) << error;
  EXPECT_TRUE(fs::is_symlink(path("link.csv")));
  EXPECT_EQ(contents(path("target.csv")), "new");
  EXPECT_EQ(entries(), 2u);
}

TEST_F(Files, WritesThroughAChainOfLinksToAFileNotYetMade) {
  fs::create_symlink("second", path("first"));
  fs::create_symlink(path("result.txt"), path("second"));
  std::string target, error;
  ASSERT_TRUE(output_target(path("first"), target, error)) << error;
  EXPECT_EQ(target, path("result.txt"));
  ASSERT_TRUE(write_file_atomically(path("first"), "text", error)) << error;
  EXPECT_EQ(contents(path("result.txt")), "text");
}

TEST_F(Files, RefusesFifosDevicesFoldersAndLinkLoops) {
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  fs::create_directory(path("folder"));
  fs::create_symlink("/dev/full", path("full"));
  fs::create_symlink("loop", path("loop"));
  std::string error;
  EXPECT_FALSE(write_file_atomically(path("fifo"), "x", error));
  EXPECT_NE(error.find("a FIFO, not a regular file"), std::string::npos) << error;
  EXPECT_FALSE(write_file_atomically(path("folder"), "x", error));
  EXPECT_NE(error.find("a folder, not a regular file"), std::string::npos) << error;
  EXPECT_FALSE(write_file_atomically(path("full"), "x", error));
  EXPECT_NE(error.find("links to '/dev/full', a device"), std::string::npos) << error;
  EXPECT_FALSE(write_file_atomically("/dev/null", "x", error));
  EXPECT_FALSE(write_file_atomically(path("loop"), "x", error));
  EXPECT_NE(error.find("too many levels of symbolic links"), std::string::npos) << error;
  struct stat info {};
  ASSERT_EQ(::stat("/dev/full", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
  EXPECT_TRUE(fs::is_fifo(path("fifo")));
  EXPECT_EQ(entries(), 4u);  // nothing written beside them
}

TEST_F(Files, ReadsRegularFilesOfBoundedSizeOnly) {
  std::ofstream(path("small.mtl")) << "P=? [ F x ]\n";
  EXPECT_EQ(read_input_file(path("small.mtl"), "the property file"), "P=? [ F x ]\n");
  std::ofstream(path("large.mtl")) << std::string(1025, ' ');
  const auto message = [](const auto& read) {
    try {
      read();
    } catch (const InputError& e) {
      return e.describe("tool");
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([&] { read_input_file(path("large.mtl"), "the file", 1024); }),
            path("large.mtl") + ": error: the file is larger than 1024 bytes");
  EXPECT_EQ(message([&] { read_input_file(dir_.string(), "the property file"); }),
            dir_.string() + ": error: the property file is a folder, not a regular file");
  EXPECT_EQ(message([] { read_input_file("/dev/zero", "the property file"); }),
            "/dev/zero: error: the property file is a device, not a regular file");
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  // Refused at once, without waiting for a writer.
  EXPECT_EQ(message([&] { read_input_file(path("fifo"), "the property file"); }),
            path("fifo") + ": error: the property file is a FIFO, not a regular file");
  EXPECT_NO_THROW(require_input_file(path("fifo"), "the trace", /*streams=*/true));
  EXPECT_THROW(require_input_file("/dev/zero", "the trace", true), InputError);
  EXPECT_NO_THROW(require_model_file(path("missing.bip")));  // the front end reports it
  EXPECT_THROW(require_model_file(dir_.string()), InputError);
}

}  // namespace
}  // namespace smcbip::bipc
