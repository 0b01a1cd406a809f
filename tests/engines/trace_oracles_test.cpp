// Unit tests of the trace oracles themselves: grep's basic-regex semantics, exact state headers.
#include "tests/engines/trace_oracles.h"

#include <gtest/gtest.h>

namespace smcbip::tests {
namespace {

const Lines kTrace = split_lines(
    "[BIP ENGINE]: BIP Engine (version 2)\n"
    "[BIP ENGINE]: state #0 and global time 0: 2 interactions:\n"
    "[BIP ENGINE]:   [0] ROOT.myBroadcast: myAtom1.p() myAtom3.p() [ 0, +INFTY [\n"
    "[BIP ENGINE]:   [1] ROOT.myBroadcast: myAtom1.p() myAtom2.p() [ 0, +INFTY [\n"
    "[BIP ENGINE]: -> choose [1] ROOT.myBroadcast: myAtom1.p() myAtom2.p() at global time 0\n"
    "New value: 1\n"
    "[BIP ENGINE]: state #1 and global time 1s500ms: 11 interactions:\n"
    "[BIP ENGINE]:   [0] ROOT.A.p1 ] 1s, 2s ]\n"
    "[BIP ENGINE]: -> choose [0] ROOT.A.p1 at global time 2s\n"
    "[BIP ENGINE]: state #10 and global time 2s: deadlock!\n"
    "[BIP ENGINE]: ERROR: [BIP ENGINE]: state #11 and global time 7s: violation of the following "
    "timing constraints:\n"
    "[BIP ENGINE]:   ROOT.C2: A.p() C.p() [ 4s, +INFTY [ eager\n");

TEST(TraceOracles, SplitLinesDropsTerminatorsButKeepsEmptyLines) {
  EXPECT_EQ(split_lines("a\r\n\nb"), (Lines{"a", "", "b"}));
  EXPECT_EQ(split_lines("a\n"), (Lines{"a"}));
  EXPECT_TRUE(split_lines("").empty());
}

TEST(TraceOracles, ParenthesesArePlainCharactersInBasicRegex) {
  EXPECT_TRUE(has(kTrace, "myBroadcast:.*myAtom1.p() .*myAtom3.p()"));
  EXPECT_TRUE(lacks(kTrace, "myAtom2.p() .*myAtom3.p()"));
  EXPECT_TRUE(has(kTrace, "ERROR: .*violation of the following timing constraints:"));
  EXPECT_TRUE(lacks(kTrace, "myAtom(1|2).p"));  // `|` is literal too
}

TEST(TraceOracles, PlusIsPlainAndDotStarMatchesAnyString) {
  EXPECT_TRUE(has(kTrace, "C2.*A.p.*C.p.*4s.*+INFTY"));
  EXPECT_TRUE(has(kTrace, "state #1.*:.*deadlock"));  // the loose original: #1 matches #10
  EXPECT_TRUE(has(kTrace, "choose.*A.p1.*global time 2s$"));
  EXPECT_TRUE(lacks(kTrace, "choose.*A.p1.*global time 2$"));
}

TEST(TraceOracles, CountTailAndErrorPatterns) {
  EXPECT_EQ(count(kTrace, "1 interaction"), 1u);  // matches `11 interactions`, as grep would
  EXPECT_EQ(count(kTrace, "choose"), 2u);
  EXPECT_TRUE(tail_has(kTrace, 3, "state #10.*:.*deadlock"));
  EXPECT_FALSE(tail_has(kTrace, 2, "state #10.*:.*deadlock"));
  EXPECT_TRUE(tail_has(kTrace, 100, "BIP Engine (version"));
  EXPECT_TRUE(has(kTrace, error_line_pattern(7)));
  EXPECT_FALSE(has(kTrace, error_line_pattern(3)));
  EXPECT_TRUE(
      has(Lines{"[BIP ENGINE]: ERROR: cycle in priorities! (a < b < a)"}, error_line_pattern(3)));
}

TEST(TraceOracles, StateHeaderIsThatOfStateNItself) {
  EXPECT_EQ(state_header(kTrace, 0), "2 interactions:");
  EXPECT_EQ(state_header(kTrace, 1), "11 interactions:");
  EXPECT_EQ(state_header(kTrace, 10), "deadlock!");
  EXPECT_EQ(state_time(kTrace, 1), "1s500ms");
  EXPECT_EQ(state_time(kTrace, 10), "2s");
  // The time-safety error line repeats the header form but is not a header.
  EXPECT_FALSE(find_state_header(kTrace, 11).has_value());
  EXPECT_EQ(state_header(kTrace, 11), "<no state #11>");
  EXPECT_EQ(state_header(kTrace, 2), "<no state #2>");
  EXPECT_EQ(last_state_header(kTrace), "deadlock!");
  EXPECT_EQ(state_headers(kTrace).size(), 3u);
}

TEST(TraceOracles, ListingAndChooseLines) {
  EXPECT_EQ(listing(kTrace, 0).size(), 2u);
  EXPECT_EQ(listing(kTrace, 1), (Lines{"[BIP ENGINE]:   [0] ROOT.A.p1 ] 1s, 2s ]"}));
  EXPECT_TRUE(listing(kTrace, 10).empty());
  EXPECT_EQ(choose_lines(kTrace).size(), 2u);
}

TEST(TraceOracles, ExplorationSummaryParsesSingularAndPlural) {
  const auto plural = exploration_summary(
      Lines{"[BIP ENGINE]: computing reachable states:..... found 10201 reachable states, 2 "
            "deadlocks, 0 timelocks, and 3 errors in 4 states"});
  ASSERT_TRUE(plural.has_value());
  EXPECT_EQ(plural->states, 10201u);
  EXPECT_EQ(plural->deadlocks, 2u);
  EXPECT_EQ(plural->timelocks, 0u);
  EXPECT_EQ(plural->errors, 3u);
  EXPECT_EQ(plural->error_states, 4u);
  const auto singular = exploration_summary(
      Lines{"[BIP ENGINE]: computing reachable states: found 1 reachable state, 1 deadlock, 1 "
            "timelock, and 1 error in 1 state"});
  ASSERT_TRUE(singular.has_value());
  EXPECT_EQ(singular->states, 1u);
  EXPECT_EQ(singular->errors, 1u);
  EXPECT_EQ(exploration_summary(kTrace), std::nullopt);
}

TEST(TraceOracles, DescribeDifferenceNamesTheFirstDifference) {
  EXPECT_EQ(describe_difference(Lines{"a", "b"}, Lines{"a", "b"}), "");
  EXPECT_NE(describe_difference(Lines{"a", "c"}, Lines{"a", "b"}).find("line 2"),
            std::string::npos);
  EXPECT_NE(describe_difference(Lines{"a"}, Lines{"a", "b"}).find("missing line: \"b\""),
            std::string::npos);
}

}  // namespace
}  // namespace smcbip::tests
