// The BIP conformance oracles (bip-conformance/EXPECTED.md sections 6, 8 and 11) that do not
// depend on the wall clock, run on every engine; the real-time ones are in
// conformance_realtime_test.cpp. Each test is named after its oracle id and model.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tests/engines/conformance_externs.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::kRunOk;

template <class Engine>
class Conformance : public ConformanceFixture<Engine> {};
TYPED_TEST_SUITE(Conformance, AllEngines, EngineNames);

/// True when the header of state `n` says one of `summaries`.
bool header_in(const Lines& lines, std::uint64_t n, std::initializer_list<const char*> summaries) {
  const std::string summary = state_header(lines, n);
  return std::any_of(summaries.begin(), summaries.end(),
                     [&](const char* candidate) { return summary == candidate; });
}

/// The exact --silent output of the tempcontrol models: the header line, then the rows of the
/// table of EXPECTED.md R02 (steps 1..3598).
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
  EXPECT_EQ(run.result.code, kRunOk);
  EXPECT_EQ(describe_difference(run.lines, expected_tempcontrol_output()), "");
  EXPECT_EQ(count(run.lines, "3599"), 0u);
}

/// Header n is `deadlock!`, and (the original check) one of the last k lines says so.
void expect_deadlock_in_tail(const Lines& lines, std::uint64_t n, std::size_t k) {
  EXPECT_EQ(state_header(lines, n), "deadlock!");
  EXPECT_TRUE(tail_has(lines, k, "state #" + std::to_string(n) + ".*:.*deadlock"));
}

// The tempcontrol extern's row layout, pinned by a literal (the R02 table is built with it).
TEST(ConformanceExterns, TempcontrolRowWidths) {
  EXPECT_EQ(tempcontrol_row(899, 999, "ready", "ready", "down", "up"),
            "   899         999   ready   ready        down          up");
  EXPECT_EQ(tempcontrol_position(2), "ready");
  EXPECT_EQ(tempcontrol_position(7), "ERROR!");
  EXPECT_EQ(tempcontrol_command(2), "Shutdown!");
  EXPECT_EQ(tempcontrol_command(-1), "ERROR!");
}

// ---- Timed models, simulated time -----------------------------------------------------------

TYPED_TEST(Conformance, R02_timed_tempcontrol) {
  auto options = this->options();
  options.silent = true;
  this->check_runs("running/timed_tempcontrol", "Top()", options, expect_tempcontrol_table);
}

TYPED_TEST(Conformance, R03_clock_speed) {
  this->check_runs("running/clock_speed", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 200), "deadlock!");
    EXPECT_EQ(state_time(run.lines, 200), "2s");
    EXPECT_EQ(count(run.lines, "choose.*A.p1"), 200u);
  });
}

TYPED_TEST(Conformance, R04_clock_units) {
  this->check_runs("running/clock_units", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
    EXPECT_EQ(state_time(run.lines, 1), "1s");
    EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
    EXPECT_EQ(count(run.lines, "choose.*A.p1"), 1u);
  });
}

TYPED_TEST(Conformance, R05_time_lock1) {
  this->check_runs("running/time_lock1", "Compound()", this->options(), [](const auto& run) {
    EXPECT_TRUE(has(run.lines, "state #0.*:.*time.*lock.* 5s"));
    EXPECT_EQ(state_header(run.lines, 0), "time-lock at 5s!");  // closed invariant x <= 5
  });
}

TYPED_TEST(Conformance, R06_time_lock2) {
  this->check_runs("running/time_lock2", "Compound()", this->options(), [](const auto& run) {
    EXPECT_TRUE(has(run.lines, "state #0.*:.*time.*lock.* 5s"));
    EXPECT_EQ(state_header(run.lines, 0), "time-lock right before 5s!");  // open x < 5
  });
}

TYPED_TEST(Conformance, R07_time_lock3) {
  this->check_runs("running/time_lock3", "Compound()", this->options(), [](const auto& run) {
    EXPECT_TRUE(has(run.lines, "state #0.*:.*time.*lock.* 5s"));
    // The eager guard x > 5 has no earliest instant: either form is right.
    EXPECT_TRUE(header_in(run.lines, 0, {"time-lock at 5s!", "time-lock right before 5s!"}))
        << state_header(run.lines, 0);
  });
}

