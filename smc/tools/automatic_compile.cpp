// Choosing between the interpreter and the model's compiled code for `smcbip check`.
#include "smc/tools/automatic_compile.h"

#include <cstdio>
#include <optional>

#include "smc/tools/run_time_estimate.h"

namespace smcbip::tools {

namespace {

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, seconds < 10 ? "%.1f s" : "%.0f s", seconds);
  return text;
}

constexpr const char* kInterpreted = "; running it interpreted\n";

/// The plugin of `path` when it holds the model `hash`; otherwise a warning and null.
const engines::PluginEntry* load_entry(const std::string& path, const std::string& hash,
                                       std::ostream& err) {
  try {
    const engines::Plugin plugin = engines::load_plugin(path);
    if (hash == plugin.entry->model_hash) return plugin.entry;
    err << "smcbip: warning: the cached plugin " << path << " holds another model (hash "
        << plugin.entry->model_hash << ")";
  } catch (const engines::PluginError& e) {
    err << "smcbip: warning: the cached plugin cannot be used (" << e.message << ")";
  }
  return nullptr;
}

}  // namespace

const engines::PluginEntry* compiled_model(CompileMode mode, const ModelToCompile& model,
                                           const monitors::PropertyFile& file,
                                           const smc::CheckOptions& options, bool explore,
                                           std::ostream& err) {
  if (mode == CompileMode::Never) return nullptr;
  const bool always = mode == CompileMode::Always;
  const std::filesystem::path folder = cache_folder();
  if (folder.empty()) {
    if (always) err << "smcbip: warning: no cache folder (set SMCBIP_CACHE_DIR)" << kInterpreted;
    return nullptr;
  }
  PluginCache cache(folder);
  if (const std::optional<std::string> hit = cache.find(model.hash)) {
    if (const engines::PluginEntry* entry = load_entry(*hit, model.hash, err)) {
      err << "smcbip: using the compiled model from the cache (hash " << model.hash.substr(0, 12)
          << "...)\n";
      return entry;
    }
    err << "; removed from the cache\n";
    cache.discard(model.hash);
  }
  std::string why;
  const std::optional<Toolchain> tools = find_toolchain(why);
  if (!tools) {
    if (always) err << "smcbip: warning: cannot compile the model (" << why << ")" << kInterpreted;
    return nullptr;
  }
  std::string because = "--compile always";
  if (!always) {
    const RunTimeEstimate estimate = estimate_run_time(*model.system, file, options, explore);
    const double build_seconds = cache.expected_build_seconds();
    if (estimate.seconds <= build_seconds) return nullptr;
    because = "expected " + seconds_text(estimate.seconds) + " of interpreted runs" +
              (estimate.sequential ? ", sequential tests estimated" : "") + ", build about " +
              seconds_text(build_seconds);
  }
  err << "smcbip: compiling the model (" << because << "); cached in " << folder.string() << "\n";
  std::string error;
  const std::optional<std::string> built = cache.build(model, *tools, error);
  if (!built) {
    err << "smcbip: warning: could not compile the model (" << error << ")" << kInterpreted;
    return nullptr;
  }
  const engines::PluginEntry* entry = load_entry(*built, model.hash, err);
  if (entry == nullptr) {
    err << kInterpreted;
    cache.discard(model.hash);
  }
  return entry;
}

}  // namespace smcbip::tools
