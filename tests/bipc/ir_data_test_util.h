// Helpers of the IR data and model hash tests: a System with every field set, model loading,
// and the round-trip check through three independent views.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir_data_test {

/// A small System, consistent for from_data's checks, in which every field of every struct of
/// ir.h holds a value other than its default (and each optional is set), numbered by
/// number_code. Tests mutate one field of it at a time.
ir::System sample_system();

/// Loads `file` and instantiates `root` (the default root when empty); nullopt with the
/// diagnostics in `messages` when the front end rejects it.
std::optional<ir::System> load_system(const std::filesystem::path& file, const std::string& root,
                                      const std::vector<std::string>& include_dirs,
                                      std::string* messages = nullptr);

/// Checks from_data(to_data(s)) and from_bytes(to_bytes(s)) against `s` through to_data, the
/// JSON view (ir_json.h) and the outline (ir_text.h); failures name `label`.
void expect_round_trip(const ir::System& system, const std::string& label);

/// The `.bip` files directly in `dir`, sorted.
std::vector<std::filesystem::path> bip_files_in(const std::filesystem::path& dir);

/// The repository's source tree.
inline std::filesystem::path source_dir() { return SMCBIP_SOURCE_DIR; }

}  // namespace smcbip::bipc::ir_data_test
