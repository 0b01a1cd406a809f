// --explore counts each reachable state once, with its own time bounds: a state restored from
// the frontier is judged on its own invariants, not on those of the state explored before it.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "engines/engines.h"
#include "tests/engines/lock_model.h"
#include "tests/engines/temp_model.h"

namespace smcbip::engines {
namespace {

constexpr const char* kModel = tests::kDeadlockOrTimeLock;

std::string exploration_line(EngineKind engine) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(kModel, "Top()");
  if (!system) return "the test model does not load";
  SimulateOptions options;
  options.engine = engine;
  options.explore = true;
  std::ostringstream out;
  const RunResult result = simulate(*system, options, Externs::with_builtins(), out);
  EXPECT_EQ(result.code, kRunOk);
  const std::string text = out.str();
  const std::size_t line = text.rfind("[BIP ENGINE]: computing");
  return line == std::string::npos ? text : text.substr(line);
}

TEST(Explore, EachStateKeepsItsOwnInvariantBounds) {
  for (EngineKind engine : {EngineKind::Reference, EngineKind::Optimised}) {
    EXPECT_EQ(exploration_line(engine),
              "[BIP ENGINE]: computing reachable states:... found 3 reachable states, 1 deadlock, "
              "1 timelock, and 0 errors in 0 states\n");
  }
}

}  // namespace
}  // namespace smcbip::engines
