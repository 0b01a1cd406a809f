// Writing result files so that a failed run leaves nothing half-written on disk.
#pragma once

#include <string>

namespace smcbip::bipc {

/// Writes `text` to a new file created from `pattern` (mkstemp: it must end in XXXXXX), made
/// readable by all like an ordinary output file; returns its path, or "" on failure (errno set).
std::string write_temporary_file(const std::string& pattern, const std::string& text);

/// Writes `text` to `path` through a temporary file beside it, renamed into place only once it
/// is complete. On failure returns false, removes the temporary and explains in `error`.
bool write_file_atomically(const std::string& path, const std::string& text, std::string& error);

}  // namespace smcbip::bipc
