// The conformance models generated as C++ at build time (generate_conformance.sh), for the
// generated-model variants of the typed conformance suite.
#pragma once

#include <string>
#include <vector>

#include "engines/api/model.h"

namespace smcbip::tests {

struct GeneratedConformanceModel {
  const char* model;  // e.g. `running/clock_speed`
  const char* root;   // e.g. `Compound()`
  engines::CompiledModel::CodeFactory make_code;
};

/// Every generated model (none when the shared data were absent at build time).
const std::vector<GeneratedConformanceModel>& generated_conformance_models();

/// The factory of `model` generated with `root`, or null.
inline engines::CompiledModel::CodeFactory find_generated_conformance(const std::string& model,
                                                                      const std::string& root) {
  for (const GeneratedConformanceModel& m : generated_conformance_models()) {
    if (model == m.model && root == m.root) return m.make_code;
  }
  return nullptr;
}

}  // namespace smcbip::tests
