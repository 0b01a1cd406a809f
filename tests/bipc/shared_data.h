// Where the tests find the shared real inputs (reference conformance models, ESROCOS design).
#pragma once

#include <cstdlib>
#include <filesystem>

namespace smcbip::bipc::test {

/// `SMCBIP_SHARED_DATA` when set, else `../shared/data` beside the source tree; tests that need
/// it skip with a one-line reason when it is absent (a user's clone does not have it).
inline std::filesystem::path shared_data_dir() {
  if (const char* env = std::getenv("SMCBIP_SHARED_DATA")) return env;
  return std::filesystem::path(SMCBIP_SOURCE_DIR) / ".." / "shared" / "data";
}

}  // namespace smcbip::bipc::test
