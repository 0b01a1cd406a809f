// The random models the build wrote (random_bip_model) and generated (bipc gen --code-only),
// with their compiled code.
#pragma once

#include <cstdint>
#include <ostream>
#include <vector>

#include "engines/api/model.h"

namespace smcbip::tests {

struct GeneratedRandomModel {
  std::uint64_t seed;
  const char* options;  // random_bip_model's options besides the seed, as one list
  const char* file;     // the package, in the build folder; root Root()
  engines::CompiledModel::CodeFactory make_code;
};

/// Test names show the seed.
inline void PrintTo(const GeneratedRandomModel& model, std::ostream* out) {
  *out << "seed " << model.seed << " (" << model.options << ")";
}

/// Every random model generated for the tests, by increasing seed.
const std::vector<GeneratedRandomModel>& generated_random_models();

}  // namespace smcbip::tests
