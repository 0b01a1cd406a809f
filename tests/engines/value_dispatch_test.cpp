// Transitions of a state machine led by `s == literal` on one datum are looked up by the datum's
// value (Layout::dispatch_from_place): the runs are those of examining every transition, on every
// engine. Expectations derived by hand from the models below.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "engines/engines.h"
#include "tests/engines/run_once.h"
#include "tests/engines/temp_model.h"

namespace smcbip::tests {
namespace {

using engines::EngineKind;

// Walker: s goes 0 -> 1 -> 2 -> 3 -> 4 (n counts the steps); at s == 4 with n == 4 two
// transitions labelled p are enabled: a non-deterministic choice, found as the fourth step
// computes the atom's offers (the run's error after 3 complete steps).
// The literal stands on either side, some guards go on after the comparison, some literals are
// never reached, and two transitions share the literal 3 (the first one's guard is false).
// Stopper: from s == 0 it sets s = 9, which no transition compares with: a deadlock.
constexpr const char* kModel = R"(package dispatch
  port type P()
  connector type Solo(P p)
    define p
  end
  atom type Walker()
    data int s = 0
    data int n = 0
    export port P p()
    place L
    initial to L
    on p from L to L provided (s == 0) do { s = 1; n = n + 1; }
    on p from L to L provided (1 == s && n < 100) do { s = 2; n = n + 1; }
    on p from L to L provided (s == 2) do { s = 3; n = n + 1; }
    on p from L to L provided (s == 7) do { s = 0; }
    on p from L to L provided (s == 3 && n > 100) do { s = 0; }
    on p from L to L provided (s == 3) do { s = 4; n = n + 1; }
    on p from L to L provided (s == 4 && n == 4) do { s = 5; }
    on p from L to L provided (s == 4) do { s = 6; }
  end
  atom type Stopper()
    data int s = 0
    export port P p()
    place L
    initial to L
    on p from L to L provided (s == 0) do { s = 9; }
    on p from L to L provided (s == 1) do { s = 0; }
    on p from L to L provided (s == 2) do { s = 0; }
    on p from L to L provided (s == 3) do { s = 0; }
  end
  compound type Walk()
    component Walker w()
    connector Solo c(w.p)
  end
  compound type Stop()
    component Stopper w()
    connector Solo c(w.p)
  end
end
)";

engines::RunResult run(const bipc::ir::System& system, EngineKind engine) {
  return run_once(system, engine, 5, 20);
}

constexpr EngineKind kEngines[] = {EngineKind::Reference, EngineKind::Optimised,
                                   EngineKind::Multithread};

TEST(ValueDispatch, FindsTheTransitionsTheDatumEnables) {
  const TempDir dir;
  const std::string file = dir.write("dispatch.bip", kModel).string();
  const std::optional<bipc::ir::System> system = load_model(file, "Walk()");
  ASSERT_TRUE(system);
  for (EngineKind engine : kEngines) {
    const engines::RunResult result = run(*system, engine);
    EXPECT_EQ(result.end, engines::RunEnd::Error);
    EXPECT_EQ(result.steps, 3u);
    EXPECT_TRUE(result.message.starts_with(
        "non-deterministic choice between transitions labelled by p in ROOT.w"))
        << result.message;
  }
}

TEST(ValueDispatch, AValueNoTransitionComparesWithDeadlocks) {
  const TempDir dir;
  const std::string file = dir.write("dispatch.bip", kModel).string();
  const std::optional<bipc::ir::System> system = load_model(file, "Stop()");
  ASSERT_TRUE(system);
  for (EngineKind engine : kEngines) {
    const engines::RunResult result = run(*system, engine);
    EXPECT_EQ(result.end, engines::RunEnd::Deadlock);
    EXPECT_EQ(result.steps, 1u);
  }
}

}  // namespace
}  // namespace smcbip::tests