// Run a of R08 and R12 (test_resume, test_resume4 call no sleep); run b and the other
// test_resume* models are in conformance_realtime_test.cpp.
TYPED_TEST(Conformance, R08_test_resume_run_a) {
  this->check_runs("running/test_resume", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
    EXPECT_TRUE(has(run.lines, "choose.*A.p1.*global time 5s$"));
    EXPECT_EQ(state_header(run.lines, 1), "1 internal port:");
    EXPECT_TRUE(has(run.lines, "choose.*A.p2.*global time 5s$"));
    EXPECT_EQ(state_header(run.lines, 2), "deadlock!");
  });
}

TYPED_TEST(Conformance, R12_test_resume4_run_a) {
  this->check_runs("running/test_resume4", "Compound()", this->options(), [](const auto& run) {
    EXPECT_EQ(state_header(run.lines, 0), "1 internal port:");
    EXPECT_TRUE(has(run.lines, "choose.*A.p.*global time 0$"));
    EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
  });
}

// ---- Untimed structure, data transfer, Petri nets -------------------------------------------

TYPED_TEST(Conformance, R18_double_compound) {
  this->check_runs("running/double_compound", "System()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(count(run.lines, "1 interaction"), 1001u);
    EXPECT_EQ(state_header(run.lines, 1001), "deadlock!");
  });
}

TYPED_TEST(Conformance, R19_and_expressions) {
  this->check_runs("running/and_expressions", "AndExpressions()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "1 interaction"), 15u);
                     EXPECT_EQ(state_header(run.lines, 15), "deadlock!");
                   });
}

TYPED_TEST(Conformance, R20_or_expressions) {
  this->check_runs("running/or_expressions", "OrExpressions()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "choose.*single.*sync"), 4u);
                     EXPECT_EQ(state_header(run.lines, 4), "deadlock!");
                   });
}

TYPED_TEST(Conformance, R21_petri_net) {
  this->check_runs("running/petri_net", "MyCompoundType()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    for (const char* name : {"start1", "start2", "res1", "res2", "synchro"}) {
      EXPECT_TRUE(has(run.lines, std::string(name) + ":.*petriNet." + name)) << name;
    }
    EXPECT_EQ(state_header(run.lines, 0), "2 interactions:");
    EXPECT_EQ(state_header(run.lines, 1), "2 interactions:");
    EXPECT_TRUE(header_in(run.lines, 2, {"2 interactions:", "1 interaction:"}))
        << state_header(run.lines, 2);
    EXPECT_EQ(state_header(run.lines, 3), "1 interaction:");
    EXPECT_EQ(state_header(run.lines, 4), "1 interaction:");
    expect_deadlock_in_tail(run.lines, 5, 50);
  });
}

TYPED_TEST(Conformance, R22_petri_net_non_safe) {
  this->check_silent_error("running/petri_net_non_safe", "MyCompoundType()",
                           engines::kNonOneSafeNet);
}

TYPED_TEST(Conformance, R23_petri_net_non_deterministic) {
  this->check_silent_error("running/petri_net_non_deterministic", "MyCompoundType()",
                           engines::kNonDeterministicNet);
}

TYPED_TEST(Conformance, R24_petri_net_non_deterministic2) {
  this->check_silent_error("running/petri_net_non_deterministic2", "MyCompoundType()",
                           engines::kNonDeterministicNet);
}

TYPED_TEST(Conformance, R25_petri_net_non_deterministic3) {
  this->check_silent_error("running/petri_net_non_deterministic3", "MyCompoundType()",
                           engines::kNonDeterministicNet);
}

TYPED_TEST(Conformance, R26_petri_net_deterministic) {
  this->check_runs("running/petri_net_deterministic", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_TRUE(has(run.lines, "choose.*singleP"));
                     EXPECT_TRUE(has(run.lines, "choose.*singleQ"));
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 1), "1 interaction:");
                     expect_deadlock_in_tail(run.lines, 2, 10);
                   });
}

TYPED_TEST(Conformance, R27_simple10counter) {
  this->check_runs("running/simple10counter", "CT()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 0), "deadlock!");
  });
}

TYPED_TEST(Conformance, R28_atom_internal_transitions) {
  this->check_runs("running/atom_internal_transitions", "CT()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "choose.*single:.*c.incr()"), 5u);
                     for (std::uint64_t n = 0; n <= 4; ++n) {
                       EXPECT_EQ(state_header(run.lines, n), "1 interaction:") << "state " << n;
                     }
                     expect_deadlock_in_tail(run.lines, 5, 10);
                   });
}

