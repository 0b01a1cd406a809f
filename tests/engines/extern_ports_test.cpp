// Extern ports in simulated time: the conformance models `external` and `external_error` (whose
// event sources live in conformance_externs.cpp) give the same outcomes as in real time, in a
// fraction of a second; and the three event policies on small models of this file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "bipc/bipc.h"
#include "engines/engines.h"
#include "tests/engines/temp_model.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

engines::SimulateOptions simulated(std::uint64_t seed) {
  engines::SimulateOptions options;
  options.seed = seed;
  return options;
}

class ExternConformance : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(conformance_dir())) {
      GTEST_SKIP() << "shared conformance data not found (set SMCBIP_SHARED_DATA)";
    }
  }
};

TEST_F(ExternConformance, EveryEventIsTakenOnceThenTheAtomsMeet) {
  const auto system = load_conformance_model("running/external", "Compound()");
  ASSERT_TRUE(system);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const ConformanceRun run = run_conformance(*system, simulated(seed));
    EXPECT_EQ(run.result.code, engines::kRunOk) << run.result.message;
    // Exact lines (400 regular-expression scans of the trace would dominate the test).
    for (int k = 1; k <= 100; ++k) {
      const std::string sum = std::to_string(k * (k + 1) / 2);
      for (const char* port : {"1.s1=", "2.s1=", "1.s2=", "2.s2="}) {
        const std::string line = port + sum + ";";
        EXPECT_EQ(std::count(run.lines.begin(), run.lines.end(), line), 1) << line;
      }
    }
    for (const char* line : {"1.s3=42;", "2.s3=42;", "1.s4=42;", "2.s4=42;", "sync 1 and 2"}) {
      EXPECT_EQ(count(run.lines, line), 1u) << line;
    }
    EXPECT_EQ(state_header(run.lines, 405), "deadlock!");
  }
}

TEST_F(ExternConformance, AnEventForADisabledErrorPortStopsTheRun) {
  const auto system = load_conformance_model("running/external_error", "Compound()");
  ASSERT_TRUE(system);
  const ConformanceRun run = run_conformance(*system, simulated(1));
  expect_run_error(run, engines::kUnexpectedEvent);
  EXPECT_TRUE(has(run.lines,
                  "ERROR: port p1 of component ROOT\\.[AB] has received an event at "
                  ".* while being disabled at current state and having event "
                  "consumption policy 'error'!"))
      << run.text;
  EXPECT_EQ(count(run.lines, "s3=42"), 0u);
}

/// Events at 10, 20, 30 ms carrying 1, 2, 3.
class ThreeEvents final : public engines::ExternPortSource {
 public:
  std::optional<engines::ExternEvent> next(engines::TimeValue /*now*/) override {
    if (sent_ == 3) return std::nullopt;
    ++sent_;
    return engines::ExternEvent{sent_ * 10'000'000, {engines::make_int(sent_)}};
  }

 private:
  std::int64_t sent_ = 0;
};

/// An atom that takes events on `e` only from 15 ms on (clock guard), then sums them.
std::string policy_model(const std::string& policy) {
  return R"(package policies
  port type Int(int v)
  extern function printf(string, int)
  atom type A()
    data int v, sum
    clock t unit millisecond
    extern port Int e(v) as "ThreeEvents" )" +
         policy + R"(
    place S
    initial to S do { v = 0; sum = 0; t = 0; }
    on e from S to S provided (t >= 15) do { sum = sum + v; printf("sum=%d\n", sum); }
  end
  compound type Top()
    component A a()
  end
end
)";
}

engines::RunResult run_policy(const std::string& policy, std::string& text) {
  const std::optional<bipc::ir::System> system = load_model_text(policy_model(policy), "Top()");
  if (!system) return {};
  engines::Externs externs = engines::Externs::with_builtins();
  externs.add_port_class("ThreeEvents", [](const std::string&, const std::string&) {
    return std::make_unique<ThreeEvents>();
  });
  std::ostringstream out;
  engines::SimulateOptions options = simulated(1);
  options.asap = true;  // each event is taken at the first date its port allows
  const engines::RunResult result = engines::simulate(*system, options, externs, out);
  text = out.str();
  return result;
}

TEST(ExternPolicies, RememberKeepsTheEventUntilThePortTakesIt) {
  std::string text;
  const engines::RunResult result = run_policy("remember", text);
  EXPECT_EQ(result.code, engines::kRunOk);
  // The 10 ms event waits until 15 ms; then 20 and 30 ms: sums 1, 3, 6.
  const Lines lines = split_lines(text);
  EXPECT_TRUE(has(lines, "^sum=1$") && has(lines, "^sum=3$") && has(lines, "^sum=6$")) << text;
  EXPECT_EQ(state_time(lines, 1), "15ms");
  EXPECT_EQ(last_state_header(lines), "deadlock!");
}

TEST(ExternPolicies, IgnoreDropsTheEventThePortCannotTake) {
  std::string text;
  const engines::RunResult result = run_policy("ignore", text);
  EXPECT_EQ(result.code, engines::kRunOk);
  // The 10 ms event is dropped: sums 2, 5.
  const Lines lines = split_lines(text);
  EXPECT_TRUE(lacks(lines, "^sum=1$") && has(lines, "^sum=2$") && has(lines, "^sum=5$")) << text;
  EXPECT_EQ(state_time(lines, 1), "20ms");
}

TEST(ExternPolicies, ErrorStopsAtTheFirstEventThePortCannotTake) {
  std::string text;
  const engines::RunResult result = run_policy("error", text);
  EXPECT_EQ(result.code, engines::kUnexpectedEvent);
  EXPECT_TRUE(has(split_lines(text),
                  "ERROR: port e of component ROOT.a has received an event at "
                  "10ms while being disabled"))
      << text;
}

TEST(ExternPolicies, AMissingPortClassIsAnInputError) {
  const std::optional<bipc::ir::System> system = load_model_text(policy_model("remember"), "Top()");
  ASSERT_TRUE(system);
  std::ostringstream out;
  const engines::RunResult result =
      engines::simulate(*system, simulated(1), engines::Externs::with_builtins(), out);
  EXPECT_EQ(result.code, engines::kInputError);
  EXPECT_NE(result.message.find("no extern port class \"ThreeEvents\""), std::string::npos)
      << result.message;
}

}  // namespace
}  // namespace smcbip::tests
