// Property files answered on the watchdog's models through the smc library.
#include "tests/taste2bip/watchdog_answers.h"

#include <gtest/gtest.h>

#include <iostream>

#include "engines/api/plugin.h"
#include "tests/taste2bip/watchdog_model.h"

namespace smcbip::taste2bip::test {
namespace {

/// The model entry smc runs: plain function pointers, so the model is reached through a static.
const engines::Model* checked_model = nullptr;
const engines::Model& entry_model() { return *checked_model; }
void entry_externs(engines::Externs& externs) { add_watchdog_externs(externs); }

}  // namespace

std::vector<smc::QueryResult> watchdog_answers(const bipc::ir::System& system,
                                               const std::string& queries,
                                               const std::string& file_name, bool watchdog_externs,
                                               std::uint64_t seed, const std::string& label) {
  monitors::ParsedProperties parsed = monitors::parse_properties(queries, file_name);
  if (parsed.ok()) monitors::resolve_names(parsed.file, system, parsed.diagnostics);
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  if (!parsed.ok()) return {};
  const engines::InterpretedModel model(system);
  engines::PluginEntry entry;
  entry.model = &entry_model;
  entry.register_externs = &entry_externs;
  smc::CheckOptions options;
  options.method = smc::Method::Pestim;
  options.delta = kWatchdogDelta;
  options.alpha = kWatchdogAlpha;
  options.seed = seed;
  options.threads = 2;
  if (watchdog_externs) {
    checked_model = &model;
    options.compiled = &entry;
  }
  std::vector<smc::QueryResult> results = smc::check_properties(system, parsed.file, options);
  checked_model = nullptr;
  for (const smc::QueryResult& r : results) {
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.samples, smc::chernoff_samples(kWatchdogDelta, kWatchdogAlpha));
    EXPECT_EQ(r.undecided, 0u) << r.why_undecided.first_error;
    std::cerr << label << " query " << r.query + 1 << ": " << r.estimate << " [" << r.ci.low << ", "
              << r.ci.high << "] from " << r.samples << " runs, seed " << seed << "\n";
  }
  return results;
}

std::vector<smc::QueryResult> original_watchdog_answers(const std::string& queries, bool nominal,
                                                        std::uint64_t seed) {
  std::string why;
  std::optional<bipc::ir::System> system = load_watchdog_original(why);
  EXPECT_TRUE(system) << why;
  if (!system) return {};
  if (nominal) remove_fault_transitions(*system);
  return watchdog_answers(*system, queries, "watchdog.mtl", /*watchdog_externs=*/true, seed,
                          "original");
}

}  // namespace smcbip::taste2bip::test
