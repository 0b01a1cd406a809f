// The user-written externs of the BIP conformance models (EXPECTED.md section 10): the
// tempcontrol print helpers and the extern-port classes of `external` / `external_error`.
#pragma once

#include <cstdint>
#include <string>

#include "engines/api/externs.h"

namespace smcbip::tests {

/// Registers, on top of the builtins, what the conformance models call beyond the C library:
/// - `print(string)`, `string print_position(int)`, `string print_command(int)` and
///   `print(int, int, string, string, string, string)` (tempcontrol-print.hpp);
/// - extern-port classes "MyExternalPortSum" and "MyExternalPortSingle".
/// demosaicing9's image types and functions are not provided (its test is skipped).
void register_conformance_externs(engines::Externs& externs);

/// One tempcontrol table row without its newline: the six fields right-aligned in widths
/// 6, 12, 8, 8, 12 and 12, with no other separator.
std::string tempcontrol_row(std::int64_t step, std::int64_t temperature, const std::string& rod1,
                            const std::string& rod2, const std::string& command1,
                            const std::string& command2);

/// `down`, `rest`, `ready` for 0, 1, 2; `ERROR!` otherwise.
std::string tempcontrol_position(std::int64_t position);
/// `up`, `down`, `Shutdown!` for 0, 1, 2; `ERROR!` otherwise.
std::string tempcontrol_command(std::int64_t command);

/// Events per "MyExternalPortSum" port, and the seed of their shared random delays.
inline constexpr int kSumEventsPerPort = 100;
inline constexpr std::uint64_t kSumDelaySeed = 20'250'101;

}  // namespace smcbip::tests