TYPED_TEST(Conformance, R29_internal_export_compound) {
  this->check_runs("running/internal_export_compound", "BIG_CT()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 1), "1 internal port:");
                     EXPECT_EQ(state_header(run.lines, 2), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 3), "deadlock!");
                   });
}

TYPED_TEST(Conformance, R30_multi_export_atom) {
  this->check_runs(
      "running/multi_export_atom", "MyCompoundType()", this->options(), [](const auto& run) {
        EXPECT_EQ(run.result.code, kRunOk);
        for (const char* d : {"1", "2", "3"}) {
          EXPECT_TRUE(has(run.lines, std::string("mySingleton:.*myAtom.xport(d=") + d + ";)"))
              << "d=" << d;
        }
        EXPECT_EQ(state_header(run.lines, 0), "3 interactions:");
        expect_deadlock_in_tail(run.lines, 1, 10);
      });
}

TYPED_TEST(Conformance, R31_multi_export_compound) {
  this->check_runs("running/multi_export_compound", "Top()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    for (const char* d : {"1", "2", "3"}) {
      EXPECT_TRUE(has(run.lines, std::string("mySingleton:.*C.xport(d=") + d + ";)")) << "d=" << d;
    }
    EXPECT_EQ(state_header(run.lines, 0), "3 interactions:");
    EXPECT_EQ(state_header(run.lines, 1), "2 interactions:");
    EXPECT_EQ(state_header(run.lines, 2), "1 interaction:");
    expect_deadlock_in_tail(run.lines, 3, 10);
  });
}

TYPED_TEST(Conformance, R57_multi_export_compound2) {
  this->check_runs("running/multi_export_compound2", "Top()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 0), "5 interactions:");
    EXPECT_TRUE(header_in(run.lines, 1, {"3 interactions:", "4 interactions:"}))
        << state_header(run.lines, 1);
    EXPECT_TRUE(header_in(run.lines, 2, {"1 interaction:", "2 interactions:"}))
        << state_header(run.lines, 2);
    EXPECT_FALSE(state_header(run.lines, 1) == "4 interactions:" &&
                 state_header(run.lines, 2) == "1 interaction:");
  });
}

TYPED_TEST(Conformance, R58_const_data) {
  this->check_runs("running/const_data", "Top()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 25), "2 internal ports:");
    EXPECT_EQ(state_header(run.lines, 27), "deadlock!");
  });
}

// ---- Connectors: broadcast, hierarchy, data up/down -----------------------------------------

TYPED_TEST(Conformance, R32_broadcast) {
  this->check_runs("running/broadcast", "MyCompoundType()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_TRUE(has(run.lines, "myBroadcast:.*myAtom1.p() .*myAtom3.p()") ||
                has(run.lines, "myBroadcast:.*myAtom3.p() .*myAtom1.p()"));
    EXPECT_TRUE(has(run.lines, "myBroadcast:.*myAtom1.p() .*myAtom2.p()") ||
                has(run.lines, "myBroadcast:.*myAtom2.p() .*myAtom1.p()"));
    EXPECT_EQ(state_header(run.lines, 0), "2 interactions:");
    expect_deadlock_in_tail(run.lines, 1, 10);
    EXPECT_TRUE(lacks(run.lines, "myAtom2.p() .*myAtom3.p()"));
    EXPECT_TRUE(lacks(run.lines, "myAtom3.p() .*myAtom2.p()"));
  });
}

TYPED_TEST(Conformance, R33_broadcast_reverted) {
  this->check_runs("running/broadcast_reverted", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_TRUE(has(run.lines, "myBroadcast:.*myAtom1.p() .*myAtom3.p()") ||
                                 has(run.lines, "myBroadcast:.*myAtom3.p() .*myAtom1.p()"));
                     EXPECT_TRUE(has(run.lines, "myBroadcast:.*myAtom3.p() .*myAtom2.p()") ||
                                 has(run.lines, "myBroadcast:.*myAtom2.p() .*myAtom3.p()"));
                     EXPECT_EQ(state_header(run.lines, 0), "2 interactions:");
                     expect_deadlock_in_tail(run.lines, 1, 10);
                     EXPECT_TRUE(lacks(run.lines, "myAtom1.p() .*myAtom2.p()"));
                     EXPECT_TRUE(lacks(run.lines, "myAtom2.p() .*myAtom1.p()"));
                   });
}

