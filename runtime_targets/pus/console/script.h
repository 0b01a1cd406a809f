// Scripts of telecommands: one TC per line in the syntax of `pus-console encode`, '#' comments,
// every refused line reported at its line and column.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "console/tc_options.h"
#include "packets/packets.h"

namespace smcbip::pus::console {

/// Where a script line went wrong (1-based line and column) and what was expected there.
struct ScriptError {
  std::uint32_t line = 0, column = 0;
  std::string message;
};

/// One line of a script: nothing (blank or comment), a TC, a pause, or an error.
struct LineResult {
  bool has_tc = false;
  BuiltTc tc;  ///< checked to encode; its sequence count is set by a Sequencer
  std::optional<std::chrono::milliseconds> wait;  ///< `wait MS`: receive for MS before going on
  /// `raw HEX`: octets sent as they are, unchecked (to see how the other end refuses them).
  std::optional<std::vector<std::uint8_t>> raw;
  std::vector<ScriptError> errors;
};

/// The longest pause a `wait` line may ask for, in milliseconds (an hour).
inline constexpr std::uint64_t kMaxWaitMs = 3600000;

/// Parses one line numbered `line`: a TC (an optional leading word `encode`, SERVICE SUBTYPE,
/// fields and header options), `wait MS` or `raw HEX`; '#' starts a comment.
LineResult parse_line(std::string_view text, std::uint32_t line, const Config& config);

/// Numbers the TCs without --seq: one more than the previous TC of the same APID, from 0
/// (a given --seq sets the count the next ones continue from).
class Sequencer {
 public:
  void number(BuiltTc& tc);

 private:
  std::map<std::uint16_t, std::uint16_t> next_;
};

/// The TCs of a script, numbered and encoded (with the data length of their octets), and its
/// pauses, each with its line; or the errors of every refused line (then no entry).
struct ParsedScript {
  struct Entry {
    Telecommand tc;
    std::vector<std::uint8_t> bytes;
    std::uint32_t line = 0;
    std::optional<std::chrono::milliseconds> wait;  ///< set for a pause (then no TC)
    bool raw = false;  ///< `bytes` are a raw line's octets (then no TC)
  };
  std::vector<Entry> tcs;
  std::vector<ScriptError> errors;
};

/// Parses a whole script; prints nothing.
ParsedScript parse_script(std::string_view text, const Config& config);

}  // namespace smcbip::pus::console
