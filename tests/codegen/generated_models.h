// The models of models/ that the build generated with bipc gen, with their compiled code.
#pragma once

#include <ostream>
#include <vector>

#include "engines/model.h"

namespace smcbip::tests {

struct GeneratedModel {
  const char* name;
  const char* file;  // relative to the source folder
  const char* root;
  engines::CompiledModel::CodeFactory make_code;
};

/// Test names show the model's name.
inline void PrintTo(const GeneratedModel& model, std::ostream* out) { *out << model.name; }

/// Every model generated for the tests, in tests/codegen/CMakeLists.txt's order.
const std::vector<GeneratedModel>& generated_models();

}  // namespace smcbip::tests
