// Temporary-then-rename output files.
#include "bipc/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "bipc/input_file.h"

namespace smcbip::bipc {

std::string write_temporary_file(const std::string& pattern, const std::string& text) {
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) return {};
  ::fchmod(fd, 0644);  // mkstemp's 0600 would make the renamed result private
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  const bool ok = ::close(fd) == 0 && written == text.size();
  if (!ok) ::unlink(name.data());
  return ok ? std::string(name.data()) : std::string();
}

bool output_target(const std::string& path, std::string& target, std::string& error) {
  // Linux follows at most 40 links in a path; a longer chain is a loop.
  constexpr int kMaxLinks = 40;
  std::filesystem::path current = path;
  for (int links = 0;; ++links) {
    struct stat info {};
    if (::lstat(current.c_str(), &info) != 0) {
      if (errno != ENOENT) {
        error = "cannot write '" + path + "': " + std::strerror(errno);
        return false;
      }
      break;  // a new file (or a link to one that does not exist yet)
    }
    if (S_ISREG(info.st_mode)) break;
    if (!S_ISLNK(info.st_mode)) {
      error = "cannot write '" + path + "': " +
              (current == path ? std::string() : "it links to '" + current.string() + "', ") +
              kind_of(info.st_mode) + ", not a regular file";
      return false;
    }
    if (links == kMaxLinks) {
      error = "cannot write '" + path + "': too many levels of symbolic links";
      return false;
    }
    std::error_code ec;
    const std::filesystem::path next = std::filesystem::read_symlink(current, ec);
    if (ec) {
      error = "cannot write '" + path + "': " + ec.message();
      return false;
    }
    current = next.is_absolute() ? next : current.parent_path() / next;
  }
  target = current.string();
  return true;
}

bool write_file_atomically(const std::string& path, const std::string& text, std::string& error) {
  std::string target;
  if (!output_target(path, target, error)) return false;
  // The temporary sits next to the result, so that the rename stays on one file system.
  const std::string temporary = write_temporary_file(target + ".tmpXXXXXX", text);
  if (temporary.empty()) {
    error = "cannot write next to '" + target + "': " + std::strerror(errno);
    return false;
  }
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    error = "cannot write '" + target + "': " + std::strerror(errno);
    ::unlink(temporary.c_str());
    return false;
  }
  return true;
}

bool write_files_atomically(const std::string& folder, const std::vector<NamedText>& files,
                            std::string& error) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) {
    error = "cannot create the folder " + folder + ": " + ec.message();
    return false;
  }
  std::vector<std::pair<std::string, std::string>> written;  // temporary, final
  for (const NamedText& file : files) {
    std::string path;
    if (!output_target(folder + "/" + file.name, path, error)) {
      for (const auto& [done, unused] : written) std::filesystem::remove(done, ec);
      return false;
    }
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    const std::string temporary = write_temporary_file(path + ".tmpXXXXXX", file.text);
    if (temporary.empty()) {
      error = "cannot write " + path;
      for (const auto& [done, unused] : written) std::filesystem::remove(done, ec);
      return false;
    }
    written.emplace_back(temporary, path);
  }
  for (std::size_t i = 0; i < written.size(); ++i) {
    std::filesystem::rename(written[i].first, written[i].second, ec);
    if (ec) {
      error = "cannot write " + written[i].second + ": " + ec.message();
      for (std::size_t j = i; j < written.size(); ++j) {
        std::filesystem::remove(written[j].first, ec);
      }
      return false;
    }
  }
  return true;
}

}  // namespace smcbip::bipc
