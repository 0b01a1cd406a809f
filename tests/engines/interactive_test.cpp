// `--interactive`: the person's choices drive the run, bad answers are asked again, `q` stops.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "bipc/bipc.h"
#include "engines/engines.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

bipc::ir::System rendezvous_model() {
  const auto file = std::filesystem::path(SMCBIP_SOURCE_DIR) / "models/families/rendezvous_10.bip";
  bipc::FrontendResult result = bipc::run_frontend({file.string(), {}, "Top()"}, true);
  EXPECT_TRUE(result.system) << result.diags.format(result.model.files);
  return result.system ? std::move(*result.system) : bipc::ir::System{};
}

engines::RunResult run_with_answers(const std::string& answers, std::string& text) {
  engines::SimulateOptions options;
  options.seed = 1;
  options.interactive = true;
  std::istringstream input(answers);
  std::ostringstream out;
  const engines::RunResult result = engines::simulate(
      rendezvous_model(), options, engines::Externs::with_builtins(), out, &input);
  text = out.str();
  return result;
}

TEST(Interactive, AnswersChooseTheItemsUntilQuit) {
  std::string text;
  const engines::RunResult result = run_with_answers("1\n0\nq\n", text);
  EXPECT_EQ(result.code, engines::kRunOk);
  EXPECT_EQ(result.end, engines::RunEnd::Stopped);
  EXPECT_EQ(result.steps, 2u);
  const Lines lines = split_lines(text);
  const Lines chosen = choose_lines(lines);
  ASSERT_EQ(chosen.size(), 2u) << text;
  EXPECT_NE(chosen[0].find("-> choose [1] "), std::string::npos) << chosen[0];
  EXPECT_NE(chosen[1].find("-> choose [0] "), std::string::npos) << chosen[1];
}

TEST(Interactive, BadAnswersAreAskedAgainAndTheEndOfInputStops) {
  std::string text;
  const engines::RunResult result = run_with_answers("x\n999\n-1\n0\n", text);
  EXPECT_EQ(result.end, engines::RunEnd::Stopped);
  EXPECT_EQ(result.steps, 1u);
  EXPECT_NE(text.find("'x' is not a number between 0 and"), std::string::npos) << text;
  EXPECT_NE(text.find("'999' is not a number between 0 and"), std::string::npos) << text;
}

}  // namespace
}  // namespace smcbip::tests
