// Property files answered on the watchdog's models by statistical model checking through the smc
// library (smc::check_properties), for the tests that compare the original translator's BIP with
// the new translation on the same properties.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "smc/smc.h"

namespace smcbip::taste2bip::test {

/// PESTIM's precision and confidence for every answer: N = ceil(ln(2/alpha) / (2 delta^2)) =
/// 6,623 runs per query, and each estimate is within delta of the true probability with
/// probability 1 - alpha (Okamoto's bound).
inline constexpr double kWatchdogDelta = 0.02, kWatchdogAlpha = 0.01;

/// The answers to `queries` (a property file's text; `file_name` names it in diagnostics) on
/// `system` with a fixed `seed`, each printed (`label`, estimate, interval, runs). With
/// `watchdog_externs` the runs take the original's extern functions (watchdog_model.h) through a
/// model entry of the interpreted system; without, the interpreter runs the system as it is. A
/// property that does not parse or resolve, a query's error or an undecided run is a test
/// failure (and the answers then are empty or partial).
std::vector<smc::QueryResult> watchdog_answers(const bipc::ir::System& system,
                                               const std::string& queries,
                                               const std::string& file_name, bool watchdog_externs,
                                               std::uint64_t seed, const std::string& label);

/// watchdog_answers on the original translator's model (watchdog_model.h), with its fault
/// transitions (or without them: `nominal`), its property file named watchdog.mtl.
std::vector<smc::QueryResult> original_watchdog_answers(const std::string& queries, bool nominal,
                                                        std::uint64_t seed);

}  // namespace smcbip::taste2bip::test
