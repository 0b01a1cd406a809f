// What the engines refuse, with a clear error instead of exhausting memory: connectors whose
// define expression allows more interactions than they enumerate, and over 64 ports.
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

/// A broadcast from one trigger to `receivers` synchrons: 2^receivers interactions.
std::string broadcast_model(int receivers) {
  std::string ports = "Sig t", define = "t'", bind = "c(s.p";
  for (int i = 0; i < receivers; ++i) {
    ports += ", Sig r" + std::to_string(i);
    define += " r" + std::to_string(i);
    bind += ", r" + std::to_string(i) + ".p";
  }
  std::string text = "package wide\n  port type Sig()\n  connector type All(" + ports +
                     ")\n    define " + define + "\n  end\n" +
                     "  atom type A()\n    export port Sig p()\n    place S\n    initial to S\n"
                     "    on p from S to S\n  end\n  compound type Top()\n    component A s()\n";
  for (int i = 0; i < receivers; ++i) text += "    component A r" + std::to_string(i) + "()\n";
  return text + "    connector All " + bind + ")\n  end\nend\n";
}

RunResult run_broadcast(int receivers) {
  const std::optional<bipc::ir::System> system =
      tests::load_model_text(broadcast_model(receivers), "Top()");
  if (!system) return {};
  SimulateOptions options;
  options.seed = 1;
  options.limit = 2;
  options.silent = true;
  std::ostringstream out;
  return simulate(*system, options, Externs::with_builtins(), out);
}

TEST(EngineLimits, ABroadcastOfTwelveRuns) {
  const RunResult result = run_broadcast(12);
  EXPECT_EQ(result.code, kRunOk) << result.message;
  EXPECT_EQ(result.steps, 2u);
}

TEST(EngineLimits, TooManyDefinedInteractionsIsAnInputError) {
  const RunResult result = run_broadcast(40);
  EXPECT_EQ(result.code, kInputError);
  EXPECT_NE(result.message.find("connector 'c' defines more than 1048576 interactions"),
            std::string::npos)
      << result.message;
}

TEST(EngineLimits, MoreThan64PortsIsAnInputError) {
  const RunResult result = run_broadcast(64);
  EXPECT_EQ(result.code, kInputError);
  EXPECT_NE(result.message.find("more than 64 ports"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace smcbip::engines
