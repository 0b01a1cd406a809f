// ST23 file management over host files: the repositories are folders under one root folder
// (the mission's `file_repository`), a repository path and a file name naming a file below it.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "mission/mission.h"
#include "packets/packets.h"
#include "tm_output.h"
#include "verification.h"

namespace smcbip::pus::services {

/// The largest maximum size [23,1] may reserve on the host (the file is made that long).
inline constexpr std::uint64_t kMaxCreatedFileSize = 1 << 20;

/// ECSS-E-ST-70-41C 6.23 on a host file system. A path stays below the root: the repository
/// path and file names are relative, made of components that are neither empty, `.` nor `..`
/// (a file name is a single component), printable ASCII; anything else is InvalidArgument
/// (datum: the field, 1 repository, 2 file, 3 target repository, 4 target file). A file that
/// is a symbolic link is not followed (O_NOFOLLOW); links among the repositories' folders are
/// the root owner's to make, and are followed. What the host
/// refuses is FileRefused (datum: its errno). Paths are built in a fixed buffer: no allocation
/// after construction.
class FileManagement {
 public:
  explicit FileManagement(const mission::Mission& mission) : root_(mission.file_repository) {}

  /// Whether a request may start: a repository root is configured (NotRouted otherwise), its
  /// paths are confined (InvalidArgument), [23,1]'s size at most kMaxCreatedFileSize.
  Outcome check(const Telecommand& tc) const;
  /// [23,1] creates the file, its maximum size of zero octets (it must not exist); [23,2]
  /// deletes a regular file; [23,3] reports [23,4] with the file's size as its maximum size
  /// (what [23,1] reserved, or what a copy holds); [23,14] copies a regular file to a target
  /// that must not exist. The repositories must exist.
  Outcome execute(const Telecommand& tc, TmOutput& out, Millis now);

 private:
  using PathBuffer = std::array<char, 4096>;
  /// ROOT/REPOSITORY/FILE into `out`; false if it does not fit.
  bool full_path(const FixedBytes<kMaxFileString>& repository,
                 const FixedBytes<kMaxFileString>& file, PathBuffer& out) const;
  Outcome create(const FileRequest& f) const;
  Outcome remove(const FileRequest& f) const;
  Outcome report(const FileRequest& f, std::uint16_t destination, TmOutput& out, Millis now) const;
  Outcome copy(const FileRequest& f) const;

  std::string root_;
};

}  // namespace smcbip::pus::services
