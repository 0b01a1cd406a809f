// Generated C++ of random models runs like the interpreted model: the same traces for the same
// seeds on every engine. The models cover what tests/engines/random_model.h generates (data,
// guards, clocks and urgencies, priorities, hierarchy) beyond the hand-written ones.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "engines/engines.h"
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

// The comparison shows little on models that deadlock at once: most must run to the limit.
TEST(GeneratedRandomModels, MostRunToTheLimit) {
  std::size_t lively = 0;
  for (const GeneratedRandomModel& generated : generated_random_models()) {
    const std::optional<bipc::ir::System> system = load_model(generated.file, "Root()");
    ASSERT_TRUE(system) << generated.file;
    const std::string trace =
        trace_of(engines::InterpretedModel(*system), EngineKind::Optimised, 1);
    if (trace.find("reached limit") != std::string::npos) ++lively;
  }
  EXPECT_GE(3 * lively, 2 * generated_random_models().size());
}

INSTANTIATE_TEST_SUITE_P(Seeds, GeneratedRandomCode, ::testing::ValuesIn(generated_random_models()),
                         [](const auto& info) {
                           return "seed_" + std::to_string(info.param.seed);
                         });

}  // namespace
}  // namespace smcbip::tests
