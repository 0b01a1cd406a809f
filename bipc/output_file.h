// Writing result files so that a failed run leaves nothing half-written on disk.
#pragma once

#include <string>
#include <vector>

namespace smcbip::bipc {

/// Writes `text` to a new file created from `pattern` (mkstemp: it must end in XXXXXX), made
/// readable by all like an ordinary output file; returns its path, or "" on failure (errno set).
std::string write_temporary_file(const std::string& pattern, const std::string& text);

/// The file that writing `path` must replace: `path` itself, or the file its chain of symbolic
/// links ends at (which may not exist yet). False, with the reason in `error`, when that is not
/// a regular file (a folder, a FIFO, a device, a socket) or the links loop, so that a result
/// never replaces one of those.
bool output_target(const std::string& path, std::string& target, std::string& error);

/// Writes `text` to `path` (through its symbolic links, to their target) by a temporary file
/// beside the target, renamed over it only once complete. Refuses a target that is not a
/// regular file (output_target). On failure returns false, removes the temporary and explains
/// in `error`.
bool write_file_atomically(const std::string& path, const std::string& text, std::string& error);

/// A file to write: its name relative to an output folder, and its contents.
struct NamedText {
  std::string name;
  std::string text;
};

/// Writes `files` into `folder` (created if needed) so that either all are written or none:
/// each goes to a temporary file beside its target (output_target), and the temporaries are
/// renamed over the targets only once all are complete. False with the reason in `error`.
bool write_files_atomically(const std::string& folder, const std::vector<NamedText>& files,
                            std::string& error);

}  // namespace smcbip::bipc
