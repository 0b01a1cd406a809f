// Checks shared by the files of the conformance suite.
#include "tests/engines/conformance_suite.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/engines/conformance_externs.h"

namespace smcbip::tests {

bool header_in(const Lines& lines, std::uint64_t n, std::initializer_list<const char*> summaries) {
  const std::string summary = state_header(lines, n);
  return std::any_of(summaries.begin(), summaries.end(),
                     [&](const char* candidate) { return summary == candidate; });
}

Lines expected_tempcontrol_output() {
  struct Rows {
    int first, last;         // steps
    int temperature, slope;  // temperature at `first`, change per step
    const char *rod1, *rod2, *command1, *command2;
  };
  static constexpr Rows kTable[] = {
      {1, 898, 101, 1, "ready", "ready", "up", "up"},
      {899, 899, 999, 0, "ready", "ready", "down", "up"},
      {900, 1348, 1000, -2, "down", "ready", "down", "up"},
      {1349, 1349, 102, 0, "down", "ready", "up", "up"},
      {1350, 2248, 100, 1, "rest", "ready", "up", "up"},
      {2249, 2249, 999, 0, "rest", "ready", "up", "down"},
      {2250, 2698, 1000, -2, "rest", "down", "up", "down"},
      {2699, 2699, 102, 0, "rest", "down", "up", "up"},
      {2700, 3598, 100, 1, "rest", "rest", "up", "up"},
  };
  Lines lines{"# STEP Reactor/Temp Rod1/Pos Rod2/pos Control/cmd1 Control/cmd2"};
  for (const Rows& rows : kTable) {
    for (int step = rows.first; step <= rows.last; ++step) {
      const int temperature = rows.temperature + rows.slope * (step - rows.first);
      lines.push_back(
          tempcontrol_row(step, temperature, rows.rod1, rows.rod2, rows.command1, rows.command2));
    }
  }
  return lines;
}

void expect_tempcontrol_table(const ConformanceRun& run) {
  EXPECT_EQ(run.result.code, engines::kRunOk);
  EXPECT_EQ(describe_difference(run.lines, expected_tempcontrol_output()), "");
  EXPECT_EQ(count(run.lines, "3599"), 0u);
}

void expect_deadlock_in_tail(const Lines& lines, std::uint64_t n, std::size_t k) {
  EXPECT_EQ(state_header(lines, n), "deadlock!");
  EXPECT_TRUE(tail_has(lines, k, "state #" + std::to_string(n) + ".*:.*deadlock"));
}

}  // namespace smcbip::tests
