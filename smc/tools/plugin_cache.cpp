// Building generated plugins into the cache of compiled models, and finding them there.
#include "smc/tools/plugin_cache.h"

#include <fcntl.h>
#include <link.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "bipc/codegen/code_cpp.h"
#include "bipc/codegen/generate_project.h"
#include "bipc/output_file.h"
#include "engines/api/plugin.h"

extern char** environ;

namespace smcbip::tools {

namespace fs = std::filesystem;

namespace {

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SMCBIP_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SMCBIP_SANITIZED 1
#endif

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

/// `name` as the shell would run it: a path as it is, a bare name through PATH.
std::string find_program(const std::string& name) {
  if (name.empty()) return {};
  if (name.find('/') != std::string::npos) {
    return ::access(name.c_str(), X_OK) == 0 ? name : std::string();
  }
  std::stringstream path(environment("PATH"));
  for (std::string folder; std::getline(path, folder, ':');) {
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) {
      return candidate.string();
    }
  }
  return {};
}

/// The folder of smcbipConfig.cmake: the build tree holds it above bin/, an install under
/// <prefix>/<libdir>/cmake/smcbip with bin/ beside <libdir>.
std::string find_package_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path above = exe.parent_path().parent_path();
  for (const fs::path& folder : {above, above / SMCBIP_INSTALL_LIBDIR / "cmake" / "smcbip"}) {
    if (fs::is_regular_file(folder / "smcbipConfig.cmake", ec)) return folder.string();
  }
  return {};
}

/// The hexadecimal GNU build ID of the main program, or its size and time when it has none.
std::string executable_id() {
  std::string id;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* data) {
        auto& out = *static_cast<std::string*>(data);
        for (int i = 0; i < info->dlpi_phnum && out.empty(); ++i) {
          const ElfW(Phdr)& segment = info->dlpi_phdr[i];
          if (segment.p_type != PT_NOTE) continue;
          const auto* at = reinterpret_cast<const char*>(info->dlpi_addr + segment.p_vaddr);
          const char* end = at + segment.p_memsz;
          while (at + sizeof(ElfW(Nhdr)) <= end) {
            const auto* note = reinterpret_cast<const ElfW(Nhdr)*>(at);
            const char* name = at + sizeof(ElfW(Nhdr));
            const char* desc = name + ((note->n_namesz + 3) & ~3u);
            if (note->n_type == NT_GNU_BUILD_ID && note->n_namesz == 4 &&
                std::string_view(name, 3) == "GNU") {
              static constexpr char kHex[] = "0123456789abcdef";
              for (unsigned b = 0; b < note->n_descsz; ++b) {
                const auto byte = static_cast<unsigned char>(desc[b]);
                out += kHex[byte >> 4];
                out += kHex[byte & 15];
              }
              break;
            }
            at = desc + ((note->n_descsz + 3) & ~3u);
          }
        }
        return 1;  // the first object is the main program
      },
      &id);
  if (!id.empty()) return id;
  struct stat about {};
  if (::stat("/proc/self/exe", &about) != 0) return "unknown";
  return std::to_string(about.st_size) + "-" + std::to_string(about.st_mtime);
}

/// An exclusive lock on a file of the cache, held for the object's life.
class FileLock {
 public:
  explicit FileLock(const fs::path& file)
      : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    while (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
    }
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  bool held() const { return fd_ >= 0; }

 private:
  int fd_;
};