TYPED_TEST(Conformance, R34_broadcast_maximal) {
  this->check_runs(
      "running/broadcast_maximal", "MyCompoundType()", this->options(), [](const auto& run) {
        EXPECT_EQ(run.result.code, kRunOk);
        EXPECT_EQ(state_header(run.lines, 0), "20 interactions:");
        EXPECT_EQ(state_header(run.lines, 1), "1 interaction:");
        EXPECT_EQ(state_header(run.lines, 2), "deadlock!");
        for (int k = 1; k <= 6; ++k) {
          const std::size_t n = count(run.lines, "myBroadcast:.*myAtom" + std::to_string(k) + ".p");
          EXPECT_TRUE(n == 11 || n == 12) << "myAtom" << k << ": " << n << " lines";
        }
      });
}

TYPED_TEST(Conformance, R35_broadcast_up) {
  this->check_runs("running/broadcast_up", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_TRUE(has(run.lines, "single:.*brd.xport(d=54;)"));
                     EXPECT_TRUE(has(run.lines, "single:.*brd.xport(d=115;)"));
                     EXPECT_EQ(state_header(run.lines, 0), "2 interactions:");
                     expect_deadlock_in_tail(run.lines, 1, 10);
                   });
}

TYPED_TEST(Conformance, R36_broadcast_up_down) {
  this->check_runs("running/broadcast_up_down", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_TRUE(has(run.lines, "div:.*xport(d=70;)"));
                     EXPECT_TRUE(has(run.lines, "div:.*xport(d=54;)"));
                     EXPECT_TRUE((has(run.lines, "choose.*xport(d=70;") &&
                                  has(run.lines, "choose.*disp:.*myAtom1.q(d=38;")) ||
                                 (has(run.lines, "choose.*xport(d=54;") &&
                                  has(run.lines, "choose.*disp:.*myAtom1.q(d=28;")));
                     EXPECT_EQ(state_header(run.lines, 0), "2 interactions:");
                     EXPECT_EQ(state_header(run.lines, 1), "1 interaction:");
                     expect_deadlock_in_tail(run.lines, 2, 10);
                   });
}

TYPED_TEST(Conformance, R37_rendezvous_down) {
  this->check_runs("running/rendezvous_down", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_TRUE(has(run.lines, "send:.*sender.p(d=-32;) .*receiver.p(d=0;)") ||
                                 has(run.lines, "send:.*receiver.p(d=0;) .*sender.p(d=-32;)"));
                     EXPECT_TRUE(has(run.lines, "send:.*sender.p(d=99;) .*receiver.p(d=-32;)") ||
                                 has(run.lines, "send:.*receiver.p(d=-32;) .*sender.p(d=99;)"));
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 1), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 2), "deadlock!");
                   });
}

TYPED_TEST(Conformance, R53_broadcast_browser) {
  this->check_runs("running/broadcast_browser", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "choose.*sync"), 62u);
                     EXPECT_EQ(count(run.lines, "choose.*stop"), 1u);
                     const std::size_t bit_counts[] = {64, 67, 73, 85, 109, 126};
                     for (int k = 1; k <= 6; ++k) {
                       const std::string bit = "bit" + std::to_string(k);
                       EXPECT_EQ(count(run.lines, "choose.*sync.*" + bit), 31u) << bit;
                       EXPECT_EQ(count(run.lines, "choose.*" + bit), bit_counts[k - 1]) << bit;
                     }
                     expect_deadlock_in_tail(run.lines, 183, 10);
                   });
}

TYPED_TEST(Conformance, R54_guarded_transitions) {
  this->check_runs("running/guarded_transitions", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "choose.*myAtom1.p"), 11u);
                     EXPECT_EQ(count(run.lines, "choose.*myAtom2.p"), 21u);
                   });
}

TYPED_TEST(Conformance, R55_maximal_progress) {
  this->check_runs("running/maximal_progress", "Top()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 0), "3 interactions:");
    EXPECT_TRUE(has(run.lines, "high:.*low.xport(x=-12;)"));
    EXPECT_TRUE(has(run.lines, "high:.*low.xport(x=-5;)"));
    EXPECT_TRUE(has(run.lines, "single:.*myCompound.p(x=-5;)"));
    // Intended: state 0 lists exactly these three (no `single` with x=-12).
    const Lines state0 = listing(run.lines, 0);
    EXPECT_EQ(count(state0, "high:.*low.xport(x=-12;)"), 1u);
    EXPECT_EQ(count(state0, "high:.*low.xport(x=-5;)"), 1u);
    EXPECT_EQ(count(state0, "single:.*myCompound.p(x=-5;)"), 1u);
    EXPECT_EQ(state0.size(), 3u);
  });
}

