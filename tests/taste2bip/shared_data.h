// Where the taste2bip tests find the real TASTE designs (../shared/data, absent from a user's
// clone: the tests that need them skip), and how they read a file whole.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/bipc/shared_data.h"

namespace smcbip::taste2bip::test {

using bipc::test::shared_data_dir;

/// The bytes of `path` (empty when it cannot be read).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace smcbip::taste2bip::test
