// pus-console's TC syntax: encode then decode round trips for every TC subtype, octets derived
// by hand, and the words it refuses.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bipc/errors.h"
#include "console/console.h"

namespace smcbip::pus::console {
namespace {

/// The words of `pus-console encode LINE`, read by the encode command's own declaration.
TcWords words_of(const std::string& line) {
  CLI::App app;
  TcWords words;
  register_tc_options(app, words);
  app.parse(line, false);
  return words;
}

std::vector<std::uint8_t> encode_line(const std::string& line) {
  return encode_words(words_of(line), Config{});
}

/// encode LINE, then decode: the row's columns and information are as expected, and decoding
/// gives back the TC the words describe.
void check_round_trip(const std::string& line, const std::string& information) {
  SCOPED_TRACE(line);
  const std::vector<std::uint8_t> bytes = encode_line(line);
  const Row row = decode_bytes(bytes, Config{});
  EXPECT_EQ(row.kind, "TC");
  EXPECT_EQ(row.status, "valid");
  EXPECT_EQ(row.information, information);
  auto decoded = decode_tc(bytes, Config{});
  ASSERT_TRUE(decoded.ok());
  BuiltTc built = build_tc(words_of(line), Config{});
  built.tc.primary.data_length = static_cast<std::uint16_t>(bytes.size() - 7);  // set by encoding
  EXPECT_EQ(decoded.value(), built.tc);
  EXPECT_EQ(row.service, std::to_string(built.tc.header.service));
  EXPECT_EQ(row.subtype, std::to_string(built.tc.header.subtype));
}

TEST(PusConsoleEncode, RoundTripsEverySupportedTcSubtype) {
  const std::string ping = to_hex(encode_line("17 1 --apid 5 --seq 1"));
  check_round_trip("3 5 --sid 1 2",
                   "TC[3,5] enable periodic housekeeping reports: structures 1, 2");
  check_round_trip("3 6 --sid 0xffff",
                   "TC[3,6] disable periodic housekeeping reports: structures 65535");
  check_round_trip("5 5 --event 4", "TC[5,5] enable event report generation: events 4");
  check_round_trip("5 6 --event 4 5", "TC[5,6] disable event report generation: events 4, 5");
  check_round_trip("8 1 --function 3 --arg 1=5 2=0x10",
                   "TC[8,1] perform a function: function 3, arguments 1=5, 2=16");
  check_round_trip("8 1 --function 9", "TC[8,1] perform a function: function 9, arguments none");
  check_round_trip("9 1 --rate 3", "TC[9,1] set the time report generation rate: rate exponent 3");
  check_round_trip("11 4 --release 100:32768=" + ping,
                   "TC[11,4] insert activities into the time-based schedule: at 100.500 "
                   "TC[17,1] apid 0x5 seq 1");
  check_round_trip("12 1 --pmon 7",
                   "TC[12,1] enable parameter monitoring definitions: "
                   "monitoring definitions 7");
  check_round_trip("12 2 --pmon 7 8",
                   "TC[12,2] disable parameter monitoring definitions: "
                   "monitoring definitions 7, 8");
  check_round_trip("17 1", "TC[17,1] are-you-alive connection test");
  check_round_trip("19 1 --action 12=" + ping,
                   "TC[19,1] add event-action definitions: on event 12 TC[17,1] apid 0x5 seq 1");
  check_round_trip("19 4 --event 12", "TC[19,4] enable event-action definitions: events 12");
  check_round_trip("20 1 --param 7 8", "TC[20,1] report parameter values: parameters 7, 8");
  check_round_trip("20 3 --param 7=42", "TC[20,3] set parameter values: values 7=42");
  check_round_trip("23 1 --repo logs --file a.bin --size 0x100",
                   "TC[23,1] create a file: repository 'logs', file 'a.bin', maximum size 256");
  check_round_trip("23 2 --file a.bin", "TC[23,2] delete a file: repository '', file 'a.bin'");
  check_round_trip("23 3 --repo a/b --file c",
                   "TC[23,3] report the attributes of a file: repository 'a/b', file 'c'");
  check_round_trip("23 14 --operation 2 --repo a --file b --to-file c",
                   "TC[23,14] copy a file: operation 2, repository 'a', file 'b' to repository "
                   "'', file 'c'");
}

// TC[17,1] from the primary header (CCSDS 133.0-B-2 4.1.3) and the TC secondary header
// (ECSS-E-ST-70-41C 7.4.3.1) written out by hand.
TEST(PusConsoleEncode, HeaderOptionsGiveTheOctetsDerivedByHand) {
  const std::vector<std::uint8_t> bytes =
      encode_line("17 1 --apid 0x12 --seq 5 --source 0x0102 --ack ac");
  // version 000, type 1, secondary header 1, APID 0x012: 0001 1000 0001 0010;
  // unsegmented 11, count 5: 0xC005; data length 5 + 2 - 1 = 6.
  // PUS version 2 and ack flags c (bit 3) + a (bit 0) = 0x9: 0x29; 17; 1; source 0x0102.
  const std::vector<std::uint8_t> head{0x18, 0x12, 0xC0, 0x05, 0x00, 0x06,
                                       0x29, 0x11, 0x01, 0x01, 0x02};
  ASSERT_EQ(bytes.size(), head.size() + 2);
  EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin(), bytes.end() - 2), head);
  EXPECT_EQ(crc16(bytes), 0) << "the packet ends with its own CRC";
  const Row row = decode_bytes(bytes, Config{});
  EXPECT_EQ(row.source, "258");
  EXPECT_EQ(row.destination, "0x12");
  EXPECT_EQ(row.sequence, "5");
  EXPECT_EQ(row.time, "-");
}