TYPED_TEST(Conformance, R56_maximal_progress_hierarchy) {
  this->check_runs("running/maximal_progress_hierarchy", "System()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                   });
}

TYPED_TEST(Conformance, R59_hierarchical) {
  this->check_runs("running/hierarchical", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 21), "deadlock!");
                   });
}

// The original compiled R59's model again with the compiler's flattening pass; our IR is always
// the flattened instance tree, so this re-checks the same facts on the same IR.
TYPED_TEST(Conformance, R60_hierarchical_filter) {
  this->check_runs("running/hierarchical", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 21), "deadlock!");
                   });
}

TYPED_TEST(Conformance, R61_nested) {
  this->check_runs("running/nested", "MyCompoundType()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 21), "deadlock!");
  });
}

TYPED_TEST(Conformance, R62_nested2) {
  this->check_runs("running/nested2", "MyCompoundType()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 0), "3 interactions:");
    EXPECT_EQ(state_header(run.lines, 1), "2 interactions:");
    EXPECT_EQ(state_header(run.lines, 2), "1 interaction:");
    EXPECT_EQ(state_header(run.lines, 3), "deadlock!");
    EXPECT_TRUE(has(run.lines, "choose.*P.*Q"));
    EXPECT_TRUE(has(run.lines, "choose.*R.*S"));
    EXPECT_TRUE(has(run.lines, "choose.*T.*U"));
  });
}

/// The atom sets of the interactions listed in state 0 of nested3, each as sorted letters.
std::multiset<std::string> nested3_listed_sets(const Lines& lines) {
  static const std::regex connector(R"(ROOT\.C: (.*)$)");
  static const std::regex entry(R"(\b([PQRSTU])\.p\(\))");
  std::multiset<std::string> sets;
  for (const std::string& line : listing(lines, 0)) {
    std::smatch values;
    if (!std::regex_search(line, values, connector)) continue;
    const std::string text = values[1].str();
    std::set<char> atoms;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), entry);
         it != std::sregex_iterator(); ++it) {
      atoms.insert((*it)[1].str()[0]);
    }
    sets.insert(std::string(atoms.begin(), atoms.end()));
  }
  return sets;
}

TYPED_TEST(Conformance, R63_nested3) {
  auto options = this->options();
  options.disable_maximal_progress = true;
  this->check_runs("running/nested3", "MyCompoundType()", options, [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 0), "7 interactions:");
    EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
    for (const char* pattern : {".*P.*Q.*R.*S.*T.*U", ".*P.*Q.*R.*T.*U", ".*P.*Q.*S.*T.*U",
                                ".*Q.*R.*S.*T.*U", ".*Q.*R.*T.*U", ".*Q.*S.*T.*U", ".*T.*U"}) {
      EXPECT_TRUE(has(run.lines, pattern)) << pattern;
    }
    const std::multiset<std::string> intended{"PQRSTU", "PQRTU", "PQSTU", "QRSTU",
                                              "QRTU",   "QSTU",  "TU"};
    EXPECT_EQ(nested3_listed_sets(run.lines), intended);
  });
}

TYPED_TEST(Conformance, R64_hierarchical_priority) {
  this->check_runs("running/hierarch_priority", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 21), "deadlock!");
                   });
}

// As R60: the original's flattening pass has no counterpart, the IR is already flat.
TYPED_TEST(Conformance, R65_hierarchical_priority_filter) {
  this->check_runs("running/hierarch_priority", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 21), "deadlock!");
                   });
}

TYPED_TEST(Conformance, R66_demosaicing9) {
  GTEST_SKIP() << "demosaicing9 needs extern image types, the original filter tables and "
                  "image data, and its reference output is missing from the data set";
}

// ---- Priorities ------------------------------------------------------------------------------

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

TYPED_TEST(Conformance, R38_priority_rules) {
  this->check_runs("running/priority_rules", "MyCompoundType()", this->options(),
                   expect_priority_rules);
}

