// --explore counts each reachable state once, with its own time bounds: a state restored from
// the frontier is judged on its own invariants, not on those of the state explored before it.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "engines/engines.h"
#include "tests/engines/temp_model.h"

namespace smcbip::engines {
namespace {

// From s0 the atom moves to s1 (no transition, no invariant: a deadlock) or to s2, whose
// invariant bounds the time that may pass (no transition: a time-lock).
constexpr const char* kModel = R"(package explore_model
  port type Sig()
  atom type A()
    clock x unit millisecond
    port Sig a(), b()
    place s0, s1, s2
    initial to s0 do { x = 0; }
    on a from s0 to s1
    on b from s0 to s2
    invariant stay_short at s2 provided (x <= 3)
  end
  compound type Top()
    component A one()
  end
end
)";

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
