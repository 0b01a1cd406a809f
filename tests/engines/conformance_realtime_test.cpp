// The BIP conformance oracles (bip-conformance/EXPECTED.md sections 6 and 8) that take wall-clock
// time: runs with --real-time, and models that call sleep/usleep. A separate executable
// labelled `slow`; each oracle runs once (seed 1) per engine.
#include <gtest/gtest.h>

#include <string>

#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::kRunOk;

template <class Engine>
class ConformanceRealTime : public ConformanceFixture<Engine> {
 protected:
  /// Options of a --real-time run on this engine.
  static engines::SimulateOptions real_time() {
    engines::SimulateOptions options = ConformanceFixture<Engine>::options();
    options.real_time = true;
    return options;
  }
};
TYPED_TEST_SUITE(ConformanceRealTime, AllModels, EngineNames);

/// Wall-clock runs are costly: one seed each.
constexpr std::uint64_t kOneSeed = 1;

TYPED_TEST(ConformanceRealTime, R01_writers_buffer) {
  auto options = this->real_time();
  options.silent = true;
  this->check_runs("running/writers_buffer", "Compound()", options, kOneSeed, [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    std::size_t total = 0;
    for (int k = 0; k <= 9; ++k) {
      const std::size_t n = count(run.lines, "New value: " + std::to_string(k));
      // The reading of EXPECTED.md: W1's values 0..9, each once.
      EXPECT_EQ(n, 1u) << "New value: " << k;
      total += n;
    }
    EXPECT_EQ(total, 10u);  // the original check
  });
}

// ---- test_resume* (R08-R15): run a is simulated but sleeps; run b is --real-time ---------

TYPED_TEST(ConformanceRealTime, R08_test_resume_run_b) {
  this->check_runs("running/test_resume", "Compound()", this->real_time(), kOneSeed,
                   [](const auto& run) {
                     EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
                     EXPECT_TRUE(has(run.lines, "choose.*A.p1.*global time 5s$"));
                     EXPECT_EQ(state_header(run.lines, 1), "1 internal port:");
                     EXPECT_TRUE(has(run.lines, "choose.*A.p2"));
                     EXPECT_EQ(state_header(run.lines, 2), "deadlock!");
                   });
}

// Intended facts; the original script skipped its assertion whenever a grep failed.
TYPED_TEST(ConformanceRealTime, R09_test_resume2) {
  this->check_runs("running/test_resume2", "Compound()", this->real_time(), kOneSeed,
                   [](const auto& run) {
                     EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
                     EXPECT_TRUE(has(run.lines, "choose.*A.p1.*global time 1s$"));
                     EXPECT_EQ(state_header(run.lines, 1), "1 internal port:");
                     EXPECT_TRUE(has(run.lines, "choose.*B.p1.*global time 5s$"));
                     EXPECT_EQ(state_header(run.lines, 2), "deadlock!");
                   });
}

/// R10 and R11 share their first two steps: A.i at 1s, then C1.
void expect_resume3_start(const ConformanceRun& run, bool c1_time_checked) {
  EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
  EXPECT_TRUE(has(run.lines, "choose.*A.i.*global time 1s$"));
  EXPECT_EQ(state_header(run.lines, 1), "1 interaction:");
  EXPECT_TRUE(has(run.lines, c1_time_checked ? "choose.*C1.*A.p.*B.p.*global time 1s$"
                                             : "choose.*C1.*A.p.*B.p.*"));
}

TYPED_TEST(ConformanceRealTime, R10_test_resume3_run_a) {
  this->check_runs("running/test_resume3", "Compound()", this->options(), kOneSeed,
                   [](const auto& run) {
                     expect_resume3_start(run, true);
                     EXPECT_EQ(state_header(run.lines, 2), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "choose.*C2.*A.p.*C.p.*global time 6s$"));
                     EXPECT_EQ(state_header(run.lines, 3), "deadlock!");
                   });
}

TYPED_TEST(ConformanceRealTime, R10_test_resume3_run_b) {
  this->check_runs("running/test_resume3", "Compound()", this->real_time(), kOneSeed,
                   [](const auto& run) {
                     expect_resume3_start(run, false);
                     EXPECT_EQ(state_header(run.lines, 2), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "choose.*C2.*A.p.*C.p.*global time 6s$"));
                     EXPECT_EQ(state_header(run.lines, 3), "deadlock!");
                   });
}

TYPED_TEST(ConformanceRealTime, R11_test_resume3_error_run_a) {
  this->check_runs("running/test_resume3_error", "Compound()", this->options(), kOneSeed,
                   [](const auto& run) {
                     expect_resume3_start(run, true);
                     EXPECT_EQ(state_header(run.lines, 2), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "choose.*C2.*A.p.*C.p.*global time 4s$"));
                     EXPECT_EQ(state_header(run.lines, 3), "deadlock!");
                   });
}

TYPED_TEST(ConformanceRealTime, R11_test_resume3_error_run_b) {
  this->check_runs("running/test_resume3_error", "Compound()", this->real_time(), kOneSeed,
                   [](const auto& run) {
                     expect_run_error(run, engines::kTimeSafetyViolation);
                     expect_resume3_start(run, false);
                     EXPECT_TRUE(has(run.lines, "state #2.*:.*violation.*timing constraint"));
                     EXPECT_TRUE(has(run.lines, "C2.*A.p.*C.p.*4s.*+INFTY"));
                   });
}

TYPED_TEST(ConformanceRealTime, R12_test_resume4_run_b) {
  this->check_runs("running/test_resume4", "Compound()", this->real_time(), kOneSeed,
                   [](const auto& run) {
                     EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
                     EXPECT_TRUE(has(run.lines, "choose.*A.p"));
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                   });
}

