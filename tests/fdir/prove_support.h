// What the prover's tests share: loading a model of the source tree and proving one query
// given as text.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "fdir/fdir.h"
#include "monitors/monitors.h"
#include "tests/engines/temp_model.h"

namespace smcbip::fdir::testing {

/// The model `file` (relative to the source tree) instantiated at `root`.
inline std::optional<bipc::ir::System> load(const std::string& file, const std::string& root) {
  return tests::load_model(std::string(SMCBIP_SOURCE_DIR) + "/" + file, root);
}

/// The outcome of the single query `text` on `system`, under the assumptions `sources`.
inline QueryOutcome prove_text(const bipc::ir::System& system, const std::string& text,
                               const ProveOptions& options = {},
                               const std::vector<AssumptionSource>& sources = {}) {
  monitors::ParsedProperties parsed = monitors::parse_properties(text, "query.mtl");
  if (parsed.ok()) monitors::resolve_names(parsed.file, system, parsed.diagnostics);
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  if (!parsed.ok()) return {};
  Prover prover(system, options);
  if (!sources.empty()) prover.assume(sources);
  return prover.prove(parsed.file.queries.front(), monitors::constant_values(parsed.file));
}

}  // namespace smcbip::fdir::testing
