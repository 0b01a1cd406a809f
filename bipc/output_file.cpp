// Temporary-then-rename output files.
#include "bipc/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

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

bool write_file_atomically(const std::string& path, const std::string& text, std::string& error) {
  // The temporary sits next to the result, so that the rename stays on one file system.
  const std::string temporary = write_temporary_file(path + ".tmpXXXXXX", text);
  if (temporary.empty()) {
    error = "cannot write next to '" + path + "': " + std::strerror(errno);
    return false;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    error = "cannot write '" + path + "': " + std::strerror(errno);
    ::unlink(temporary.c_str());
    return false;
  }
  return true;
}

}  // namespace smcbip::bipc
