// Generated C++ runs like the interpreted model: the same traces for the same seeds on every
// engine, for every model of models/ (generated at build time by bipc gen).
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "bipc/ir/ir_data.h"
#include "bipc/ir/model_hash.h"
#include "engines/engines.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/flat_tables.h"
#include "engines/semantics/layout.h"
#include "generated_models.h"
#include "run_trace.h"
#include "tests/engines/temp_model.h"

namespace smcbip::tests {
namespace {

using engines::EngineKind;

/// Counts the calls into a model's code, so that a test knows which code ran.
class CountingCode final : public engines::ModelCode {
 public:
  CountingCode(std::unique_ptr<engines::ModelCode> inner, int& calls)
      : inner_(std::move(inner)), calls_(calls) {}
  engines::Val evaluate(const bipc::ir::Code& code, const engines::Frame& f) override {
    ++calls_;
    return inner_->evaluate(code, f);
  }
  void execute(const bipc::ir::Code& code, const engines::Frame& f) override {
    ++calls_;
    inner_->execute(code, f);
  }
  engines::Interval holds_when(const bipc::ir::Code& code, const engines::Frame& f) override {
    ++calls_;
    return inner_->holds_when(code, f);
  }

 private:
  std::unique_ptr<engines::ModelCode> inner_;
  int& calls_;
};

std::string trace_of(const engines::Model& model, EngineKind engine, std::uint64_t seed) {
  return run_trace(model, engine, seed, 400);
}

/// The model's file: in the source tree, or (a model the build makes) where the build put it.
std::string model_file(const GeneratedModel& generated) {
  const std::string file = generated.file;
  return !file.empty() && file.front() == '/' ? file : std::string(SMCBIP_SOURCE_DIR) + "/" + file;
}

class GeneratedCode : public ::testing::TestWithParam<GeneratedModel> {};

TEST_P(GeneratedCode, RunsLikeTheInterpretedModel) {
  const GeneratedModel& generated = GetParam();
  const std::optional<bipc::ir::System> system = load_model(model_file(generated), generated.root);
  ASSERT_TRUE(system);
  const engines::InterpretedModel interpreted(*system);
  const engines::CompiledModel compiled(*system, generated.make_code);
  for (EngineKind engine :
       {EngineKind::Reference, EngineKind::Optimised, EngineKind::Multithread}) {
    for (std::uint64_t seed : {1, 2, 3}) {
      const std::string expected = trace_of(interpreted, engine, seed);
      EXPECT_EQ(trace_of(compiled, engine, seed), expected)
          << generated.name << ", engine " << static_cast<int>(engine) << ", seed " << seed;
    }
  }
}

TEST_P(GeneratedCode, EmbedsItsModelAndIdentity) {
  const GeneratedModel& generated = GetParam();
  const std::optional<bipc::ir::System> system = load_model(model_file(generated), generated.root);
  ASSERT_TRUE(system);
  EXPECT_EQ(bipc::ir::to_data(generated.system()), bipc::ir::to_data(*system));
  EXPECT_EQ(&generated.model().system(), &generated.system());
  EXPECT_EQ(generated.hash,
            bipc::ir::model_hash(*system, bipc::ir::extern_sources_of(*system, {})));
  // The embedded model alone (no front end) runs as the interpreted one.
  const engines::InterpretedModel interpreted(*system);
  EXPECT_EQ(trace_of(generated.model(), EngineKind::Optimised, 7),
            trace_of(interpreted, EngineKind::Optimised, 7));
}

TEST_P(GeneratedCode, ItsOwnCodeRuns) {
  const GeneratedModel& generated = GetParam();
  const std::optional<bipc::ir::System> system = load_model(model_file(generated), generated.root);
  ASSERT_TRUE(system);
  // The generated code answers only the Code of its own numbering: anything else is a fault,
  // not a silent fall back on an interpreter.
  int calls = 0;
  engines::StringPool strings;
  std::ostringstream out;
  engines::CallContext call{out, strings};
  engines::BoundFunctions functions;
  ASSERT_EQ(engines::bind_functions(*system, engines::Externs::with_builtins(), strings, functions),
            "");
  CountingCode code(generated.make_code(*system, functions, call, nullptr), calls);
  bipc::ir::Code foreign;
  foreign.instrs.emplace_back();    // push.int 0
  foreign.id = system->code_count;  // beyond the model's numbering
  engines::Frame frame;
  EXPECT_THROW(code.evaluate(foreign, frame), engines::CodeFault);
  EXPECT_THROW(code.execute(foreign, frame), engines::CodeFault);
  EXPECT_EQ(calls, 2);
}

// The runs above compare the compiled step path with the interpreter only where it is taken:
// these are the models it covers (rendezvous, untimed, timed or stochastic, and untimed
// broadcasts), the others it must leave alone.
TEST(CompiledSteps, CoverTheRendezvousModels) {
  std::set<std::string> covered;
  for (const GeneratedModel& generated : generated_models()) {
    if (has_compiled_steps(generated.system(), generated.make_code)) covered.insert(generated.name);
  }
  const std::set<std::string> expected = {"broadcast_10",
                                          "chain_10",
                                          "channel",
                                          "hub",
                                          "late_division",
                                          "late_mixed_urgency",
                                          "late_nondeterminism",
                                          "late_unsafe",
                                          "rendezvous_10",
                                          "work_10"};
  EXPECT_EQ(covered, expected);
}

// A step recomputes the positions listed for the position it fired, merged from its atoms'
// neighbours, unless those lists would be far larger than the atoms' own (the hub, in 300
// connectors): the runs above compare both ways with the interpreter.
TEST(CompiledSteps, ListAffectedPositionsUnlessTooMany) {
  std::map<std::string, std::size_t> affected;
  for (const GeneratedModel& generated : generated_models()) {
    const std::string name = generated.name;
    if (name != "hub" && name != "channel") continue;
    ASSERT_TRUE(with_generated_code(generated.system(), generated.make_code,
                                    [&](const engines::Layout& layout, engines::ModelCode& code) {
                                      const std::optional<engines::FlatTables> tables =
                                          engines::flat_tables(generated.system(), layout, code);
                                      ASSERT_TRUE(tables);
                                      affected[name] = tables->affected.size();
                                      EXPECT_EQ(tables->first_affected.empty(),
                                                tables->affected.empty());
                                    }));
  }
  ASSERT_EQ(affected.size(), 2u);
  EXPECT_EQ(affected["hub"], 0u);
  // Channel: the 5 connectors of the channel atom, with the receiver's internal port (6)
  // when they bind the receiver (deliver, ack_back, loss): 5 + 6 + 6 + 5 + 6, and the internal
  // port's own, the receiver's 4.
  EXPECT_EQ(affected["channel"], 32u);
}

INSTANTIATE_TEST_SUITE_P(Models, GeneratedCode, ::testing::ValuesIn(generated_models()),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace smcbip::tests
