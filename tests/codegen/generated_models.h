// The models of models/ that the build generated with bipc gen, with their compiled code.
#pragma once

#include <ostream>
#include <string_view>
#include <vector>

#include "engines/api/model.h"

namespace smcbip::tests {

struct GeneratedModel {
  const char* name;
  const char* file;  // relative to the source folder, or absolute (a model the build makes)
  const char* root;
  engines::CompiledModel::CodeFactory make_code;
  const bipc::ir::System& (*system)();  // the IR embedded in the generated sources
  const engines::Model& (*model)();     // that IR with the generated code
  std::string_view hash;                // the generated kModelHash
};

/// Test names show the model's name.
inline void PrintTo(const GeneratedModel& model, std::ostream* out) { *out << model.name; }

/// Every model generated for the tests, in tests/codegen/CMakeLists.txt's order.
const std::vector<GeneratedModel>& generated_models();

}  // namespace smcbip::tests
