// Loading generated plugins with dlopen.
#include "engines/api/plugin.h"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>
#include <vector>

namespace smcbip::engines {

namespace fs = std::filesystem;

namespace {

bool is_plugin_file(const fs::directory_entry& entry) {
  const std::string name = entry.path().filename().string();
  constexpr std::string_view kSuffix = "_plugin.so";
  std::error_code ec;
  return name.size() > kSuffix.size() && name.ends_with(kSuffix) && entry.is_regular_file(ec);
}

std::string find_plugin_file(const fs::path& folder) {
  std::vector<fs::path> found;
  std::error_code ec;
  auto it =
      fs::recursive_directory_iterator(folder, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it.depth() >= 3) it.disable_recursion_pending();
    if (is_plugin_file(*it)) found.push_back(it->path());
  }
  if (ec) throw PluginError{"cannot read the folder " + folder.string() + ": " + ec.message()};
  if (found.empty()) {
    throw PluginError{"no *_plugin.so under " + folder.string() +
                      " (build the project bipc gen wrote: cmake -S DIR -B DIR/build && cmake "
                      "--build DIR/build)"};
  }
  if (found.size() > 1) {
    throw PluginError{"several plugins under " + folder.string() + ": " + found[0].string() +
                      " and " + found[1].string() + "; name one"};
  }
  return found[0].string();
}

}  // namespace

Plugin load_plugin(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw PluginError{"no such file or folder: " + path};
  Plugin plugin;
  plugin.path = fs::is_directory(path, ec) ? find_plugin_file(path) : path;
  // A relative name without a slash would be searched on the library path, not here.
  const std::string file = fs::absolute(plugin.path, ec).string();
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = ::dlerror();
    throw PluginError{"cannot load " + plugin.path + ": " + (why ? why : "unknown error")};
  }
  void* symbol = ::dlsym(handle, kPluginSymbol);
  if (symbol == nullptr) {
    throw PluginError{plugin.path + " is not a model plugin (no " + kPluginSymbol + ")"};
  }
  plugin.entry = reinterpret_cast<PluginFunction>(symbol)();
  if (plugin.entry == nullptr || plugin.entry->abi != kPluginAbi ||
      plugin.entry->layout != plugin_layout()) {
    throw PluginError{plugin.path +
                      " was built against another version of smcbip; rebuild it against this one"};
  }
  if (plugin.entry->model == nullptr || plugin.entry->register_externs == nullptr) {
    throw PluginError{plugin.path + " is not a complete model plugin"};
  }
  return plugin;
}

}  // namespace smcbip::engines
