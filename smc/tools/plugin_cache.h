// The cache of compiled models behind `smcbip check --compile`: one plugin per model hash and
// smcbip build, built by cmake from the project `bipc gen` writes, against the smcbip package
// found beside the running executable.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "bipc/ir/ir.h"
#include "bipc/ir/model_hash.h"

namespace smcbip::tools {

/// What builds a plugin: the smcbip package (the build tree or an install) beside the running
/// executable, and cmake, a build tool (ninja or make) and a C++ compiler on PATH.
struct Toolchain {
  std::string package_dir;  // holds smcbipConfig.cmake
  std::string cmake, compiler, generator, build_tool;
};

/// The toolchain, or nullopt with `why` saying what is missing.
std::optional<Toolchain> find_toolchain(std::string& why);

/// The cache's folder: $SMCBIP_CACHE_DIR, else $XDG_CACHE_HOME/smcbip, else $HOME/.cache/smcbip
/// (empty when none of them is set).
std::filesystem::path cache_folder();

/// This smcbip build: its version, plugin ABI and the GNU build ID of its executable (which
/// changes whenever it is linked again), so that no entry built for another smcbip is used.
std::string build_identity();

/// A build, when none was recorded yet, is expected to take this long.
inline constexpr double kDefaultBuildSeconds = 20;

/// The model a cache entry holds.
struct ModelToCompile {
  const bipc::ir::System* system = nullptr;
  std::string model_file, root, hash;
  bipc::ir::ExternSources extern_sources;
};

/// The entries of one cache folder for this smcbip build.
class PluginCache {
 public:
  explicit PluginCache(std::filesystem::path folder);

  const std::filesystem::path& folder() const { return folder_; }
  /// The plugin of the model `hash`, when its entry is there.
  std::optional<std::string> find(const std::string& hash) const;
  /// Removes the entry of `hash` (one that could not be loaded); false when it could not.
  bool discard(const std::string& hash);
  /// How long the last build took (kDefaultBuildSeconds before the first one).
  double expected_build_seconds() const;
  /// Builds the entry of `model` unless another process did meanwhile (builds are serialised
  /// by a lock file; each goes to a temporary folder renamed into place once complete). The
  /// plugin, or nullopt with `error` set and nothing left behind.
  std::optional<std::string> build(const ModelToCompile& model, const Toolchain& tools,
                                   std::string& error);

 private:
  std::filesystem::path entry(const std::string& hash) const;
  std::optional<std::string> build_locked(const ModelToCompile& model, const Toolchain& tools,
                                          std::string& error);

  std::filesystem::path folder_;
  std::string identity_;
};

}  // namespace smcbip::tools
