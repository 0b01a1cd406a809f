// pus-console scripts: TCs numbered in order, every refused line located at line:column.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "console/console.h"

namespace smcbip::pus::console {
namespace {

TEST(PusConsoleScript, CommentsAndBlankLinesAreSkipped) {
  const ParsedScript script = parse_script(
      "# a connection test, then housekeeping\n"
      "\n"
      "17 1   # ping\n"
      "  encode 3 5 --sid 1 2\n",
      Config{});
  ASSERT_TRUE(script.errors.empty());
  ASSERT_EQ(script.tcs.size(), 2u);
  EXPECT_EQ(script.tcs[0].line, 3u);
  EXPECT_EQ(script.tcs[1].line, 4u);
  EXPECT_EQ(script.tcs[1].tc.header.service, 3);
  auto decoded = decode_tc(script.tcs[1].bytes, Config{});
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded.value(), script.tcs[1].tc);
}

TEST(PusConsoleScript, SequenceCountsRunPerApidAndContinueFromAGivenOne) {
  const ParsedScript script =
      parse_script("17 1\n17 1 --apid 5\n17 1\n17 1 --seq 10\n17 1\n17 1 --apid 5\n", Config{});
  ASSERT_TRUE(script.errors.empty());
  std::vector<int> counts;
  for (const auto& entry : script.tcs) counts.push_back(entry.tc.primary.sequence_count);
  EXPECT_EQ(counts, (std::vector<int>{0, 0, 1, 10, 11, 1}));
}

TEST(PusConsoleScript, EveryRefusedLineIsLocatedAndNoTcIsKept) {
  const ParsedScript script = parse_script(
      "17 1\n"                // 1: fine
      "3 5 --sid 1 x\n"       // 2: x at column 13
      "20 3 --param 7\n"      // 3: 7 at column 14
      "17 1 --bogus 4\n"      // 4: --bogus at column 6
      "99 1\n"                // 5: 99 at column 1
      "8 1\n"                 // 6: --function missing: the end of the line, column 4
      "17 1 --apid\n"         // 7: --apid without its value at column 6
      "  5 5 --event=0x1g\n"  // 8: --event=0x1g at column 7
      "17 1 5\n",             // 9: an extra word at column 6
      Config{});
  EXPECT_TRUE(script.tcs.empty());
  ASSERT_EQ(script.errors.size(), 8u);
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> where{
      {2, 13}, {3, 14}, {4, 6}, {5, 1}, {6, 4}, {7, 6}, {8, 7}, {9, 6}};
  for (std::size_t i = 0; i < where.size(); ++i) {
    EXPECT_EQ(script.errors[i].line, where[i].first) << script.errors[i].message;
    EXPECT_EQ(script.errors[i].column, where[i].second) << script.errors[i].message;
  }
  EXPECT_EQ(format_error("s.tc", script.errors[0]),
            "s.tc:2:13: error: --sid: expected a structure ID (an integer from 0 to 65535, "
            "decimal or 0x hex), got 'x'");
  EXPECT_NE(script.errors[2].message.find("got '--bogus'"), std::string::npos)
      << script.errors[2].message;
  EXPECT_EQ(script.errors[5].message, "--apid: expected a value after it, got none");
}

TEST(PusConsoleScript, WaitLinesArePausesAndTheirWordsAreChecked) {
  const ParsedScript script = parse_script("17 1\nwait 250  # let the TMs come\n17 1\n", Config{});
  ASSERT_TRUE(script.errors.empty());
  ASSERT_EQ(script.tcs.size(), 3u);
  EXPECT_FALSE(script.tcs[0].wait);
  ASSERT_TRUE(script.tcs[1].wait);
  EXPECT_EQ(script.tcs[1].wait->count(), 250);
  EXPECT_EQ(script.tcs[1].line, 2u);
  EXPECT_EQ(script.tcs[2].tc.primary.sequence_count, 1);
  const ParsedScript bad = parse_script("wait\nwait soon\nwait 3600001\nwait 5 more\n", Config{});
  ASSERT_EQ(bad.errors.size(), 4u);
  EXPECT_EQ(
      format_error("s.tc", bad.errors[0]),
      "s.tc:1:5: error: wait: expected a number of milliseconds from 0 to 3600000, got nothing");
  EXPECT_EQ(bad.errors[1].column, 6u);
  EXPECT_EQ(bad.errors[2].column, 6u);
  EXPECT_EQ(bad.errors[3].column, 8u);
  EXPECT_NE(bad.errors[3].message.find("got 'more' after it"), std::string::npos);
}

TEST(PusConsoleScript, RawLinesAreOctetsSentAsTheyAre) {
  // The ping of the README (1800c00000062f110100007958) with its last CRC octet changed.
  const ParsedScript script = parse_script("raw 1800c00000062f110100007959\n17 1\n", Config{});
  ASSERT_TRUE(script.errors.empty());
  ASSERT_EQ(script.tcs.size(), 2u);
  EXPECT_TRUE(script.tcs[0].raw);
  EXPECT_EQ(script.tcs[0].bytes.size(), 13u);
  EXPECT_EQ(script.tcs[1].tc.primary.sequence_count, 0);  // a raw line numbers nothing
  std::ostringstream out;
  Session session(Config{}, out, nullptr);
  run_script(script, session, std::chrono::milliseconds(0));
  // The decoder's refusal of the octets, as a received packet's row shows it, status not sent.
  EXPECT_EQ(session.rows()[0].status, "not sent");
  EXPECT_EQ(session.rows()[0].kind, "TC");
  EXPECT_NE(session.rows()[0].information.find("bad-crc"), std::string::npos);
  // A raw line that decodes gets the TC's row.
  const ParsedScript valid = parse_script("raw 1800c00000062f110100007958\n", Config{});
  Session valid_session(Config{}, out, nullptr);
  run_script(valid, valid_session, std::chrono::milliseconds(0));
  EXPECT_EQ(valid_session.rows()[0].information, "TC[17,1] are-you-alive connection test");
  const ParsedScript bad = parse_script("raw\nraw 18zz\nraw 18 00\n", Config{});
  ASSERT_EQ(bad.errors.size(), 3u);
  EXPECT_EQ(format_error("s.tc", bad.errors[0]),
            "s.tc:1:4: error: raw: expected the octets in hex, got nothing");
  EXPECT_EQ(bad.errors[1].column, 7u);  // the first 'z'
  EXPECT_EQ(bad.errors[2].column, 8u);  // the word after the octets
}

TEST(PusConsoleScript, WithoutALinkTheTcsAreListedAsNotSent) {
  const ParsedScript script = parse_script("17 1 --apid 0x12\n20 1 --param 7\n", Config{});
  std::ostringstream out;
  Session session(Config{}, out, nullptr);
  run_script(script, session, std::chrono::milliseconds(0));
  EXPECT_EQ(out.str(), session.table());
  EXPECT_EQ(session.table(), table_header() + "\n" +
                                 "1     TC  17   1    -             0      0x12   0      not sent  "
                                 "TC[17,1] are-you-alive connection test\n"
                                 "2     TC  20   1    -             0      0x0    0      not sent  "
                                 "TC[20,1] report parameter values: parameters 7\n");
}

}  // namespace
}  // namespace smcbip::pus::console
