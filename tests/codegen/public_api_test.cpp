// Generated code compiles against the engines' public API alone, and the plugin ABI number is
// the hash of that API.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bipc/ir/detail/sha256.h"
#include "engines/engines.h"
#include "generated_models.h"

namespace smcbip::tests {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The `#include "..."` lines of a file.
std::vector<std::string> quoted_includes(const std::string& text) {
  std::vector<std::string> found;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("#include \"", 0) == 0)
      found.push_back(line.substr(10, line.find('"', 10) - 10));
  }
  return found;
}

// bipc gen's files of every model of the suite (model_code.*, model.h, model_data.cpp,
// model_externs.cpp) name no header of the engines outside engines/api/.
TEST(GeneratedCodeIncludes, OnlyThePublicApi) {
  std::size_t engines_includes = 0;
  for (const GeneratedModel& generated : generated_models()) {
    const fs::path folder = fs::path(SMCBIP_CODEGEN_GENERATED_DIR) / generated.name;
    ASSERT_TRUE(fs::is_directory(folder)) << folder;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
      if (!entry.is_regular_file()) continue;
      for (const std::string& header : quoted_includes(read_file(entry.path()))) {
        if (header.rfind("engines/", 0) != 0) continue;
        ++engines_includes;
        EXPECT_EQ(header.rfind("engines/api/", 0), 0u) << entry.path() << " includes " << header;
      }
    }
  }
  EXPECT_GT(engines_includes, 0u);  // the files were read
}

// The number is SHA-256 over the API's headers (sorted by path, each as its name, a newline and
// its text) and then bipc/ir/ir.h, its first 8 hex digits: recomputed here from the source tree,
// so a header edited without the build configured again fails this.
TEST(PluginAbi, IsTheHashOfTheApiHeaders) {
  const fs::path source = SMCBIP_SOURCE_DIR;
  std::vector<fs::path> headers;
  for (const fs::directory_entry& entry : fs::directory_iterator(source / "engines/api")) {
    if (entry.path().extension() == ".h") headers.push_back(entry.path());
  }
  std::sort(headers.begin(), headers.end(),
            [](const fs::path& a, const fs::path& b) { return a.string() < b.string(); });
  headers.push_back(source / "bipc/ir/ir.h");
  bipc::ir::detail::Sha256 digest;
  for (const fs::path& header : headers) {
    digest.update(header.filename().string() + "\n" + read_file(header));
  }
  const std::uint32_t expected =
      static_cast<std::uint32_t>(std::stoul(digest.hex_digest().substr(0, 8), nullptr, 16));
  EXPECT_EQ(engines::kPluginAbi, expected);
}

}  // namespace
}  // namespace smcbip::tests
