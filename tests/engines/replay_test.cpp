// `--replay`: a recorded run replays to the same states on every engine, a connector named
// without its interaction is followed only as far as the recorded states agree, and bad lines
// are refused at their place.
#include "engines/api/replay.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "engines/engines.h"

namespace smcbip::tests {
namespace {

bipc::ir::System family_model(const std::string& name) {
  const auto file = std::filesystem::path(SMCBIP_SOURCE_DIR) / "models/families" / name;
  bipc::FrontendResult result = bipc::run_frontend({file.string(), {}, "Top()"}, true);
  EXPECT_TRUE(result.system) << result.diags.format(result.model.files);
  return result.system ? std::move(*result.system) : bipc::ir::System{};
}

/// The lines of a JSON-lines trace, without the header (its seed differs) and the end line.
std::vector<std::string> state_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("{\"step\"", 0) == 0) out.push_back(line);
  }
  return out;
}

std::string recorded_run(const bipc::ir::System& system, engines::SimulateOptions options) {
  options.trace = engines::TraceFormat::Jsonl;
  std::ostringstream out;
  engines::simulate(system, options, engines::Externs::with_builtins(), out);
  return out.str();
}

engines::RunResult replay(const bipc::ir::System& system, const std::string& trace,
                          engines::SimulateOptions options, std::string& lines) {
  std::istringstream in(trace);
  const engines::ReplayScript script = engines::read_replay_script(in, "run.jsonl");
  options.trace = engines::TraceFormat::Jsonl;
  options.seed = 99;  // the trace chooses: the seed must not matter
  engines::Simulator simulator(system, options, engines::Externs::with_builtins());
  std::ostringstream out, model;
  const engines::RunResult result = simulator.replay(script, {out, model, nullptr});
  lines = out.str();
  return result;
}

TEST(Replay, EveryEngineReplaysItsOwnRunToTheSameStates) {
  const bipc::ir::System system = family_model("rendezvous_10.bip");
  for (engines::EngineKind engine : {engines::EngineKind::Reference, engines::EngineKind::Optimised,
                                     engines::EngineKind::Multithread}) {
    engines::SimulateOptions options;
    options.engine = engine;
    options.seed = 7;
    options.limit = 30;
    const std::string trace = recorded_run(system, options);
    options.limit.reset();
    std::string lines;
    const engines::RunResult result = replay(system, trace, options, lines);
    EXPECT_EQ(result.code, engines::kRunOk) << result.where << ": " << result.message;
    EXPECT_EQ(result.steps, 30u);
    ASSERT_EQ(state_lines(trace).size(), 31u);
    EXPECT_EQ(state_lines(lines), state_lines(trace)) << static_cast<int>(engine);
  }
}

TEST(Replay, AConnectorNamedWithoutItsInteractionIsCheckedByTheRecordedState) {
  // Without maximal progress the broadcast offers every subset of its receivers, all named
  // ROOT.all: the replay takes the first enabled one, and the recorded data tell whether it
  // was the one fired. Some of 10 random steps choose another subset.
  const bipc::ir::System system = family_model("broadcast_10.bip");
  engines::SimulateOptions options;
  options.disable_maximal_progress = true;
  options.seed = 3;
  options.limit = 10;
  const std::string trace = recorded_run(system, options);
  options.limit.reset();
  std::string lines;
  const engines::RunResult result = replay(system, trace, options, lines);
  EXPECT_EQ(result.code, engines::kInputError);
  EXPECT_NE(result.message.find("the state differs from the trace's: ROOT.rcv"), std::string::npos)
      << result.message;
  EXPECT_EQ(result.where.rfind("run.jsonl:", 0), 0u) << result.where;
}

TEST(Replay, AnInteractionNotEnabledIsRefusedAtItsLine) {
  const bipc::ir::System system = family_model("rendezvous_10.bip");
  engines::SimulateOptions options;
  options.seed = 7;
  options.limit = 3;
  std::string trace = recorded_run(system, options);
  const std::size_t second = trace.find("\"step\":2");
  ASSERT_NE(second, std::string::npos);
  const std::size_t fired = trace.find("\"fired\":\"", second) + 9;
  trace.replace(fired, trace.find('"', fired) - fired, "ROOT.nowhere");
  std::string lines;
  const engines::RunResult result = replay(system, trace, options, lines);
  EXPECT_EQ(result.code, engines::kInputError);
  EXPECT_EQ(result.where, "run.jsonl:4");  // the header, steps 0 and 1, then step 2
  EXPECT_EQ(result.message.rfind("step 2: interaction ROOT.nowhere is not enabled; enabled: ", 0),
            0u)
      << result.message;
  EXPECT_EQ(result.steps, 1u);
}

TEST(Replay, MalformedLinesAreRefusedAtTheirLine) {
  const auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      engines::read_replay_script(in, "t.jsonl");
    } catch (const engines::ReplayError& e) {
      return e.where + ": " + e.what();
    }
    return std::string("read");
  };
  const std::string step0 = "{\"step\":0,\"fired\":null,\"places\":{},\"data\":{}}\n";
  EXPECT_EQ(error_of(step0 + "{\"step\":1,\n").rfind("t.jsonl:2: not a JSON object", 0), 0u);
  EXPECT_EQ(error_of(step0 + "{\"step\":2,\"fired\":\"ROOT.c\"}\n"), "t.jsonl:2: expected step 1");
  EXPECT_EQ(error_of(step0 + "{\"step\":1}\n"), "t.jsonl:2: step 1 names no fired interaction");
  EXPECT_EQ(error_of(step0 + "{\"end\":\"deadlock\"}\n" + step0),
            "t.jsonl:3: a line after the trace's end");
  EXPECT_EQ(error_of("{\"header\":{}}\n"), "t.jsonl: the trace has no state");
  EXPECT_EQ(error_of(step0), "read");
}

}  // namespace
}  // namespace smcbip::tests