TYPED_TEST(Conformance, R39_priority_rules_wildcard) {
  this->check_runs("running/priority_rules_wildcard", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     expect_priority_rules(run);
                     for (const char* pattern : {"myAtom1.r()", "myAtom2.r()", "myAtom3.r()"}) {
                       EXPECT_TRUE(lacks(run.lines, pattern)) << pattern;
                     }
                     expect_deadlock_in_tail(run.lines, 1, 10);
                   });
}

TYPED_TEST(Conformance, R40_priority_rules_cycle) {
  this->check_silent_error("running/priority_rules_cycle", "MyCompoundType()",
                           engines::kCycleInPriorities);
}

// R41 (priority_rules_cycle2) must be rejected at compile time: tests/bipc covers it.

TYPED_TEST(Conformance, R42_priority_rules_cycle3) {
  this->check_silent_error("running/priority_rules_cycle3", "MyCompoundType()",
                           engines::kCycleInPriorities);
}

TYPED_TEST(Conformance, R43_priority_rules_cycle_hierarchy) {
  this->check_silent_error("running/priority_rules_cycle_hierarchy", "CTH()",
                           engines::kCycleInPriorities);
}

// R44, R45: the intended facts (the original script asserted only the exit code).
TYPED_TEST(Conformance, R44_priority_rules_no_cycle) {
  this->check_runs("running/priority_rules_no_cycle", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "rdv:.*A1.p.*A2.p.*A3.p"));
                   });
}

TYPED_TEST(Conformance, R45_priority_rules_no_cycle2) {
  this->check_runs("running/priority_rules_no_cycle2", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "rdv2:.*rdv1.r.*A3.p"));
                   });
}

TYPED_TEST(Conformance, R46_priority_rules_atom) {
  this->check_runs("running/priority_rules_atom", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                     EXPECT_TRUE(has(run.lines, "single1:.*myAtom.p"));
                     EXPECT_TRUE(lacks(run.lines, "single2:.*myAtom.q"));
                   });
}

TYPED_TEST(Conformance, R47_priority_rules_atom_internal) {
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

TYPED_TEST(Conformance, R48_priority_rules_atom_export) {
  this->check_runs("running/priority_rules_atom_export", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "single:.*myAtom.exp()"), 3u);
                     EXPECT_EQ(count(run.lines, "choose.*single:.*myAtom.exp()"), 1u);
                     EXPECT_EQ(state_header(run.lines, 0), "2 interactions:");
                     EXPECT_EQ(state_header(run.lines, 1), "deadlock!");
                   });
}

