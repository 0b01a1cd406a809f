// The BIP that the original TASTE-to-BIP tool made of the ESROCOS watchdog design, made runnable
// here: its extern C++ (ASN.1 records, a FIFO, write/writeln) supplied through engines::Externs
// after a small, documented textual adaptation of the file.
//
// Adaptations of InterfaceViewFull.bip (watchdog_adapted_text, each checked to apply exactly as
// often as the original has it, so a changed input fails loudly):
//  1. The setters `set_rad`, `set_translation`, `set_rotation`, `set_heading` return the updated
//     record instead of updating their first argument (extern functions get their arguments by
//     value here): `extern function T set_x(const T, const float)`, and each call statement
//     `set_x(v, e);` becomes `v = set_x(v, e);`.
//  2. The FIFO is a value too: `push_back` returns the new queue (`q = push_back(q, val, size);`),
//     and the connector's `r.v = pop_front(s.q);` becomes `r.v = front(s.q);
//     s.q = pop_front(s.q);` with `front` a new extern and `pop_front` returning the rest.
// Nothing else changes: places, transitions, guards, timing and connectors are the original's.
//
// What the externs keep (watchdog_externs): a Base_commands_Motion2D record is its translation,
// rotation and heading as the doubles the model writes (no ASN.1 range or precision), a
// Base_Angle its radians; the one decision that reads them is BLSClient's (all three zero: a
// stop command), and Logger prints them. Records and queues are immutable values interned in a
// process-wide pool: a handle (Val::i) names one value, equal values have equal handles (so an
// explorer that compares states by their bytes compares records and queues by value), handle 0 is
// the default (all-zero record, empty queue) that the engines give extern data before any
// assignment. `push_back(q, v, size)` on a queue holding `size` elements or more returns q
// unchanged (the call is dropped, as the new translation's sporadic wrappers drop calls to a full
// FIFO: an assumption, since the original's ext-cpp sources are not in the data); `front` and
// `pop_front` of an empty queue give the default record and the empty queue (the model only calls
// them when `get_size(q) > 0`). write/writeln print to the run's output.
//
// Besides, tests use the nominal variant (remove_fault_transitions: an IR transform dropping
// the transitions of the hand-added @fault ports), whose behaviour the translation should have.
#pragma once

#include <compare>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "tests/taste2bip/watchdog_traces.h"

/// Skips the calling test (one-line reason) when the shared data is absent (a user's clone).
#define WATCHDOG_SKIP_WITHOUT_DATA()                                                 \
  if (!std::filesystem::exists(::smcbip::taste2bip::test::watchdog_original_file())) \
  GTEST_SKIP() << "the shared ESROCOS watchdog data is absent"

namespace smcbip::taste2bip::test {

/// The original translator's BIP of the watchdog design, under the shared data folder.
std::filesystem::path watchdog_original_file();

/// `original` with the adaptations listed above; nullopt (and `why` set) when one of them does
/// not apply as often as expected.
std::optional<std::string> watchdog_adapted_text(const std::string& original, std::string& why);

/// The builtins plus the extern functions of the adapted model, as described above.
engines::Externs watchdog_externs();
/// The same functions added to `externs` (without the builtins).
void add_watchdog_externs(engines::Externs& externs);

/// The adapted text of the original file; nullopt (and `why` set) when unreadable.
std::optional<std::string> watchdog_adapted_original(std::string& why);

/// `text` written to a temporary `file_name` (the package's name plus .bip) and loaded through
/// the front end with `root`; nullopt (and `why` set to the diagnostics) on failure.
std::optional<bipc::ir::System> load_bip_text(const std::string& text, const std::string& file_name,
                                              const std::string& root, std::string& why);

/// The adapted original, through the front end, with root `Syst()`; nullopt (and `why` set,
/// with the front end's diagnostics) on failure.
std::optional<bipc::ir::System> load_watchdog_original(std::string& why);

/// The transitions labelled by ports annotated `@fault` removed (JoystickDriver.fault1: the
/// lost heartbeat), leaving the nominal behaviour.
void remove_fault_transitions(bipc::ir::System& system);

/// Whose names an observation uses: the original translator's (port `F.F_p_in`) or the new
/// translation's (`F.p_in`, taste2bip/translate/signature.h).
enum class WatchdogNaming { Original, Translation };

/// The calls of the design's functions, under the labels `F.p` whatever the naming: those of
/// the four SDL functions (JoystickDriver, CmdDispatcher, Logger, BLSClient), and with
/// `watchdog_calls` those of the C++ function Watchdog (test_cmd, mot_cmd); the SDL functions'
/// state Wait as `F.Wait`, and with `watchdog_wait` Watchdog's place Wait (original only).
WatchdogObservation watchdog_observation(WatchdogNaming naming, bool watchdog_calls,
                                         bool watchdog_wait);

/// The translation, rotation and heading of a record handle (for tests that read data).
struct Motion2D {
  double translation = 0, rotation = 0, heading = 0;
  auto operator<=>(const Motion2D&) const = default;
};
Motion2D motion2d_value(std::int64_t handle);

}  // namespace smcbip::taste2bip::test
