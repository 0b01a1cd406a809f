// Vocabulary shared by the syntax tree and the IR: time units, urgencies, extern-port policies.
#pragma once

#include <cstdint>

namespace smcbip::bipc {

/// The unit of a clock (`clock x unit millisecond`).
enum class TimeUnit : std::uint8_t {
  Nanosecond,
  Microsecond,
  Millisecond,
  Second,
  Minute,
  Hour,
  Day
};

/// How long a transition may wait once enabled: lazy (any time), delayable (up to the end of
/// its window), eager (not at all). Lazy is BIP2's default.
enum class Urgency : std::uint8_t { Lazy, Delayable, Eager };

/// What an extern port does with an event it cannot take now.
enum class ExternPolicy : std::uint8_t { Remember, Ignore, Error };

}  // namespace smcbip::bipc
