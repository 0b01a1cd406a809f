// Wide connectors: a broadcast over any number of ports runs (its largest enabled interaction
// is found from the define tree), and what still needs every interaction enumerated is refused
// with a clear error instead of exhausting memory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "bipc/bipc.h"
#include "engines/engines.h"
#include "tests/engines/temp_model.h"

namespace smcbip::engines {
namespace {

/// A broadcast from one trigger to `receivers` synchrons: 2^receivers interactions. `extra`
/// goes into the connector type (e.g. a guarded `on` clause); with `timed`, every second
/// receiver's port is open only from 5 ns on, so the enabled ports offer different windows.
std::string broadcast_model(int receivers, const std::string& extra = "", bool timed = false) {
  std::string ports = "Sig t", define = "t'", bind = "c(s.p";
  for (int i = 0; i < receivers; ++i) {
    ports += ", Sig r" + std::to_string(i);
    define += " r" + std::to_string(i);
    bind += ", r" + std::to_string(i) + ".p";
  }
  std::string text = "package wide\n  port type Sig()\n  connector type All(" + ports +
                     ")\n    define " + define + "\n" + extra + "  end\n" +
                     "  atom type A()\n    export port Sig p()\n    place S\n    initial to S\n"
                     "    on p from S to S\n  end\n" +
                     "  atom type Late()\n    clock x unit nanosecond\n    export port Sig p()\n"
                     "    place S\n    initial to S do { x = 0; }\n"
                     "    on p from S to S provided (x >= 5)\n  end\n" +
                     "  compound type Top()\n    component A s()\n";
  for (int i = 0; i < receivers; ++i) {
    text += std::string("    component ") + (timed && i % 2 ? "Late" : "A") + " r" +
            std::to_string(i) + "()\n";
  }
  return text + "    connector All " + bind + ")\n  end\nend\n";
}

/// Runs the model for two steps; `out` receives the text trace.
RunResult run_text(const std::string& model, std::ostringstream& out,
                   EngineKind engine = EngineKind::Reference) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(model, "Top()");
  if (!system) return {kInputError, RunEnd::Error, 0, "the test model does not load", {}};
  SimulateOptions options;
  options.engine = engine;
  options.seed = 1;
  options.limit = 2;
  return simulate(*system, options, Externs::with_builtins(), out);
}

RunResult run_broadcast(int receivers, const std::string& extra = "", bool timed = false) {
  std::ostringstream out;
  return run_text(broadcast_model(receivers, extra, timed), out);
}

TEST(EngineLimits, ABroadcastOfTwelveRuns) {
  const RunResult result = run_broadcast(12);
  EXPECT_EQ(result.code, kRunOk) << result.message;
  EXPECT_EQ(result.steps, 2u);
}

TEST(EngineLimits, ABroadcastOfFiveHundredFiresEveryReceiverAtOnce) {
  for (EngineKind engine :
       {EngineKind::Reference, EngineKind::Optimised, EngineKind::Multithread}) {
    std::ostringstream out;
    const RunResult result = run_text(broadcast_model(500), out, engine);
    ASSERT_EQ(result.code, kRunOk) << result.message;
    EXPECT_EQ(result.steps, 2u);
    // One item, the whole broadcast: the smaller ones are dominated by maximal progress.
    EXPECT_NE(out.str().find(": 1 interaction:"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("s.p() r0.p() r1.p()"), std::string::npos);
    EXPECT_NE(out.str().find("r498.p() r499.p()"), std::string::npos);
  }
}

/// The run is refused as bad input with a message containing `text`.
void expect_refused(const RunResult& result, const std::string& text) {
  EXPECT_EQ(result.code, kInputError);
  EXPECT_NE(result.message.find(text), std::string::npos) << result.message;
}

TEST(EngineLimits, AGuardedWideConnectorIsAnInputError) {
  expect_refused(run_broadcast(64, "    on t provided (false)\n"),
                 "connector 'c' has more than 64 ports and a guard");
}

TEST(EngineLimits, TooManyGuardedInteractionsIsAnInputError) {
  expect_refused(run_broadcast(40, "    on t provided (false)\n"),
                 "connector 'c' defines more than 1048576 interactions");
}

TEST(EngineLimits, DifferentWindowsOnAWideConnectorAreAnInputError) {
  // Half the receivers offer their port from 5 ns on, the others at any time: the dominated
  // interactions may then run where the largest cannot, and there are 2^70 of them.
  expect_refused(run_broadcast(70, "", true),
                 "connector 'ROOT.c': its enabled ports offer different timing");
}

}  // namespace
}  // namespace smcbip::engines
