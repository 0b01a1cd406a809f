// Conformance oracles of EXPECTED.md section 6, "Priorities" (R38-R52, R67).
#include <gtest/gtest.h>

#include <cstddef>
#include <regex>
#include <string>

#include "tests/engines/conformance_suite.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::kRunOk;

template <class Engine>
class ConformancePriorities : public ConformanceFixture<Engine> {};
TYPED_TEST_SUITE(ConformancePriorities, AllModels, EngineNames);

/// The checks shared by R38 and R39.
void expect_priority_rules(const ConformanceRun& run) {
  EXPECT_EQ(run.result.code, kRunOk);
  EXPECT_TRUE(has(run.lines, "brd1:.*myAtom1.p() .*myAtom3.p()") ||
              has(run.lines, "brd1:.*myAtom3.p() .*myAtom1.p()"));
  EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
  EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
  for (const char* pattern : {"myAtom2.p()", "myAtom1.q()", "myAtom2.q()", "myAtom3.q()"}) {
    EXPECT_TRUE(lacks(run.lines, pattern)) << pattern;
  }
}

TYPED_TEST(ConformancePriorities, R38_priority_rules) {
  this->check_runs("running/priority_rules", "MyCompoundType()", this->options(),
                   expect_priority_rules);
}

TYPED_TEST(ConformancePriorities, R39_priority_rules_wildcard) {
  this->check_runs("running/priority_rules_wildcard", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     expect_priority_rules(run);
                     for (const char* pattern : {"myAtom1.r()", "myAtom2.r()", "myAtom3.r()"}) {
                       EXPECT_TRUE(lacks(run.lines, pattern)) << pattern;
                     }
                     expect_deadlock_in_tail(run.lines, 1, 10);
                   });
}

TYPED_TEST(ConformancePriorities, R40_priority_rules_cycle) {
  this->check_silent_error("running/priority_rules_cycle", "MyCompoundType()",
                           engines::kCycleInPriorities);
}

// R41 (priority_rules_cycle2) must be rejected at compile time: tests/bipc covers it.

TYPED_TEST(ConformancePriorities, R42_priority_rules_cycle3) {
  this->check_silent_error("running/priority_rules_cycle3", "MyCompoundType()",
                           engines::kCycleInPriorities);
}

TYPED_TEST(ConformancePriorities, R43_priority_rules_cycle_hierarchy) {
  this->check_silent_error("running/priority_rules_cycle_hierarchy", "CTH()",
                           engines::kCycleInPriorities);
}

// R44, R45: the intended facts (the original script asserted only the exit code).
TYPED_TEST(ConformancePriorities, R44_priority_rules_no_cycle) {
  this->check_runs("running/priority_rules_no_cycle", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "rdv:.*A1.p.*A2.p.*A3.p"));
                   });
}

TYPED_TEST(ConformancePriorities, R45_priority_rules_no_cycle2) {
  this->check_runs("running/priority_rules_no_cycle2", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "rdv2:.*rdv1.r.*A3.p"));
                   });
}

TYPED_TEST(ConformancePriorities, R46_priority_rules_atom) {
  this->check_runs("running/priority_rules_atom", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                     EXPECT_TRUE(has(run.lines, "single1:.*myAtom.p"));
                     EXPECT_TRUE(lacks(run.lines, "single2:.*myAtom.q"));
                   });
}

TYPED_TEST(ConformancePriorities, R47_priority_rules_atom_internal) {
  this->check_runs(
      "running/priority_rules_atom_internal", "MyCompoundType()", this->options(),
      [](const auto& run) {
        EXPECT_EQ(run.result.code, kRunOk);
        EXPECT_TRUE(has(run.lines, "myAtom.p"));
        EXPECT_TRUE(has(run.lines, "myAtom.r"));
        EXPECT_TRUE(has(run.lines, "choose .*myAtom.p") || has(run.lines, "choose .*myAtom.r"));
        EXPECT_EQ(state_header(run.lines, 0), "2 internal ports:");
        EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
      });
}

