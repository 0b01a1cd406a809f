// Every SDL-PR file of the shared TASTE designs (ESROCOS, OpenGEODE's test suite, kazoo, SAMV71)
// reads without diagnostics.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "taste2bip/sdl/sdl_reader.h"

namespace smcbip::taste2bip::sdl {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(SMCBIP_SOURCE_DIR) / ".." / "shared" / "data";

std::vector<fs::path> pr_files() {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(kData, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file() && it->path().extension() == ".pr") files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SdlRealFiles, EveryPrFileReadsWithoutErrors) {
  if (!fs::is_directory(kData)) GTEST_SKIP() << "no shared TASTE data beside the source tree";
  const std::vector<fs::path> files = pr_files();
  EXPECT_EQ(files.size(), 57u);
  for (const fs::path& path : files) {
    bipc::SourceFiles sources;
    const std::uint32_t file = sources.add(path.string());
    bipc::Diagnostics diags;
    const SdlFile sdl = read_sdl(slurp(path), file, diags);
    EXPECT_TRUE(diags.all().empty()) << diags.format(sources);
    EXPECT_FALSE(sdl.systems.empty() && sdl.processes.empty()) << path << " declares nothing";
  }
}

}  // namespace
}  // namespace smcbip::taste2bip::sdl
