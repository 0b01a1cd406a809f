// Conformance oracles of EXPECTED.md section 6, "Untimed structure, data transfer and
// Petri-net checks" (R18-R31, R57, R58) and "Invariants" (R68, R69).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "tests/engines/conformance_suite.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::kRunOk;

template <class Engine>
class ConformanceStructure : public ConformanceFixture<Engine> {};
TYPED_TEST_SUITE(ConformanceStructure, AllModels, EngineNames);

TYPED_TEST(ConformanceStructure, R18_double_compound) {
  this->check_runs("running/double_compound", "System()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(count(run.lines, "1 interaction"), 1001u);
    EXPECT_EQ(state_header(run.lines, 1001), "deadlock!");
  });
}

TYPED_TEST(ConformanceStructure, R19_and_expressions) {
  this->check_runs("running/and_expressions", "AndExpressions()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "1 interaction"), 15u);
                     EXPECT_EQ(state_header(run.lines, 15), "deadlock!");
                   });
}

TYPED_TEST(ConformanceStructure, R20_or_expressions) {
  this->check_runs("running/or_expressions", "OrExpressions()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(count(run.lines, "choose.*single.*sync"), 4u);
                     EXPECT_EQ(state_header(run.lines, 4), "deadlock!");
                   });
}

TYPED_TEST(ConformanceStructure, R21_petri_net) {
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

TYPED_TEST(ConformanceStructure, R22_petri_net_non_safe) {
  this->check_silent_error("running/petri_net_non_safe", "MyCompoundType()",
                           engines::kNonOneSafeNet);
}

TYPED_TEST(ConformanceStructure, R23_petri_net_non_deterministic) {
  this->check_silent_error("running/petri_net_non_deterministic", "MyCompoundType()",
                           engines::kNonDeterministicNet);
}

TYPED_TEST(ConformanceStructure, R24_petri_net_non_deterministic2) {
  this->check_silent_error("running/petri_net_non_deterministic2", "MyCompoundType()",
                           engines::kNonDeterministicNet);
}

TYPED_TEST(ConformanceStructure, R25_petri_net_non_deterministic3) {
  this->check_silent_error("running/petri_net_non_deterministic3", "MyCompoundType()",
                           engines::kNonDeterministicNet);
}

TYPED_TEST(ConformanceStructure, R26_petri_net_deterministic) {
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

TYPED_TEST(ConformanceStructure, R27_simple10counter) {
  this->check_runs("running/simple10counter", "CT()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 0), "deadlock!");
  });
}

TYPED_TEST(ConformanceStructure, R28_atom_internal_transitions) {
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

TYPED_TEST(ConformanceStructure, R29_internal_export_compound) {
  this->check_runs("running/internal_export_compound", "BIG_CT()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     EXPECT_EQ(state_header(run.lines, 0), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 1), "1 internal port:");
                     EXPECT_EQ(state_header(run.lines, 2), "1 interaction:");
                     EXPECT_EQ(state_header(run.lines, 3), "deadlock!");
                   });
}

TYPED_TEST(ConformanceStructure, R30_multi_export_atom) {
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

TYPED_TEST(ConformanceStructure, R31_multi_export_compound) {
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

TYPED_TEST(ConformanceStructure, R57_multi_export_compound2) {
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

TYPED_TEST(ConformanceStructure, R58_const_data) {
  this->check_runs("running/const_data", "Top()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 25), "2 internal ports:");
    EXPECT_EQ(state_header(run.lines, 27), "deadlock!");
  });
}

// ---- Invariants ------------------------------------------------------------------------------

TYPED_TEST(ConformanceStructure, R68_invariants) {
  this->check_runs("running/invariants", "CT()", this->options(), [](const auto& run) {
    expect_run_error(run, engines::kInvariantViolation);
    EXPECT_TRUE(has(run.lines, "state #202"));
    EXPECT_TRUE(find_state_header(run.lines, 202).has_value());
    EXPECT_TRUE(has(run.lines, "ERROR.*invariant.*totalUse2"));
  });
}

TYPED_TEST(ConformanceStructure, R69_invariants2) {
  this->check_runs("running/invariants2", "CT()", this->options(), [](const auto& run) {
    expect_run_error(run, engines::kInvariantViolation);
    EXPECT_TRUE(has(run.lines, "state #200"));
    EXPECT_TRUE(find_state_header(run.lines, 200).has_value());
    EXPECT_TRUE(has(run.lines, "ERROR.*invariant.*use12"));
  });
}

}  // namespace
}  // namespace smcbip::tests
