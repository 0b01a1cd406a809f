// Runs that reach an absorbing state (steps go on, none changes the places or data) end there
// with their verdict, as PRISM's simulator ends its paths, instead of running to the step limit
// or the formula's bound: on every engine, for formulas over places and data; formulas that read
// a clock still wait for their step limit. The probabilities are worked out in the models' headers;
// seeds are fixed and each bound holds with probability 0.99 (PESTIM at alpha 0.01).
#include <gtest/gtest.h>

#include "smc/smc.h"
#include "tests/smc/check_fixtures.h"

namespace smcbip::smc {
namespace {

std::vector<QueryResult> check_test_model(const std::string& file, const std::string& queries,
                                          const CheckOptions& options) {
  const bipc::ir::System& system = tests::model_in("tests/smc/models", file);
  return check_properties(system, tests::properties(queries, system), options);
}

CheckOptions short_runs(engines::EngineKind engine) {
  CheckOptions options;
  options.delta = 0.03;
  options.alpha = 0.01;
  options.seed = 5;
  options.threads = 2;
  options.engine = engine;
  // Far more steps than a run takes to its absorbing state, far fewer than it could loop
  // there: without the stop every losing run would end undecided at this limit.
  options.max_steps = 2'000;
  return options;
}

TEST(Absorbing, UntimedLotteryStopsInItsAbsorbingStatesOnEveryEngine) {
  for (const auto engine : {engines::EngineKind::Reference, engines::EngineKind::Optimised,
                            engines::EngineKind::Multithread}) {
    const auto results = check_test_model(
        "lottery.bip", "P=? [ F lottery.WON ]\nP=? [ !lottery.LOST U lottery.prize == 1 ]\n",
        short_runs(engine));
    ASSERT_EQ(results.size(), 2u);
    for (const QueryResult& r : results) {
      EXPECT_TRUE(r.error.empty()) << r.error;
      EXPECT_EQ(r.undecided, 0u);
      EXPECT_NEAR(r.estimate, 1.0 / 3.0, 0.03) << "engine " << static_cast<int>(engine);
    }
  }
}

TEST(Absorbing, BoundedFormulasAreDecidedInTheAbsorbingStatesOfLastingRuns) {
  // The step bounds lie beyond the step limit, so without the stop every losing run would end
  // undecided at the limit. Runs look for absorbing states after 1,000 steps, and from their
  // start once one has ended in one.
  for (const auto engine : {engines::EngineKind::Reference, engines::EngineKind::Optimised,
                            engines::EngineKind::Multithread}) {
    const auto results =
        check_test_model("lottery.bip",
                         "P=? [ F[#<=100000] lottery.WON ]\nPr[#<=100000](F lottery.WON)\n"
                         "Pr[#<=100000](G !lottery.WON)\n",
                         short_runs(engine));
    ASSERT_EQ(results.size(), 3u);
    for (const QueryResult& r : results) {
      EXPECT_TRUE(r.error.empty()) << r.error;
      EXPECT_EQ(r.undecided, 0u) << "engine " << static_cast<int>(engine);
    }
    EXPECT_NEAR(results[0].estimate, 1.0 / 3.0, 0.03);
    EXPECT_NEAR(results[1].estimate, 1.0 / 3.0, 0.03);
    EXPECT_NEAR(results[2].estimate, 2.0 / 3.0, 0.03);
  }
}

TEST(Absorbing, ARendezvousThatChangesNothingEndsTheRunOnEveryEngine) {
  // The first three steps change the counter (and the first the echo), so none of them may end
  // the run; the fourth keeps everything, and from there each run ends with its verdict.
  for (const auto engine : {engines::EngineKind::Reference, engines::EngineKind::Optimised,
                            engines::EngineKind::Multithread}) {
    const auto results = check_test_model("rendezvous_loop.bip",
                                          "P=? [ F counter.n == 3 ]\nP=? [ F counter.n == 4 ]\n",
                                          short_runs(engine));
    ASSERT_EQ(results.size(), 2u);
    for (const QueryResult& r : results) {
      EXPECT_TRUE(r.error.empty()) << r.error;
      EXPECT_EQ(r.undecided, 0u) << "engine " << static_cast<int>(engine);
    }
    EXPECT_EQ(results[0].estimate, 1.0);
    EXPECT_EQ(results[1].estimate, 0.0);
  }
}

TEST(Absorbing, DieWithSelfLoopsGivesEachFaceASixth) {
  const auto results = check_test_model(
      "die_self_loops.bip", "param k = {1, 2, 3, 4, 5, 6}\nP=? [ F die.s == 7 & die.d == k ]\n",
      short_runs(engines::EngineKind::Optimised));
  ASSERT_EQ(results.size(), 6u);
  for (const QueryResult& r : results) {
    EXPECT_EQ(r.undecided, 0u);
    EXPECT_NEAR(r.estimate, 1.0 / 6.0, 0.03) << "face " << r.parameters.at("k");
  }
}

TEST(Absorbing, FormulaOverAClockIsNotDecidedByTheLoops) {
  // The loops at s = 7 reset x (mean 0.5 ms apart), so x > 50 has probability e^-100 per loop:
  // the formula is false on every run, but no finite run shows it. Read as a deadlock (x
  // growing forever), the state would wrongly make it true.
  CheckOptions options = short_runs(engines::EngineKind::Optimised);
  options.delta = 0.1;
  options.undecided = UndecidedPolicy::Fail;
  const auto results =
      check_test_model("die_self_loops.bip", "P=? [ F die.s == 7 & die.x > 50 ]\n", options);
  ASSERT_EQ(results.size(), 1u);
  // Under Fail the undecided runs count as false samples.
  EXPECT_EQ(results[0].undecided, results[0].samples);
  EXPECT_EQ(results[0].why_undecided.limit, results[0].undecided);
  EXPECT_EQ(results[0].estimate, 0);
}

}  // namespace
}  // namespace smcbip::smc
