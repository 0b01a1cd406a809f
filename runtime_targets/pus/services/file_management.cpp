// ST23 file management on host files below the repository root.
#include "file_management.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace smcbip::pus::services {
namespace {

enum class Field : std::uint32_t { Repository = 1, File = 2, TargetRepository = 3, TargetFile = 4 };

Failure invalid(Field field) {
  return Failure{FailureCode::InvalidArgument, static_cast<std::uint32_t>(field)};
}

Failure host_refused() {
  return Failure{FailureCode::FileRefused, static_cast<std::uint32_t>(errno)};
}

/// Relative, components neither empty, "." nor "..", printable ASCII; a file name one
/// component and not empty. The repository may be empty (the root itself).
bool confined(std::span<const std::uint8_t> text, bool file_name) {
  if (text.empty()) return !file_name;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && (text[i] < 0x20 || text[i] >= 0x7F)) return false;
    if (i < text.size() && text[i] != '/') continue;
    const std::size_t length = i - start;
    const bool dots = (length == 1 && text[start] == '.') ||
                      (length == 2 && text[start] == '.' && text[start + 1] == '.');
    if (length == 0 || dots || (file_name && i < text.size())) return false;
    start = i + 1;
  }
  return true;
}

/// A file descriptor closed when it goes out of scope.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

Outcome FileManagement::check(const Telecommand& tc) const {
  if (root_.empty()) return Failure{FailureCode::NotRouted, tc.header.service};
  const auto& f = std::get<FileRequest>(tc.data);
  if (!confined(f.repository.span(), false)) return invalid(Field::Repository);
  if (!confined(f.file.span(), true)) return invalid(Field::File);
  if (tc.header.subtype == 14) {
    if (!confined(f.target_repository.span(), false)) return invalid(Field::TargetRepository);
    if (!confined(f.target_file.span(), true)) return invalid(Field::TargetFile);
  }
  if (tc.header.subtype == 1 && f.max_size > kMaxCreatedFileSize) {
    return Failure{FailureCode::InvalidArgument, static_cast<std::uint32_t>(f.max_size)};
  }
  return std::nullopt;
}

bool FileManagement::full_path(const FixedBytes<kMaxFileString>& repository,
                               const FixedBytes<kMaxFileString>& file, PathBuffer& out) const {
  if (root_.size() + repository.size() + file.size() + 3 > out.size()) return false;
  char* at = std::copy(root_.begin(), root_.end(), out.data());
  *at++ = '/';
  if (!repository.empty()) {
    at = std::copy(repository.begin(), repository.end(), at);
    *at++ = '/';
  }
  at = std::copy(file.begin(), file.end(), at);
  *at = '\0';
  return true;
}

Outcome FileManagement::create(const FileRequest& f) const {
  PathBuffer path;
  if (!full_path(f.repository, f.file, path))
    return Failure{FailureCode::FileRefused, ENAMETOOLONG};
  const Descriptor file{::open(path.data(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0644)};
  if (file.fd < 0) return host_refused();
  if (::ftruncate(file.fd, static_cast<off_t>(f.max_size)) != 0) {
    const Failure failure = host_refused();
    ::unlink(path.data());
    return failure;
  }
  return std::nullopt;
}

Outcome FileManagement::remove(const FileRequest& f) const {
  PathBuffer path;
  if (!full_path(f.repository, f.file, path))
    return Failure{FailureCode::FileRefused, ENAMETOOLONG};
  struct stat status {};
  if (::lstat(path.data(), &status) != 0) return host_refused();
  if (!S_ISREG(status.st_mode)) return Failure{FailureCode::FileRefused, EISDIR};
  if (::unlink(path.data()) != 0) return host_refused();
  return std::nullopt;
}

Outcome FileManagement::report(const FileRequest& f, std::uint16_t destination, TmOutput& out,
                               Millis now) const {
  PathBuffer path;
  if (!full_path(f.repository, f.file, path))
    return Failure{FailureCode::FileRefused, ENAMETOOLONG};
  struct stat status {};
  if (::lstat(path.data(), &status) != 0) return host_refused();
  if (!S_ISREG(status.st_mode)) return Failure{FailureCode::FileRefused, EISDIR};
  FileRequest attributes;
  attributes.repository = f.repository;
  attributes.file = f.file;
  attributes.max_size = static_cast<std::uint64_t>(status.st_size);
  out.emit(23, 4, attributes, destination, now);
  return std::nullopt;
}

Outcome FileManagement::copy(const FileRequest& f) const {
  PathBuffer from, to;
  if (!full_path(f.repository, f.file, from) ||
      !full_path(f.target_repository, f.target_file, to)) {
    return Failure{FailureCode::FileRefused, ENAMETOOLONG};
  }
  const Descriptor source{::open(from.data(), O_RDONLY | O_NOFOLLOW)};
  if (source.fd < 0) return host_refused();
  struct stat status {};
  if (::fstat(source.fd, &status) != 0) return host_refused();
  if (!S_ISREG(status.st_mode)) return Failure{FailureCode::FileRefused, EISDIR};
  const Descriptor target{::open(to.data(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0644)};
  if (target.fd < 0) return host_refused();
  std::array<char, 4096> buffer;
  for (;;) {
    const ssize_t got = ::read(source.fd, buffer.data(), buffer.size());
    if (got == 0) return std::nullopt;
    if (got < 0 || ::write(target.fd, buffer.data(), static_cast<std::size_t>(got)) != got) {
      const Failure failure = host_refused();
      ::unlink(to.data());  // no half-copied file left behind
      return failure;
    }
  }
}

Outcome FileManagement::execute(const Telecommand& tc, TmOutput& out, Millis now) {
  const auto& f = std::get<FileRequest>(tc.data);
  switch (tc.header.subtype) {
    case 1:
      return create(f);
    case 2:
      return remove(f);
    case 3:
      return report(f, tc.header.source_id, out, now);
    default:
      return copy(f);
  }
}

}  // namespace smcbip::pus::services
