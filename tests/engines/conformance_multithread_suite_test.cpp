// Conformance oracles of EXPECTED.md section 8, the multithread engine's suite
// (running_multithread_extra/), run on every engine. M01 and M04 call usleep(1 s): they are in
// conformance_realtime_test.cpp.
#include <gtest/gtest.h>

#include "tests/engines/conformance_suite.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::kRunOk;

template <class Engine>
class ConformanceMultithreadSuite : public ConformanceFixture<Engine> {};
TYPED_TEST_SUITE(ConformanceMultithreadSuite, AllModels, EngineNames);

TYPED_TEST(ConformanceMultithreadSuite, M02_priority_rules_cycle5) {
  this->check_silent_error("running_multithread_extra/priority_rules_cycle5", "Level1()",
                           engines::kCycleInPriorities);
}

// The intended facts (the original test asserted nothing).
TYPED_TEST(ConformanceMultithreadSuite, M03_priority_rules_no_cycle3) {
  this->check_runs("running_multithread_extra/priority_rules_no_cycle3", "MyCompoundType()",
                   this->options(), [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "brd:.*A1.p.*A2.p.*A3.p"));
                   });
}

TYPED_TEST(ConformanceMultithreadSuite, M05_tempcontrol) {
  auto options = this->options();
  options.silent = true;
  this->check_runs("running_multithread_extra/tempcontrol", "Top()", options,
                   expect_tempcontrol_table);
}

}  // namespace
}  // namespace smcbip::tests
