// The new translation of the ESROCOS watchdog design (taste2bip's translate, default options)
// beside the original translator's BIP of it, for the tests that compare them.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "bipc/ir/ir.h"
#include "tests/taste2bip/watchdog_traces.h"

namespace smcbip::taste2bip::test {

/// The nominal package taste2bip writes for the design in the shared data (WCET zero), with the
/// atom types of `behaviours` (function name -> atom type text, Design::behaviours); nullopt (and
/// `why` set to the diagnostics) on failure.
std::optional<std::string> translated_package(
    std::string& why, const std::map<std::string, std::string>& behaviours = {});

/// tests/taste2bip/watchdog/watchdog_atom.bip: the original's hand-written Watchdog with the
/// translation's ports, for `behaviours["Watchdog"]`.
std::filesystem::path watchdog_atom_file();

/// `package` (a translation of the design) with the lost heartbeat that the original's authors
/// added by hand to their JoystickDriver (InterfaceViewFull.bip), added to the translated
/// JoystickDriver atom: a clock `t`, the port `@fault port Port fault1()` and a `silent` port,
/// places `l5` (heartbeat lost: its steps send nothing) and `l6` (such a step running), and the
/// original's four transitions, adapted to the translated atom's places (between two
/// transitions it marks its state Wait and `ready`):
///   on fault1 from Wait, ready to l5 provided (t < 100) lazy
///   on silent from l5 to Wait, ready provided (t >= 150) lazy do { t = 0; }
///   on step_in from l5 to l6 eager
///   on step_return from l6 to l5
/// (the last lazy, as the translated atom's own return, so that the step's wrapper dates it;
/// the original made it eager: the same runs with WCET zero). nullopt (and `why` set) when the
/// JoystickDriver atom is not as expected.
std::optional<std::string> with_lost_heartbeat(const std::string& package, std::string& why);

/// The translation's observation of the design's calls (watchdog_observation), with its
/// sporadic wrappers' counters of dropped calls (`dropped`, which nothing reads) erased:
/// untimed, a cyclic caller may call without end, and the original's FIFO drops such calls
/// without counting them.
WatchdogObservation translation_observation(bool watchdog_calls);

/// Both models: the nominal original (its hand-added fault transitions removed: the
/// translation's nominal package has none) and the translation; a failure to make one is a
/// test failure.
struct BothModels {
  std::optional<bipc::ir::System> original, translation;
};
BothModels load_both();

}  // namespace smcbip::taste2bip::test
