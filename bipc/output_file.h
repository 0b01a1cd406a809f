// Writing result files so that a failed run leaves nothing half-written on disk.
#pragma once

#include <string>

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

}  // namespace smcbip::bipc
