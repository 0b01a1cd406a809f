// smc::check_properties on models whose probabilities are known: the race of two exponentials
// (models/two_exponentials.bip, worked out in its header), and the same answers for any
// number of threads on the Channel model. Seeds are fixed; each estimate's bound holds with the
// stated confidence, so a failure is a 1% event at most for a sound method.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "smc/smc.h"
#include "tests/engines/lock_model.h"
#include "tests/smc/check_fixtures.h"

namespace smcbip::smc {
namespace {

const bipc::ir::System& model(const std::string& file) { return tests::model_in("models", file); }

using tests::check;

TEST(Check, EstimatesTheRaceOfTwoExponentials) {
  CheckOptions options;
  options.delta = 0.02;
  options.alpha = 0.01;  // PESTIM: 6,623 runs, within 0.02 with probability 0.99
  options.seed = 11;
  options.threads = 2;
  const auto results = check("two_exponentials.bip",
                             "P=? [ F judge.winner == 1 ]\n"
                             "P=? [ F[0,5] judge.CLOSED ]\n"
                             "P>=0.6 [ F judge.winner == 1 ]\n"
                             "P>=0.75 [ F judge.winner == 1 ]\n",
                             options);
  ASSERT_EQ(results.size(), 4u);
  EXPECT_EQ(results[0].samples, chernoff_samples(0.02, 0.01));
  EXPECT_NEAR(results[0].estimate, 2.0 / 3.0, 0.02);
  // The first firing is exponential of rate 1/10 + 1/20 per ms.
  EXPECT_NEAR(results[1].estimate, 1 - std::exp(-5 * (0.1 + 0.05)), 0.02);
  EXPECT_EQ(results[2].method, Method::Sprt);
  EXPECT_EQ(results[2].verdict, std::optional<bool>(true));
  EXPECT_EQ(results[3].verdict, std::optional<bool>(false));
  for (const QueryResult& r : results) EXPECT_EQ(r.undecided, 0u);
}

TEST(Check, EstimatesKnuthAndYaosDie) {
  // Each face has probability 1/6 (models/knuth_yao.bip): a fair coin is a race of two
  // exponentials, fair only if the flip that fired draws a new date for the next flip.
  CheckOptions options;
  options.delta = 0.02;
  options.alpha = 0.01;
  options.seed = 3;
  options.threads = 2;
  const auto results =
      check("knuth_yao.bip", "param k = {1, 2, 3, 4, 5, 6}\nP=? [ F (die.s == 7 && die.d == k) ]\n",
            options);
  ASSERT_EQ(results.size(), 6u);
  for (const QueryResult& r : results) {
    EXPECT_NEAR(r.estimate, 1.0 / 6.0, 0.02) << "face " << r.parameters.at("k");
    EXPECT_EQ(r.undecided, 0u);
  }
}

TEST(Check, EstimatesTheTandemQueueAsPrismDoes) {
  // models/tandem.bip is PRISM's and Ymer's tandem.sm (c = 7); PRISM computes 0.0999 for both
  // queues full within 26 time units. The sequential interval covers it with probability 0.99.
  CheckOptions options;
  options.method = Method::Ci;
  options.delta = 0.01;
  options.alpha = 0.01;
  options.seed = 17;
  options.threads = 2;
  const auto results =
      check("tandem.bip", "P=? [ F[0,26] (serverC.sc == 7 && serverM.sm == 7) ]\n", options);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_LE(results[0].ci.low, 0.0999);
  EXPECT_GE(results[0].ci.high, 0.0999);
  EXPECT_LE(results[0].ci.high - results[0].ci.low, 0.02);
}

/// The dates of a run's steps.
class Dates final : public engines::RunObserver {
 public:
  bool observe(const engines::StepInfo& step, const engines::StateView&) override {
    dates.push_back(step.time);
    return true;
  }
  std::vector<engines::TimeValue> dates;
};

TEST(Check, AFiredStochasticPortDrawsANewDate) {
  // The die's flips are self-loops of the same ports: each flip must come at a later date than
  // the one before (the dates are continuous), on the interpreter and the compiled step path.
  for (const engines::EngineKind engine :
       {engines::EngineKind::Reference, engines::EngineKind::Optimised}) {
    engines::SimulateOptions options;
    options.engine = engine;
    options.seed = 1;
    options.silent = true;
    engines::Simulator simulator(model("knuth_yao.bip"), options,
                                 engines::Externs::with_builtins());
    std::ostringstream sink;
    for (std::uint64_t run = 0; run < 50; ++run) {
      Dates dates;
      simulator.run(run, engines::RunStreams{sink, sink}, &dates);
      for (std::size_t i = 2; i < dates.dates.size(); ++i) {
        EXPECT_LT(dates.dates[i - 1], dates.dates[i]) << "run " << run << ", step " << i;
      }
    }
  }
}

TEST(Check, RunsOfOneSimulatorAreThoseOfFreshOnes) {
  // A simulator's later runs on the compiled step path start from a copy of its first run's
  // initial state: each must fire at the dates of the same run made by a new simulator, whose
  // run starts with the model's initial actions, and by the reference engine.
  const auto simulator = [](engines::EngineKind engine) {
    engines::SimulateOptions options;
    options.engine = engine;
    options.seed = 3;
    options.silent = true;
    options.limit = 300;  // the queues never empty for good: runs end at a step limit
    return std::make_unique<engines::Simulator>(model("tandem.bip"), options,
                                                engines::Externs::with_builtins());
  };
  const auto dates = [](engines::Simulator& simulator, std::uint64_t run) {
    std::ostringstream sink;
    Dates observed;
    simulator.run(run, engines::RunStreams{sink, sink}, &observed);
    return observed.dates;
  };
  const auto reused = simulator(engines::EngineKind::Optimised);
  for (std::uint64_t run = 0; run < 20; ++run) {
    const std::vector<engines::TimeValue> seen = dates(*reused, run);
    ASSERT_EQ(seen.size(), 301u) << "the initial state and 300 steps";
    EXPECT_EQ(seen, dates(*simulator(engines::EngineKind::Optimised), run)) << "run " << run;
    EXPECT_EQ(seen, dates(*simulator(engines::EngineKind::Reference), run)) << "run " << run;
  }
}

TEST(Check, ThreadCountsGiveTheSameAnswers) {
  const std::string queries =
      "P>=0.3 [ F[0,100] Channel.lost > 0 ]\n"
      "P=? [ F[0,100] Channel.lost > 0 ]\n"
      "E[<=500; 50](max: Sender.sent)\n";
  for (const Method method : {Method::Sprt, Method::Ci, Method::Bayes}) {
    CheckOptions options;
    options.method = method;
    options.delta = 0.03;
    options.seed = 5;
    options.threads = 1;
    const auto one = check("channel.bip", queries, options);
    for (const unsigned threads : {2u, 3u}) {
      options.threads = threads;
      const auto more = check("channel.bip", queries, options);
      ASSERT_EQ(more.size(), one.size());
      for (std::size_t i = 0; i < one.size(); ++i) {
        EXPECT_EQ(more[i].samples, one[i].samples) << method_name(method) << " " << threads;
        EXPECT_EQ(more[i].estimate, one[i].estimate);
        EXPECT_EQ(more[i].verdict, one[i].verdict);
      }
    }
  }
}

TEST(Check, RunsLeftUndecidedAreCountedAndReported) {
  // G over an unbounded time on runs cut after 20 steps: undecided unless a loss came first.
  CheckOptions options;
  options.max_steps = 20;
  options.threads = 1;
  const auto errors = check("channel.bip", "P=? [ G Channel.lost == 0 ]\n", options);
  EXPECT_FALSE(errors.at(0).error.empty());
  options.undecided = UndecidedPolicy::Fail;
  options.delta = 0.1;
  const auto failed = check("channel.bip", "P=? [ G Channel.lost == 0 ]\n", options);
  EXPECT_TRUE(failed.at(0).error.empty());
  EXPECT_EQ(failed.at(0).estimate, 0.0);
  EXPECT_GT(failed.at(0).undecided, failed.at(0).samples / 2);  // counted, as failures
}

TEST(Check, DeadlocksAndTimeLocksInsideABoundNeverHang) {
  // F[10,100] one.s1: a deadlocked run keeps s1 forever and holds; a time-locked one shows its
  // last state at time 3 only, before the window opens, and is undecided, never read as false.
  const std::optional<bipc::ir::System> system =
      smcbip::tests::load_model_text(smcbip::tests::kDeadlockOrTimeLock, "Top()");
  ASSERT_TRUE(system);
  const monitors::PropertyFile file = tests::properties("P=? [ F[10,100] one.s1 ]\n", *system);
  CheckOptions options;
  options.delta = 0.05;
  options.threads = 2;
  options.undecided = UndecidedPolicy::Skip;
  const QueryResult skipped = check_properties(*system, file, options).at(0);
  EXPECT_EQ(skipped.estimate, 1.0);
  EXPECT_EQ(skipped.samples, chernoff_samples(0.05, 0.05));
  EXPECT_GT(skipped.undecided, skipped.samples / 4);
  options.undecided = UndecidedPolicy::Fail;
  const QueryResult failed = check_properties(*system, file, options).at(0);
  EXPECT_LT(failed.estimate, 0.75);
  EXPECT_GT(failed.estimate, 0.25);
  options.undecided = UndecidedPolicy::Error;
  EXPECT_NE(check_properties(*system, file, options).at(0).error.find("undecided"),
            std::string::npos);
}

TEST(Check, ATimeLockHoldsInTheLastStateOfItsRun) {
  // Each run deadlocks in s1 or time-locks in s2 at 3 ms. timelock holds in the last state of
  // the time-locked runs, which decides F timelock and G !timelock on them; on the deadlocked
  // runs it never holds. So both are decided on every run and, on the same runs, sum to 1
  // (about half each). F deadlock is undecided on the time-locked runs (what follows their last
  // instant is unknown) and holds on the others.
  const std::optional<bipc::ir::System> system =
      smcbip::tests::load_model_text(smcbip::tests::kDeadlockOrTimeLock, "Top()");
  ASSERT_TRUE(system);
  const monitors::PropertyFile file = tests::properties(
      "P=? [ F[0,100] timelock ]\nP=? [ G[0,100] !timelock ]\nP=? [ F deadlock ]\n", *system);
  CheckOptions options;
  options.delta = 0.05;
  options.threads = 2;
  options.undecided = UndecidedPolicy::Skip;
  const std::vector<QueryResult> results = check_properties(*system, file, options);
  ASSERT_EQ(results.size(), 3u);
  for (const QueryResult& r : results) {
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.samples, chernoff_samples(0.05, 0.05));
  }
  EXPECT_EQ(results[0].undecided + results[1].undecided, 0u);
  EXPECT_GT(results[0].estimate, 0.25);
  EXPECT_LT(results[0].estimate, 0.75);
  EXPECT_DOUBLE_EQ(results[0].estimate + results[1].estimate, 1.0);
  EXPECT_EQ(results[2].estimate, 1.0);
  EXPECT_GT(results[2].undecided, results[2].samples / 4);
}

TEST(Check, SkippingUndecidedRunsGivesUpInsteadOfDrawingForever) {
  // Every run is cut at 5 steps, long before 1000 ms: --undecided skip gave no answer and never
  // stopped. Expectations and probabilities count such runs alike (the expectation counted
  // them as complete runs), and say how they ended.
  CheckOptions options;
  options.max_steps = 5;
  options.threads = 2;
  options.undecided = UndecidedPolicy::Skip;
  const auto results = check("channel.bip",
                             "E[<=1000; 20](max: Sender.sent)\n"
                             "P=? [ G[0,1000] Sender.sent >= 0 ]\n",
                             options);
  ASSERT_EQ(results.size(), 2u);
  for (const QueryResult& r : results) {
    EXPECT_EQ(r.samples, 0u);
    EXPECT_EQ(r.undecided, kMaxSkippedRuns);
    EXPECT_EQ(r.why_undecided.limit, kMaxSkippedRuns);
    EXPECT_EQ(r.error.rfind("gave up after 1000 undecided runs against 0 decided", 0), 0u)
        << r.error;
    EXPECT_NE(r.error.find("cut at the step limit (--max-steps 5)"), std::string::npos);
  }
  options.undecided = UndecidedPolicy::Error;
  for (const QueryResult& r : check("channel.bip", "E[<=1000; 20](max: Sender.sent)\n", options)) {
    EXPECT_EQ(r.undecided, 11u);
    EXPECT_EQ(r.error.rfind("11 of 11 runs undecided", 0), 0u) << r.error;
  }
  // fail cannot count a run without a value as false: the expectation gives up.
  options.undecided = UndecidedPolicy::Fail;
  const QueryResult failed = check("channel.bip", "E[<=1000; 20](max: Sender.sent)\n", options)[0];
  EXPECT_NE(failed.error.find("an expectation has no value"), std::string::npos) << failed.error;
  // Runs that reach the bound are complete, with or without the step limit.
  options.max_steps = 1'000'000;
  const QueryResult complete = check("channel.bip", "E[<=100; 20](max: Sender.sent)\n", options)[0];
  EXPECT_TRUE(complete.error.empty()) << complete.error;
  EXPECT_EQ(complete.samples, 20u);
  EXPECT_EQ(complete.undecided, 0u);
}

}  // namespace
}  // namespace smcbip::smc
