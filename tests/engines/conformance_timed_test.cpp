// Conformance oracles of EXPECTED.md section 6, "Timed models and time-safety", in simulated
// time (R01 in simulated time, R02-R08, R12 run a); the wall-clock runs are in
// conformance_realtime_test.cpp.
#include <gtest/gtest.h>

#include <string>

#include "tests/engines/conformance_externs.h"
#include "tests/engines/conformance_suite.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::kRunOk;

template <class Engine>
class ConformanceTimed : public ConformanceFixture<Engine> {};
TYPED_TEST_SUITE(ConformanceTimed, AllModels, EngineNames);

// The tempcontrol extern's row layout, pinned by a literal (the R02 table is built with it).
TEST(ConformanceExterns, TempcontrolRowWidths) {
  EXPECT_EQ(tempcontrol_row(899, 999, "ready", "ready", "down", "up"),
            "   899         999   ready   ready        down          up");
  EXPECT_EQ(tempcontrol_position(2), "ready");
  EXPECT_EQ(tempcontrol_position(7), "ERROR!");
  EXPECT_EQ(tempcontrol_command(2), "Shutdown!");
  EXPECT_EQ(tempcontrol_command(-1), "ERROR!");
}

TYPED_TEST(ConformanceTimed, R02_timed_tempcontrol) {
  auto options = this->options();
  options.silent = true;
  this->check_runs("running/timed_tempcontrol", "Top()", options, expect_tempcontrol_table);
}

// R01's model in simulated time (the oracle itself runs --real-time in the slow tier). Regression
// test for priorities that ignored invariants: W1's write, dominated by W2's next window, was
// masked although W1's invariant forces a step before that window opens, so every run
// time-locked right after W2's first write.
TYPED_TEST(ConformanceTimed, R01_writers_buffer_simulated_time) {
  this->check_runs("running/writers_buffer", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    for (int k = 0; k <= 9; ++k) {
      EXPECT_EQ(count(run.lines, "^New value: " + std::to_string(k) + "$"), 1u) << k;
    }
    EXPECT_EQ(count(run.lines, "^New value: "), 10u);
    // After its 10 writes W1 can only wait for its invariant x <= 11.
    EXPECT_EQ(last_state_header(run.lines), "time-lock at 11s!");
  });
}

TYPED_TEST(ConformanceTimed, R03_clock_speed) {
  this->check_runs("running/clock_speed", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 200), "deadlock!");
    EXPECT_EQ(state_time(run.lines, 200), "2s");
    EXPECT_EQ(count(run.lines, "choose.*A.p1"), 200u);
  });
}

TYPED_TEST(ConformanceTimed, R04_clock_units) {
  this->check_runs("running/clock_units", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
    EXPECT_EQ(state_time(run.lines, 1), "1s");
    EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
    EXPECT_EQ(count(run.lines, "choose.*A.p1"), 1u);
  });
}

TYPED_TEST(ConformanceTimed, R05_time_lock1) {
  this->check_runs("running/time_lock1", "Compound()", this->options(), [](const auto& run) {
    EXPECT_TRUE(has(run.lines, "state #0.*:.*time.*lock.* 5s"));
    EXPECT_EQ(state_header(run.lines, 0), "time-lock at 5s!");  // closed invariant x <= 5
  });
}

TYPED_TEST(ConformanceTimed, R06_time_lock2) {
  this->check_runs("running/time_lock2", "Compound()", this->options(), [](const auto& run) {
    EXPECT_TRUE(has(run.lines, "state #0.*:.*time.*lock.* 5s"));
    EXPECT_EQ(state_header(run.lines, 0), "time-lock right before 5s!");  // open x < 5
  });
}

TYPED_TEST(ConformanceTimed, R07_time_lock3) {
  this->check_runs("running/time_lock3", "Compound()", this->options(), [](const auto& run) {
    EXPECT_TRUE(has(run.lines, "state #0.*:.*time.*lock.* 5s"));
    // The eager guard x > 5 has no earliest instant: either form is right.
    EXPECT_TRUE(header_in(run.lines, 0, {"time-lock at 5s!", "time-lock right before 5s!"}))
        << state_header(run.lines, 0);
  });
}

// Run a of R08 and R12 (test_resume, test_resume4 call no sleep); run b and the other
// test_resume* models are in conformance_realtime_test.cpp.
TYPED_TEST(ConformanceTimed, R08_test_resume_run_a) {
  this->check_runs("running/test_resume", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
    EXPECT_TRUE(has(run.lines, "choose.*A.p1.*global time 5s$"));
    EXPECT_EQ(state_header(run.lines, 1), "1 internal port:");
    EXPECT_TRUE(has(run.lines, "choose.*A.p2.*global time 5s$"));
    EXPECT_EQ(state_header(run.lines, 2), "deadlock!");
  });
}

TYPED_TEST(ConformanceTimed, R12_test_resume4_run_a) {
  this->check_runs("running/test_resume4", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
    EXPECT_TRUE(has(run.lines, "choose.*A.p.*global time 0$"));
    EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
  });
}

}  // namespace
}  // namespace smcbip::tests
