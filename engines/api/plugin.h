// Generated models as plugins: the MODULE a `bipc gen` project builds exports one entry point
// that gives its model, identity and extern functions, so smcbip runs the compiled code.
#pragma once

#include <cstdint>
#include <string>

#include "bipc/errors.h"
#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/api/plugin_abi.h"  // kPluginAbi, generated from the API headers
#include "engines/api/simulate.h"

namespace smcbip::engines {

/// A fingerprint of the layouts a plugin and its host must share (both compute it from the
/// headers they were built with), to refuse a plugin built against other headers.
constexpr std::uint64_t plugin_layout() {
  return sizeof(bipc::ir::System) | sizeof(bipc::ir::AtomType) << 12 |
         sizeof(bipc::ir::ConnectorType) << 24 | std::uint64_t{sizeof(Externs)} << 36 |
         std::uint64_t{sizeof(CallContext)} << 48;
}

/// What a generated plugin exports (through the C function named kPluginSymbol).
struct PluginEntry {
  std::uint32_t abi = kPluginAbi;
  std::uint64_t layout = plugin_layout();
  const char* model_hash = "";  // bipc/ir/model_hash.h
  const char* root = "";        // the root it was generated from
  const Model& (*model)() = nullptr;
  /// Registers the model's own extern functions (not the builtins).
  void (*register_externs)(Externs&) = nullptr;
};

inline constexpr const char* kPluginSymbol = "smcbip_model_plugin";
using PluginFunction = const PluginEntry* (*)();

/// A plugin that cannot be found or loaded, or does not match this smcbip: the user's input
/// error (what() says it is --compiled's).
struct PluginError : InputError {
  explicit PluginError(const std::string& why) : InputError("--compiled: " + why), message(why) {}
  std::string message;
};

/// A loaded plugin: it stays loaded for the life of the process.
struct Plugin {
  std::string path;
  const PluginEntry* entry = nullptr;
};

/// Loads `path`: a plugin file, or a folder (a generated project or its build folder) holding
/// exactly one `*_plugin.so` within three levels. Throws PluginError.
Plugin load_plugin(const std::string& path);

}  // namespace smcbip::engines
