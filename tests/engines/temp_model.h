// BIP models written by tests into a temporary folder and loaded through the front end.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>

#include "bipc/bipc.h"

namespace smcbip::tests {

/// A temporary folder, removed with everything in it when the object goes.
class TempDir {
 public:
  TempDir() {
    path_ = std::filesystem::temp_directory_path() /
            ("smcbip_test_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream(file) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

/// The system of `file` with root `root`; on front-end errors a test failure listing them.
inline std::optional<bipc::ir::System> load_model(const std::filesystem::path& file,
                                                  const std::string& root) {
  bipc::FrontendResult result = bipc::run_frontend({file.string(), {}, root}, true);
  if (!result.system) {
    ADD_FAILURE() << result.diags.format(result.model.files);
    return std::nullopt;
  }
  return std::move(*result.system);
}

/// As load_model, for model text written to a temporary file first.
inline std::optional<bipc::ir::System> load_model_text(const std::string& text,
                                                       const std::string& root) {
  const TempDir dir;
  return load_model(dir.write("model.bip", text), root);
}

}  // namespace smcbip::tests
