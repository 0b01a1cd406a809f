// Generated C++ of random models runs like the interpreted model: the same traces for the same
// seeds on every engine. The models cover what tests/engines/random_model.h generates (data,
// guards, clocks and urgencies, priorities, hierarchy) beyond the hand-written ones.
#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>

#include "engines/engines.h"
#include "engines/stochastic/date_planner.h"
#include "random_models.h"
#include "run_trace.h"
#include "tests/engines/temp_model.h"

namespace smcbip::tests {
namespace {

using engines::EngineKind;

std::string trace_of(const engines::Model& model, EngineKind engine, std::uint64_t seed) {
  // Atoms fire on the multithread engine's threads whatever their work.
  return run_trace(model, engine, seed, 300, 0);
}

class GeneratedRandomCode : public ::testing::TestWithParam<GeneratedRandomModel> {};

TEST_P(GeneratedRandomCode, RunsLikeTheInterpretedModel) {
  const GeneratedRandomModel& generated = GetParam();
  const std::optional<bipc::ir::System> system = load_model(generated.file, "Root()");
  ASSERT_TRUE(system);
  const engines::InterpretedModel interpreted(*system);
  const engines::CompiledModel compiled(*system, generated.make_code);
  for (EngineKind engine :
       {EngineKind::Reference, EngineKind::Optimised, EngineKind::Multithread}) {
    for (std::uint64_t seed : {1, 2}) {
      const std::string expected = trace_of(interpreted, engine, seed);
      EXPECT_EQ(trace_of(compiled, engine, seed), expected)
          << "engine " << static_cast<int>(engine) << ", run seed " << seed;
    }
  }
}

// The comparison shows little on models that deadlock at once: most must run to the limit (a
// third of the seeds after 24, mostly rendezvous, where a deadlock or time-lock comes sooner).
TEST(GeneratedRandomModels, MostRunToTheLimit) {
  std::size_t lively = 0, rendezvous_lively = 0, models = 0, rendezvous = 0;
  for (const GeneratedRandomModel& generated : generated_random_models()) {
    const std::optional<bipc::ir::System> system = load_model(generated.file, "Root()");
    ASSERT_TRUE(system) << generated.file;
    const std::string trace =
        trace_of(engines::InterpretedModel(*system), EngineKind::Optimised, 1);
    const bool limit = trace.find("reached limit") != std::string::npos;
    if (generated.seed > 24) {
      ++rendezvous;
      rendezvous_lively += limit ? 1 : 0;
    } else {
      ++models;
      lively += limit ? 1 : 0;
    }
  }
  EXPECT_GE(3 * lively, 2 * models);
  EXPECT_GE(3 * rendezvous_lively, rendezvous);
}

// The seeds after 24 (tests/codegen/CMakeLists.txt) make the compiled step path's models: timed
// rendezvous (stochastic ones among them) and untimed broadcasts. Their runs on the optimised
// engine compare it with the interpreter.
TEST(GeneratedRandomModels, TheCompiledStepPathCoversTheLaterSeeds) {
  std::size_t covered = 0, stochastic = 0;
  for (const GeneratedRandomModel& generated : generated_random_models()) {
    if (generated.seed <= 24) continue;
    const std::optional<bipc::ir::System> system = load_model(generated.file, "Root()");
    ASSERT_TRUE(system) << generated.file;
    EXPECT_TRUE(has_compiled_steps(*system, generated.make_code)) << "seed " << generated.seed;
    ++covered;
    if (engines::has_stochastic_ports(*system)) ++stochastic;
  }
  EXPECT_EQ(covered, 18u);
  EXPECT_GE(stochastic, 4u);
}

INSTANTIATE_TEST_SUITE_P(Seeds, GeneratedRandomCode, ::testing::ValuesIn(generated_random_models()),
                         [](const auto& info) {
                           return "seed_" + std::to_string(info.param.seed);
                         });

}  // namespace
}  // namespace smcbip::tests