TEST(PusConsoleEncode, AckFlagsTakeLettersNoneOrANumber) {
  EXPECT_EQ(build_tc(words_of("17 1 --ack none"), Config{}).tc.header.ack_flags, 0);
  EXPECT_EQ(build_tc(words_of("17 1 --ack sp"), Config{}).tc.header.ack_flags, 0x6);
  EXPECT_EQ(build_tc(words_of("17 1 --ack 12"), Config{}).tc.header.ack_flags, 12);
  EXPECT_EQ(build_tc(words_of("17 1"), Config{}).tc.header.ack_flags, 0xF);
  EXPECT_THROW(build_tc(words_of("17 1 --ack aa"), Config{}), TcSyntaxError);
  EXPECT_THROW(build_tc(words_of("17 1 --ack x"), Config{}), TcSyntaxError);
  EXPECT_THROW(build_tc(words_of("17 1 --ack 16"), Config{}), TcSyntaxError);
}

/// The option and word a refusal names, and a part of what it says was expected.
void expect_refusal(const std::string& line, const std::string& option, const std::string& word,
                    const std::string& expected) {
  SCOPED_TRACE(line);
  try {
    build_tc(words_of(line), Config{});
    ADD_FAILURE() << "accepted";
  } catch (const TcSyntaxError& e) {
    EXPECT_EQ(e.option(), option);
    EXPECT_EQ(e.word(), word);
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(PusConsoleEncode, RefusalsNameTheWordAndWhatWasExpected) {
  expect_refusal("99 1", "SERVICE", "99", "expected a TC the console knows");
  expect_refusal("17 2", "SUBTYPE", "2", "expected a TC the console knows");
  expect_refusal("seventeen 1", "SERVICE", "seventeen", "expected a service type");
  expect_refusal("17 1 --sid 1", "--sid", "", "takes no such field; expected no fields");
  expect_refusal("3 5 --sid 1 x", "--sid", "x", "expected a structure ID");
  expect_refusal("3 5 --sid 65536", "--sid", "65536", "from 0 to 65535");
  expect_refusal("20 3 --param 7", "--param", "7", "expected ID=VALUE");
  expect_refusal("20 3 --param 7=4294967296", "--param", "7=4294967296", "expected a value");
  expect_refusal("8 1", "--function", "", "expected --function ID");
  expect_refusal("9 1 --rate 256", "--rate", "256", "expected a rate exponent");
  expect_refusal("17 1 --seq 16384", "--seq", "16384", "from 0 to 16383");
  expect_refusal("11 4 --release 5=1800", "--release", "5=1800", "expected a whole TC in hex");
  expect_refusal("11 4 --release 5=18zz", "--release", "5=18zz", "expected a hex digit");
  expect_refusal("23 1 --file a", "--size", "", "expected [--repo PATH] --file NAME --size N");
  expect_refusal("23 14 --operation 1 --file a", "--to-file", "", "got no --to-file");
  expect_refusal("23 2 --file a --size 3", "--size", "", "takes no such field");
  expect_refusal("23 2 --file " + std::string(65, 'x'), "--file", std::string(65, 'x'),
                 "expected at most 64 octets");
  expect_refusal("23 14 --operation 65536 --file a --to-file b", "--operation", "65536",
                 "expected an operation ID");
}

TEST(PusConsoleEncode, EncodeWordsReportsAUsageError) {
  EXPECT_THROW(encode_words(words_of("17 1 --apid 2048"), Config{}), UsageError);
}

}  // namespace
}  // namespace smcbip::pus::console