/// Runs `argv`, its output appended to `log`; true when it exits with 0.
bool run_logged(const std::vector<std::string>& argv, const fs::path& log) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t child = 0;
  const int failed = ::posix_spawn(&child, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (failed != 0) return false;
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/// The line of `log` that says best why a step failed, for a one-line warning: a compiler's
/// or tool's "error:" line before CMake's own "CMake Error" one.
std::string first_error(const fs::path& log, const std::string& step) {
  std::ifstream in(log);
  std::string tool_error, cmake_error;
  for (std::string line; std::getline(in, line) && tool_error.empty();) {
    line.erase(0, line.find_first_not_of(" \t"));
    if (line.starts_with("CMake Error")) {
      if (cmake_error.empty()) cmake_error = line;
    } else if (line.find("error:") != std::string::npos) {
      tool_error = line;
    }
  }
  std::string why = tool_error.empty() ? cmake_error : tool_error;
  if (why.size() > 160) why = why.substr(0, 157) + "...";
  return why.empty() ? step + " failed" : step + " failed: " + why;
}

/// Writes the project `bipc gen` would write for `model` (without its executable) into `src`;
/// the project's name, or nullopt with `error` set.
std::optional<std::string> write_project(const ModelToCompile& model, const fs::path& src,
                                         std::string& error) {
  bipc::codegen::ProjectOptions project;
  project.main = false;
  project.model_file = model.model_file;
  project.root = model.root;
  project.extern_sources = model.extern_sources;
  project.smcbip_version = SMCBIP_VERSION_TEXT;
  std::vector<bipc::NamedText> files;
  try {
    for (auto& file : bipc::codegen::generate_project(*model.system, project)) {
      files.push_back({file.name, std::move(file.text)});
    }
  } catch (const bipc::codegen::ExternSourceClash& clash) {
    error = clash.message;
    return std::nullopt;
  } catch (const bipc::codegen::UntranslatableCode& untranslatable) {
    error = untranslatable.message;
    return std::nullopt;
  }
  if (!bipc::write_files_atomically(src.string(), files, error)) return std::nullopt;
  return bipc::codegen::project_name(project.code.name_space);
}

/// Configures the project in `src` into `out` (Release, against the package of `tools`) and
/// builds its plugin there, the tools' output in `log`; false with `error` set.
bool build_plugin(const Toolchain& tools, const fs::path& src, const fs::path& out,
                  const std::string& name, const fs::path& log, std::string& error) {
  if (!run_logged(
          {tools.cmake, "-S", src, "-B", out, "-G", tools.generator, "-DCMAKE_BUILD_TYPE=Release",
           "-Dsmcbip_DIR=" + tools.package_dir, "-DCMAKE_CXX_COMPILER=" + tools.compiler,
           "-DCMAKE_MAKE_PROGRAM=" + tools.build_tool},
          log)) {
    error = first_error(log, "configuring");
    return false;
  }
  const unsigned jobs = std::clamp(std::thread::hardware_concurrency(), 1u, 4u);
  if (!run_logged({tools.cmake, "--build", out, "--target", name + "_plugin", "--parallel",
                   std::to_string(jobs)},
                  log)) {
    error = first_error(log, "building");
    return false;
  }
  return true;
}

/// Removes a folder when it goes out of scope (a build that did not complete).
struct RemovedFolder {
  fs::path path;
  ~RemovedFolder() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

}  // namespace

std::optional<Toolchain> find_toolchain(std::string& why) {
#ifdef SMCBIP_SANITIZED
  why = "this smcbip is built with sanitizers, which a plugin cannot link";
  return std::nullopt;
#endif
  Toolchain tools;
  tools.package_dir = find_package_dir();
  if (tools.package_dir.empty()) {
    why = "no smcbip package (smcbipConfig.cmake) beside this executable";
    return std::nullopt;
  }
  tools.cmake = find_program("cmake");
  if (tools.cmake.empty()) {
    why = "no cmake on PATH";
    return std::nullopt;
  }
  const std::string cxx = environment("CXX");
  for (const std::string& name :
       {cxx, std::string("c++"), std::string("g++"), std::string("clang++")}) {
    tools.compiler = find_program(name);
    if (!tools.compiler.empty() || !cxx.empty()) break;  // $CXX, when set, is the one
  }
  if (tools.compiler.empty()) {
    why = cxx.empty() ? "no C++ compiler (c++, g++, clang++) on PATH" : "no compiler " + cxx;
    return std::nullopt;
  }
  tools.build_tool = find_program("ninja");
  tools.generator = "Ninja";
  if (tools.build_tool.empty()) {
    tools.build_tool = find_program("make");
    tools.generator = "Unix Makefiles";
  }
  if (tools.build_tool.empty()) {
    why = "no ninja or make on PATH";
    return std::nullopt;
  }
  return tools;
}

fs::path cache_folder() {
  if (const std::string own = environment("SMCBIP_CACHE_DIR"); !own.empty()) return own;
  if (const std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) {
    return fs::path(xdg) / "smcbip";
  }
  if (const std::string home = environment("HOME"); !home.empty()) {
    return fs::path(home) / ".cache" / "smcbip";
  }
  return {};
}

std::string build_identity() {
  return std::string(SMCBIP_VERSION_TEXT) + "-abi" + std::to_string(engines::kPluginAbi) + "-" +
         executable_id();
}

PluginCache::PluginCache(fs::path folder)
    : folder_(std::move(folder)), identity_(build_identity()) {}

fs::path PluginCache::entry(const std::string& hash) const {
  return folder_ / (hash + "-" + identity_);
}

std::optional<std::string> PluginCache::find(const std::string& hash) const {
  const fs::path plugin = entry(hash) / "model_plugin.so";
  std::error_code ec;
  if (!fs::is_regular_file(plugin, ec)) return std::nullopt;
  return plugin.string();
}

bool PluginCache::discard(const std::string& hash) {
  std::error_code ec;
  fs::create_directories(folder_, ec);
  const FileLock lock(folder_ / "lock");
  fs::remove_all(entry(hash), ec);
  return !ec;
}

double PluginCache::expected_build_seconds() const {
  std::ifstream in(folder_ / "last-build-seconds");
  double seconds = 0;
  return in >> seconds && seconds > 0 ? seconds : kDefaultBuildSeconds;
}

std::optional<std::string> PluginCache::build(const ModelToCompile& model, const Toolchain& tools,
                                              std::string& error) {
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (ec) {
    error = "cannot make the cache folder " + folder_.string() + ": " + ec.message();
    return std::nullopt;
  }
  const FileLock lock(folder_ / "lock");
  if (!lock.held()) {
    error = "cannot lock " + (folder_ / "lock").string();
    return std::nullopt;
  }
  if (std::optional<std::string> built = find(model.hash)) return built;  // another process
  // Holding the lock, no build is under way: a temporary folder is one a killed build left.
  for (const auto& old : fs::directory_iterator(folder_, ec)) {
    if (old.path().filename().string().starts_with("tmp-")) fs::remove_all(old.path(), ec);
  }
  return build_locked(model, tools, error);
}

std::optional<std::string> PluginCache::build_locked(const ModelToCompile& model,
                                                     const Toolchain& tools, std::string& error) {
  std::string scratch = (folder_ / "tmp-XXXXXX").string();
  if (::mkdtemp(scratch.data()) == nullptr) {
    error = "cannot make a folder in " + folder_.string();
    return std::nullopt;
  }
  const RemovedFolder removed{scratch};
  const fs::path src = fs::path(scratch) / "src", out = fs::path(scratch) / "build";
  const fs::path log = fs::path(scratch) / "build.log";
  std::optional<std::string> name = write_project(model, src, error);
  const auto start = std::chrono::steady_clock::now();
  if (!name || !build_plugin(tools, src, out, *name, log, error)) return std::nullopt;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const fs::path ready = fs::path(scratch) / "entry";
  std::error_code ec;
  fs::create_directories(ready, ec);
  if (!ec) fs::rename(out / (*name + "_plugin.so"), ready / "model_plugin.so", ec);
  if (!ec) {
    std::ofstream(ready / "about.txt")
        << "model " << model.model_file << "\nroot " << model.root << "\nhash " << model.hash
        << "\nsmcbip " << identity_ << "\nbuild seconds " << seconds << "\n";
    fs::remove_all(entry(model.hash), ec);  // what is left of an entry without its plugin
    if (!ec) fs::rename(ready, entry(model.hash), ec);
  }
  if (ec) {
    error = "cannot move the plugin into " + folder_.string() + ": " + ec.message();
    return std::nullopt;
  }
  std::string ignored;
  bipc::write_file_atomically((folder_ / "last-build-seconds").string(),
                              std::to_string(seconds) + "\n", ignored);
  return find(model.hash);
}

}  // namespace smcbip::tools
