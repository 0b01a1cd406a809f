// Models and property files for the tests of smc::check_properties and explore_properties.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "smc/smc.h"
#include "tests/engines/temp_model.h"

namespace smcbip::smc::tests {

/// The model in `file` under the source folder `folder` (root System()), loaded once.
inline const bipc::ir::System& model_in(const std::string& folder, const std::string& file) {
  static std::map<std::string, std::optional<bipc::ir::System>> loaded;
  const std::string path = std::string(SMCBIP_SOURCE_DIR) + "/" + folder + "/" + file;
  auto [it, fresh] = loaded.try_emplace(path);
  if (fresh) it->second = smcbip::tests::load_model(path, "System()");
  return *it->second;
}

/// `queries` parsed and resolved against `system`; a failure to do so fails the test.
inline monitors::PropertyFile properties(const std::string& queries,
                                         const bipc::ir::System& system) {
  monitors::ParsedProperties parsed = monitors::parse_properties(queries, "q.mtl");
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  monitors::resolve_names(parsed.file, system, parsed.diagnostics);
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  return std::move(parsed.file);
}

/// The answers to `queries` on the bundled model `file` (models/).
inline std::vector<QueryResult> check(const std::string& file, const std::string& queries,
                                      const CheckOptions& options) {
  const bipc::ir::System& system = model_in("models", file);
  return check_properties(system, properties(queries, system), options);
}

/// The same, with one guarantee per sweep.
inline std::vector<QueryResult> explore(const std::string& file, const std::string& queries,
                                        const CheckOptions& options) {
  const bipc::ir::System& system = model_in("models", file);
  return explore_properties(system, properties(queries, system), options);
}

}  // namespace smcbip::smc::tests