TYPED_TEST(Conformance, R49_priority_rules_atom_closure) {
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
TYPED_TEST(Conformance, R50_priority_rules_atom_wildcard) {
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

TYPED_TEST(Conformance, R51_priority_rules_atom_cycle3) {
  this->check_silent_error("running/priority_rules_atom_cycle3", "MyCompoundType()",
                           engines::kCycleInAtomPriorities);
}

TYPED_TEST(Conformance, R52_priority_rules_atom_cycle4) {
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

TYPED_TEST(Conformance, R67_priority_rules_guard_external) {
  auto options = this->options();
  options.limit = 10'000;
  this->check_runs(
      "running/priority_rules_guard_external", "EvilPriorityRules()", options, [](const auto& run) {
        EXPECT_EQ(run.result.code, kRunOk);
        EXPECT_EQ(state_header(run.lines, 10'000), "stop (reached limit of 10000 states)");
        EXPECT_EQ(even_odd_violation(run.lines), "");
      });
}

// ---- Invariants ------------------------------------------------------------------------------

TYPED_TEST(Conformance, R68_invariants) {
  this->check_runs("running/invariants", "CT()", this->options(), [](const auto& run) {
    expect_run_error(run, engines::kInvariantViolation);
    EXPECT_TRUE(has(run.lines, "state #202"));
    EXPECT_TRUE(find_state_header(run.lines, 202).has_value());
    EXPECT_TRUE(has(run.lines, "ERROR.*invariant.*totalUse2"));
  });
}

TYPED_TEST(Conformance, R69_invariants2) {
  this->check_runs("running/invariants2", "CT()", this->options(), [](const auto& run) {
    expect_run_error(run, engines::kInvariantViolation);
    EXPECT_TRUE(has(run.lines, "state #200"));
    EXPECT_TRUE(find_state_header(run.lines, 200).has_value());
    EXPECT_TRUE(has(run.lines, "ERROR.*invariant.*use12"));
  });
}

// ---- The multithread engine's suite (running_multithread_extra/) ------------------------------
// M01 and M04 call usleep(1 s): they are in conformance_realtime_test.cpp.

TYPED_TEST(Conformance, M02_priority_rules_cycle5) {
  this->check_silent_error("running_multithread_extra/priority_rules_cycle5", "Level1()",
                           engines::kCycleInPriorities);
}

// The intended facts (the original test asserted nothing).
TYPED_TEST(Conformance, M03_priority_rules_no_cycle3) {
  this->check_runs("running_multithread_extra/priority_rules_no_cycle3", "MyCompoundType()",
                   this->options(), [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_TRUE(has(run.lines, "brd:.*A1.p.*A2.p.*A3.p"));
                   });
}

TYPED_TEST(Conformance, M05_tempcontrol) {
  auto options = this->options();
  options.silent = true;
  this->check_runs("running_multithread_extra/tempcontrol", "Top()", options,
                   expect_tempcontrol_table);
}

// ---- Models without a test: hand-derived expectations (EXPECTED.md section 11) --------------

/// Random run of a counter atom: `steps` internal-port steps, then a deadlock.
void expect_internal_counting(const ConformanceRun& run, std::uint64_t steps) {
  static const std::regex internal_ports("^[0-9]+ internal ports?:$");
  EXPECT_EQ(run.result.code, kRunOk);
  EXPECT_EQ(choose_lines(run.lines).size(), steps);
  const std::vector<StateHeader> headers = state_headers(run.lines);
  ASSERT_EQ(headers.size(), steps + 1);
  for (std::uint64_t n = 0; n < steps; ++n) {
    ASSERT_EQ(headers[n].state, n);
    ASSERT_TRUE(std::regex_match(headers[n].summary, internal_ports))
        << "state " << n << ": " << headers[n].summary;
  }
  EXPECT_EQ(state_header(run.lines, steps), "deadlock!");
}

/// An --explore run's summary: S states, D deadlocks, E errors.
void expect_exploration(const ConformanceRun& run, std::uint64_t states, std::uint64_t deadlocks,
                        std::uint64_t errors) {
  EXPECT_EQ(run.result.code, kRunOk);
  const std::optional<ExplorationSummary> summary = exploration_summary(run.lines);
  ASSERT_TRUE(summary.has_value()) << "no exploration summary in:\n" << run.text;
  EXPECT_EQ(summary->states, states);
  EXPECT_EQ(summary->deadlocks, deadlocks);
  EXPECT_EQ(summary->errors, errors);
}

TYPED_TEST(Conformance, S11_doublecounter_random_run) {
  this->check_runs("running/doublecounter", "CT()", this->options(),
                   [](const auto& run) { expect_internal_counting(run, 200); });
}

TYPED_TEST(Conformance, S11_doublecounter_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/doublecounter", "CT()", options, 1,
                   [](const auto& run) { expect_exploration(run, 10201, 1, 0); });
}

TYPED_TEST(Conformance, S11_doublecounter2_random_run) {
  this->check_runs("running/doublecounter2", "CT()", this->options(),
                   [](const auto& run) { expect_internal_counting(run, 200); });
}

TYPED_TEST(Conformance, S11_doublecounter2_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/doublecounter2", "CT()", options, 1,
                   [](const auto& run) { expect_exploration(run, 5251, 1, 0); });
}

TYPED_TEST(Conformance, S11_cyclic_random_run) {
  auto options = this->options();
  options.limit = 1000;
  this->check_runs("running/cyclic", "CT()", options, [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 1000), "stop (reached limit of 1000 states)");
    EXPECT_TRUE(lacks(run.lines, "deadlock"));
  });
}

// 201² states; 0 errors as in the multithread suite's bound-500 variant.
TYPED_TEST(Conformance, S11_cyclic_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/cyclic", "CT()", options, 1,
                   [](const auto& run) { expect_exploration(run, 40401, 0, 0); });
}

TYPED_TEST(Conformance, S11_dining_philo_random_run) {
  this->check_runs("running/dining_philo", "DiningPhilo()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(last_state_header(run.lines), "deadlock!");
  });
}

// 7 philosophers (the documentation's example); 0 errors as in the 8-philosopher variant.
TYPED_TEST(Conformance, S11_dining_philo_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/dining_philo", "DiningPhilo()", options, 1,
                   [](const auto& run) { expect_exploration(run, 27303, 2, 0); });
}

