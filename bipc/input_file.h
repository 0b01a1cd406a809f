// Reading a whole input file that must be a regular file of bounded size, so that a folder, a
// FIFO or /dev/zero named as input is refused rather than read forever.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>

namespace smcbip::bipc {

/// Property files, option files and the like are text a person writes: 4 MiB (some 100,000
/// queries) is plenty, and bounds the memory a syntax tree of the file takes (about 80 bytes per
/// byte of a property file: some 330 MB at most).
inline constexpr std::uint64_t kMaxInputFileBytes = std::uint64_t{4} << 20;

/// The contents of `path`. Throws smcbip::InputError (located at `path`) when it is missing or
/// unreadable, not a regular file, or larger than `max_bytes`; `what` names the file in the
/// message ("the property file").
std::string read_input_file(const std::string& path, const std::string& what,
                            std::uint64_t max_bytes = kMaxInputFileBytes);

/// Throws smcbip::InputError (located at `path`) unless `path` names a regular file, or, with
/// `streams`, a FIFO or a pipe (read once, as a stream): never a folder or a device.
void require_input_file(const std::string& path, const std::string& what, bool streams = false);

/// What a file that is not a regular one is, for messages ("a folder", "a FIFO", ...).
const char* kind_of(mode_t mode);

/// The model file given to a tool: when `path` exists, throws smcbip::InputError unless it is a
/// regular file (the front end reports a missing one among its diagnostics).
void require_model_file(const std::string& path);

}  // namespace smcbip::bipc
