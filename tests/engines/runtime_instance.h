// A Runtime over an interpreted model, with everything it refers to, for tests that drive the
// semantics directly.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <sstream>

#include "engines/api/model.h"
#include "engines/semantics/runtime.h"

namespace smcbip::tests {

struct RuntimeInstance {
  RuntimeInstance(const bipc::ir::System& system, const engines::Externs& externs,
                  const engines::RuntimeOptions& options)
      : model(system), random(1, 0) {
    EXPECT_EQ(engines::build_layout(system, layout), "");
    engines::bind_functions(system, externs, strings, functions);
    runtime =
        std::make_unique<engines::Runtime>(model, layout, functions, strings, out, random, options);
  }
  engines::InterpretedModel model;
  engines::Layout layout;
  engines::StringPool strings;
  engines::BoundFunctions functions;
  std::ostringstream out;
  engines::RandomStream random;
  std::unique_ptr<engines::Runtime> runtime;
};

}  // namespace smcbip::tests
