// Bounded reading of regular input files.
#include "bipc/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "bipc/errors.h"

namespace smcbip::bipc {
namespace {

/// Closes a file descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

void require_input_file(const std::string& path, const std::string& what, bool streams) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    throw InputError("cannot read " + what + ": " + std::strerror(errno), ErrorLocation{path});
  }
  if (S_ISREG(info.st_mode) || (streams && S_ISFIFO(info.st_mode))) return;
  throw InputError(what + " is " + kind_of(info.st_mode) + ", not a regular file",
                   ErrorLocation{path});
}

void require_model_file(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) require_input_file(path, "the model file");
}

std::string read_input_file(const std::string& path, const std::string& what,
                            std::uint64_t max_bytes) {
  const ErrorLocation at{path};
  // O_NONBLOCK: opening a FIFO for reading must not wait for a writer before it is refused.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw InputError("cannot read " + what + ": " + std::strerror(errno), at);
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) {
    throw InputError("cannot read " + what + ": " + std::strerror(errno), at);
  }
  if (!S_ISREG(info.st_mode)) {
    throw InputError(what + " is " + kind_of(info.st_mode) + ", not a regular file", at);
  }
  const auto too_large = [&] {
    const bool mebibytes = max_bytes >= (1u << 20) && max_bytes % (1u << 20) == 0;
    return InputError(what + " is larger than " +
                          (mebibytes ? std::to_string(max_bytes >> 20) + " MiB"
                                     : std::to_string(max_bytes) + " bytes"),
                      at);
  };
  if (static_cast<std::uint64_t>(info.st_size) > max_bytes) throw too_large();
  // The size may change while the file is read: the cap holds on what is read.
  std::string text;
  text.reserve(static_cast<std::size_t>(info.st_size));
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0) throw InputError("cannot read " + what + ": " + std::strerror(errno), at);
    if (n == 0) break;
    if (text.size() + static_cast<std::uint64_t>(n) > max_bytes) throw too_large();
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

}  // namespace smcbip::bipc