TYPED_TEST(Conformance, S11_dining_philo_flat_random_run) {
  this->check_runs("running/dining_philo_flat", "DiningPhilo()", this->options(),
                   [](const auto& run) {
                     static const std::regex internal_ports("^[0-9]+ internal ports?:$");
                     EXPECT_EQ(run.result.code, kRunOk);
                     const std::vector<StateHeader> headers = state_headers(run.lines);
                     ASSERT_FALSE(headers.empty());
                     EXPECT_EQ(headers.back().summary, "deadlock!");
                     for (std::size_t i = 0; i + 1 < headers.size(); ++i) {
                       ASSERT_TRUE(std::regex_match(headers[i].summary, internal_ports))
                           << "state " << headers[i].state << ": " << headers[i].summary;
                     }
                   });
}

TYPED_TEST(Conformance, S11_dining_philo_flat_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/dining_philo_flat", "DiningPhilo()", options, 1,
                   [](const auto& run) { expect_exploration(run, 117485, 2, 0); });
}

TYPED_TEST(Conformance, S11_priority_rules_guard) {
  this->check_runs("running/priority_rules_guard", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     for (std::uint64_t n = 0; n <= 7; ++n) {
                       EXPECT_EQ(state_header(run.lines, n), "1 interaction:") << "state " << n;
                     }
                     EXPECT_EQ(state_header(run.lines, 8), "deadlock!");
                     const Lines choices = choose_lines(run.lines);
                     ASSERT_EQ(choices.size(), 8u);
                     for (std::size_t i = 0; i < choices.size(); ++i) {
                       const char* expected = i % 2 == 0 ? "ROOT.rdv2: " : "ROOT.rdv1: ";
                       EXPECT_TRUE(has(Lines{choices[i]}, expected)) << choices[i];
                     }
                   });
}

/// The atoms named in a choose line's port values, and its connector (`c1`..`c4`).
std::pair<std::string, std::string> conflicting_choice(const std::string& line) {
  static const std::regex choice(R"(-> choose \[[0-9]+\] ROOT\.(c[1-4]): (.*) at global time )");
  static const std::regex entry(R"(\b([A-D])\.[pq]\(\))");
  std::smatch m;
  if (!std::regex_search(line, m, choice)) return {};
  const std::string values = m[2].str();
  std::set<char> atoms;
  for (auto it = std::sregex_iterator(values.begin(), values.end(), entry);
       it != std::sregex_iterator(); ++it) {
    atoms.insert((*it)[1].str()[0]);
  }
  return {m[1].str(), std::string(atoms.begin(), atoms.end())};
}

TYPED_TEST(Conformance, S11_conflicting) {
  auto options = this->options();
  options.limit = 1000;
  this->check_runs("running_multithread_extra/conflicting", "Comp()", options, [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 1000), "stop (reached limit of 1000 states)");
    EXPECT_TRUE(lacks(run.lines, "deadlock"));
    // (A,B) and (C,D) only ever move together, by their own rendezvous.
    for (const std::string& line : choose_lines(run.lines)) {
      const auto [connector, atoms] = conflicting_choice(line);
      const bool ab = connector == "c1" || connector == "c3";
      ASSERT_EQ(atoms, connector.empty() ? "?" : ab ? "AB" : "CD") << line;
    }
  });
}

TYPED_TEST(Conformance, S11_non_conflicting) {
  auto options = this->options();
  options.limit = 1000;
  this->check_runs(
      "running_multithread_extra/non_conflicting", "Comp()", options, [](const auto& run) {
        EXPECT_EQ(run.result.code, kRunOk);
        const std::vector<StateHeader> headers = state_headers(run.lines);
        ASSERT_EQ(headers.size(), 1001u);
        for (std::uint64_t n = 0; n < 1000; ++n) {
          ASSERT_EQ(headers[n].state, n);
          ASSERT_EQ(headers[n].summary, "2 interactions:") << "state " << n;
        }
        EXPECT_EQ(state_header(run.lines, 1000), "stop (reached limit of 1000 states)");
      });
}

TYPED_TEST(Conformance, S11_non_conflicting_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running_multithread_extra/non_conflicting", "Comp()", options, 1,
                   [](const auto& run) { expect_exploration(run, 4, 0, 0); });
}

}  // namespace
}  // namespace smcbip::tests