TYPED_TEST(ConformanceRealTime, R13_test_resume4_error_run_a) {
  this->check_runs("running/test_resume4_error", "Compound()", this->options(), kOneSeed,
                   [](const auto& run) {
                     EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
                     EXPECT_TRUE(has(run.lines, "choose.*A.p.*global time 0$"));
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                   });
}

// The exit code is not checked by the original (by design the engine exits 7 here).
TYPED_TEST(ConformanceRealTime, R13_test_resume4_error_run_b) {
  this->check_runs("running/test_resume4_error", "Compound()", this->real_time(), kOneSeed,
                   [](const auto& run) {
                     EXPECT_TRUE(has(run.lines, "state #0.*:.*violation.*timing constraint"));
                     EXPECT_TRUE(has(run.lines, "A.*resume.*-INFTY.*2s"));
                   });
}

/// Run a of R14 and R15: A.p1 then A.p2, both at 5s, then a deadlock.
void expect_resume_two_steps(const ConformanceRun& run) {
  EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
  EXPECT_TRUE(has(run.lines, "choose.*A.p1.*global time 5s$"));
  EXPECT_EQ(state_header(run.lines, 1), "1 internal port:");
  EXPECT_TRUE(has(run.lines, "choose.*A.p2.*global time 5s$"));
  EXPECT_EQ(state_header(run.lines, 2), "deadlock!");
}

TYPED_TEST(ConformanceRealTime, R14_test_resume_deadlock_run_a) {
  this->check_runs("running/test_resume_deadlock", "Compound()", this->options(), kOneSeed,
                   expect_resume_two_steps);
}

TYPED_TEST(ConformanceRealTime, R14_test_resume_deadlock_run_b) {
  this->check_runs("running/test_resume_deadlock", "Compound()", this->real_time(), kOneSeed,
                   [](const auto& run) {
                     EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
                     EXPECT_TRUE(has(run.lines, "choose.*A.p1.*global time 5s$"));
                     // After the 8 s action A.p2's guard x <= 3 cannot hold: a deadlock.
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                   });
}

TYPED_TEST(ConformanceRealTime, R15_test_resume_error_run_a) {
  this->check_runs("running/test_resume_error", "Compound()", this->options(), kOneSeed,
                   expect_resume_two_steps);
}

// The intended facts; the original enforced only the exit code and the last pattern.
TYPED_TEST(ConformanceRealTime, R15_test_resume_error_run_b) {
  this->check_runs("running/test_resume_error", "Compound()", this->real_time(), kOneSeed,
                   [](const auto& run) {
                     expect_run_error(run, engines::kTimeSafetyViolation);
                     EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
                     EXPECT_TRUE(has(run.lines, "choose.*A.p1.*global time 5s$"));
                     EXPECT_TRUE(has(run.lines, "state #1.*:.*violation.*timing constraint"));
                     EXPECT_TRUE(has(run.lines, "A.*resume.*-INFTY.*7s"));
                   });
}

// ---- External ports (R16, R17) -----------------------------------------------------------

engines::SimulateOptions external_options(engines::SimulateOptions options) {
  options.real_time = true;
  options.asap = true;
  options.first_enabled = true;
  return options;
}

/// The lines that follow the Sum streams: the Single events, the rendezvous, the final state.
const char* const kAfterSumLines[] = {"1.s3=42;", "2.s3=42;",     "1.s4=42;",
                                      "2.s4=42;", "sync 1 and 2", "state #405.*:.*deadlock"};

TYPED_TEST(ConformanceRealTime, R16_external) {
  this->check_runs("running/external", "Compound()", external_options(this->options()), kOneSeed,
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     // The original summed these counts to 406: each line appears once.
                     for (int k = 1; k <= 100; ++k) {
                       const std::string sum = std::to_string(k * (k + 1) / 2);
                       for (const char* port : {"1.s1=", "2.s1=", "1.s2=", "2.s2="}) {
                         const std::string pattern = port + sum + ";";
                         EXPECT_EQ(count(run.lines, pattern), 1u) << pattern;
                       }
                     }
                     for (const char* pattern : kAfterSumLines) {
                       EXPECT_EQ(count(run.lines, pattern), 1u) << pattern;
                     }
                     EXPECT_EQ(state_header(run.lines, 405), "deadlock!");
                   });
}

TYPED_TEST(ConformanceRealTime, R17_external_error) {
  this->check_runs("running/external_error", "Compound()", external_options(this->options()),
                   kOneSeed, [](const auto& run) {
                     expect_run_error(run, engines::kUnexpectedEvent);
                     for (const char* pattern : kAfterSumLines) {
                       EXPECT_EQ(count(run.lines, pattern), 0u) << pattern;
                     }
                   });
}

// ---- The multithread engine's suite: models that call usleep(1 s) ---------------------------

TYPED_TEST(ConformanceRealTime, M01_priority_rules_cycle4) {
  this->check_silent_error("running_multithread_extra/priority_rules_cycle4", "Compound()",
                           engines::kCycleInPriorities, kOneSeed);
}

// Weak in the original (exit code only); a negative test for M01.
TYPED_TEST(ConformanceRealTime, M04_priority_rules_no_cycle4) {
  auto options = this->options();
  options.silent = true;
  this->check_runs("running_multithread_extra/priority_rules_no_cycle4", "Compound()", options,
                   kOneSeed, [](const auto& run) { EXPECT_EQ(run.result.code, kRunOk); });
}

}  // namespace
}  // namespace smcbip::tests
