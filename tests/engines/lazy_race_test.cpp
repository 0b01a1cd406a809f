// The stochastic race on the compiled step path when every offer is lazy and holds at all dates
// (FlatTables::lazy_unbounded): one pass renews the plans and finds the earliest date, and a tie
// is broken afterwards with the scheduler's draws. The optimised engine (the step path) must make
// the reference engine's runs (its scheduler) step for step, on a model whose dates tie often:
// exponential delays of a few ns, rounded up to whole nanoseconds, so that most dates lie
// 1 ns ahead.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "bipc/bipc.h"
#include "engines/engines.h"
#include "engines/semantics/flat_tables.h"
#include "engines/semantics/layout.h"
#include "temp_model.h"

namespace smcbip::engines {
namespace {

// Three walkers; `up` keeps its clock running (a newly enabled `up` draws truncated at the
// clock's value), `down` resets it and draws from a mean given by a parameter (a distribution
// made for each draw), `rest` has no @stochastic port (the planner's exponential of 1 ms);
// `meet` joins two walkers in a rendezvous whose date the stochastic port of one side draws.
constexpr const char* kTiesModel = R"(package ties
  port type P()
  connector type Pair(P a, P b)
    define a b
  end
  atom type Walker(int m)
    data int n
    clock x unit nanosecond
    @stochastic(dist="exponential", clk=x, param="1")
    port P up()
    @stochastic(dist="exponential", clk=x, param="m")
    port P down()
    @stochastic(dist="exponential", clk=x, param="1")
    export port P meet()
    export port P greet()
    port P rest()
    place S
    initial to S do { n = 0; x = 0; }
    on up from S to S provided (n < m) do { n = n + 1; }
    on down from S to S provided (n > 0) do { n = n - 1; x = 0; }
    on meet from S to S provided (n == 1) do { n = 0; }
    on greet from S to S provided (n == 2) do { n = 0; x = 0; }
    on rest from S to S provided (n == 0) do { x = 0; }
  end
  compound type Root()
    component Walker a(3)
    component Walker b(2)
    component Walker c(4)
    connector Pair ab(a.meet, b.greet)
    connector Pair bc(b.greet, c.meet)
  end
end
)";

using Step =
    std::tuple<TimeValue, StepInfo::Fired, bipc::ir::Index, bipc::ir::Index, bipc::ir::Index>;

class StepRecorder : public RunObserver {
 public:
  bool observe(const StepInfo& step, const StateView& /*state*/) override {
    if (step.fired != StepInfo::Fired::Nothing) {
      steps.emplace_back(step.time, step.fired, step.connector, step.atom, step.port);
    }
    return true;
  }
  std::vector<Step> steps;
};

std::vector<std::vector<Step>> runs_on(const bipc::ir::System& system, EngineKind engine) {
  SimulateOptions options;
  options.engine = engine;
  options.seed = 20261127;
  options.silent = true;
  options.limit = 60;
  Simulator simulator(system, options, Externs::with_builtins());
  EXPECT_TRUE(simulator.stochastic());
  std::ostringstream sink;
  std::vector<std::vector<Step>> runs;
  for (std::uint64_t run = 0; run < 300; ++run) {
    StepRecorder recorder;
    const RunResult result = simulator.run(run, RunStreams{sink, sink}, &recorder);
    EXPECT_EQ(result.code, kRunOk) << result.message;
    runs.push_back(std::move(recorder.steps));
  }
  return runs;
}

/// Code that compiles every atom type, as the interpreted step path's does: all flat_tables
/// asks of it. Nothing runs.
class EveryTypeCompiled final : public ModelCode {
 public:
  Val evaluate(const bipc::ir::Code& /*code*/, const Frame& /*frame*/) override { return {}; }
  void execute(const bipc::ir::Code& /*code*/, const Frame& /*frame*/) override {}
  Interval holds_when(const bipc::ir::Code& /*code*/, const Frame& /*frame*/) override {
    return Interval::all();
  }
  bool compiles_atom_type(bipc::ir::Index /*type*/) const override { return true; }
};

std::optional<bool> lazy_unbounded(const std::string& text) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(text, "Root()");
  if (!system) return std::nullopt;
  Layout layout;
  EXPECT_EQ(build_layout(*system, layout), "");
  EveryTypeCompiled code;
  const std::optional<FlatTables> tables = flat_tables(*system, layout, code);
  if (!tables) return std::nullopt;
  return tables->lazy_unbounded;
}

/// kTiesModel with its first occurrence of `from` replaced by `to`.
std::string ties_model_with(const std::string& from, const std::string& to) {
  std::string text = kTiesModel;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(LazyRace, OnlyModelsWhoseOffersAreLazyAtAllDates) {
  EXPECT_EQ(lazy_unbounded(kTiesModel), std::optional<bool>(true));
  // A guard over a clock, and a transition that is not lazy.
  EXPECT_EQ(lazy_unbounded(ties_model_with("(n < m)", "(n < m && x < 5)")),
            std::optional<bool>(false));
  EXPECT_EQ(lazy_unbounded(ties_model_with("(n > 0) do", "(n > 0) delayable do")),
            std::optional<bool>(false));
}

TEST(LazyRace, TheStepPathMakesTheSchedulersRunsThroughTies) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(kTiesModel, "Root()");
  ASSERT_TRUE(system);
  const std::vector<std::vector<Step>> reference = runs_on(*system, EngineKind::Reference);
  const std::vector<std::vector<Step>> optimised = runs_on(*system, EngineKind::Optimised);
  ASSERT_EQ(reference.size(), optimised.size());
  std::size_t steps = 0, tied = 0;
  for (std::size_t r = 0; r < reference.size(); ++r) {
    ASSERT_EQ(reference[r], optimised[r]) << "run " << r;
    TimeValue last = 0;
    for (const Step& step : reference[r]) {
      tied += std::get<0>(step) == last ? 1 : 0;
      last = std::get<0>(step);
    }
    steps += reference[r].size();
  }
  // A drawn date lies at least 1 ns ahead: a step at the date of the step before fires the
  // loser of a tie, whose plan was kept. Every run makes its 60 steps.
  EXPECT_EQ(steps, 300u * 60u);
  EXPECT_GT(tied, steps / 10) << tied << " of " << steps;
}

}  // namespace
}  // namespace smcbip::engines