TYPED_TEST(ConformancePriorities, R48_priority_rules_atom_export) {
  this->check_runs("running/priority_rules_atom_export", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "single:.*myAtom.exp()"), 3u);
                     EXPECT_EQ(count(run.lines, "choose.*single:.*myAtom.exp()"), 1u);
                     EXPECT_EQ(state_header(run.lines, 0), "2 interactions:");
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                   });
}

TYPED_TEST(ConformancePriorities, R49_priority_rules_atom_closure) {
  this->check_runs("running/priority_rules_atom_closure", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                     EXPECT_TRUE(has(run.lines, "single5:.*myAtom.t"));
                     EXPECT_TRUE(lacks(run.lines, "single1:.*myAtom.p"));
                   });
}

// The two `lacks` are vacuous as written (single1 carries only p); the state-0 count carries
// the real fact.
TYPED_TEST(ConformancePriorities, R50_priority_rules_atom_wildcard) {
  this->check_runs("running/priority_rules_atom_wildcard", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_TRUE(has(run.lines, "single1:.*myAtom.p()"));
                     EXPECT_TRUE(lacks(run.lines, "single1:.*myAtom.q()"));
                     EXPECT_TRUE(lacks(run.lines, "single1:.*myAtom.r()"));
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                   });
}

TYPED_TEST(ConformancePriorities, R51_priority_rules_atom_cycle3) {
  this->check_silent_error("running/priority_rules_atom_cycle3", "MyCompoundType()",
                           engines::kCycleInAtomPriorities);
}

TYPED_TEST(ConformancePriorities, R52_priority_rules_atom_cycle4) {
  this->check_runs(
      "running/priority_rules_atom_cycle4", "MyCompoundType()", this->options(),
      [](const auto& run) {
        EXPECT_EQ(run.result.code, kRunOk);
        EXPECT_EQ(state_header(run.lines, 0), "2 interactions:");
        EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
        EXPECT_TRUE(has(run.lines, "single1:.*myAtom.p") || has(run.lines, "single5:.*myAtom.t"));
      });
}

/// R67's intended invariant: replaying the choose lines with a bit that `Flip` toggles
/// (initially 0), `Even` (A.p() B.p()) is only chosen at bit 0 and `Odd` (C.p() D.p()) only at
/// bit 1. Empty when it holds, else the first offending line; also requires every kind to occur.
std::string even_odd_violation(const Lines& lines) {
  static const std::regex choice(R"(^\[BIP ENGINE\]: -> choose \[[0-9]+\] ROOT\.(Even|Odd|Flip): )"
                                 R"((.*) at global time )");
  int bit = 0;
  std::size_t evens = 0, odds = 0, flips = 0;
  for (const std::string& line : choose_lines(lines)) {
    std::smatch m;
    if (!std::regex_search(line, m, choice)) return "unexpected choice: " + line;
    const std::string connector = m[1].str();
    const std::string values = m[2].str();
    if (connector == "Flip" && values == "switch.flip()") {
      bit = 1 - bit;
      ++flips;
    } else if (connector == "Even" && values == "A.p() B.p()") {
      if (bit != 0) return "Even chosen while switch.bit == 1: " + line;
      ++evens;
    } else if (connector == "Odd" && values == "C.p() D.p()") {
      if (bit != 1) return "Odd chosen while switch.bit == 0: " + line;
      ++odds;
    } else {
      return "unexpected port values: " + line;
    }
  }
  if (evens == 0 || odds == 0 || flips == 0) return "some connector never chosen";
  return {};
}

TYPED_TEST(ConformancePriorities, R67_priority_rules_guard_external) {
  auto options = this->options();
  options.limit = 10'000;
  this->check_runs(
      "running/priority_rules_guard_external", "EvilPriorityRules()", options, [](const auto& run) {
        EXPECT_EQ(run.result.code, kRunOk);
        EXPECT_EQ(state_header(run.lines, 10'000), "stop (reached limit of 10000 states)");
        EXPECT_EQ(even_odd_violation(run.lines), "");
      });
}

}  // namespace
}  // namespace smcbip::tests
