// The new translation of the ESROCOS watchdog design (taste2bip's translate, default options)
// beside the original translator's BIP of it, for the tests that compare them.
#pragma once

#include <optional>
#include <string>

#include "bipc/ir/ir.h"
#include "tests/taste2bip/watchdog_traces.h"

namespace smcbip::taste2bip::test {

/// The nominal package taste2bip writes for the design in the shared data (WCET zero); nullopt
/// (and `why` set to the diagnostics) on failure.
std::optional<std::string> translated_package(std::string& why);

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
