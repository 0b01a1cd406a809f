// pus-console's table: rows of TMs built with the packet library, against text written by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bipc/errors.h"
#include "console/console.h"
#include "console_test_support.h"

namespace smcbip::pus::console {
namespace {

using testing::verification;

/// A TM from APID 0x12, sequence count 3, destination 7, at 100.5 s (fine 0x8000 of 2^16).
Telemetry make_tm(std::uint8_t service, std::uint8_t subtype, Message data) {
  Telemetry tm;
  tm.primary.apid = 0x12;
  tm.primary.sequence_count = 3;
  tm.header.service = service;
  tm.header.subtype = subtype;
  tm.header.destination_id = 7;
  tm.header.time = CucTime{100, 0x8000};
  tm.data = std::move(data);
  return tm;
}

/// The request ID of TC apid 0x12 seq 5.
RequestId tc_apid_12_seq_5() {
  PrimaryHeader tc;
  tc.apid = 0x12;
  tc.sequence_count = 5;
  return RequestId::of(tc);
}

/// Encodes the TM with the packet library and decodes it as pus-console decode does.
Row decoded_row(const Telemetry& tm) {
  std::vector<std::uint8_t> bytes(512);
  auto length = encode(tm, Config{}, bytes);
  EXPECT_TRUE(length.ok());
  bytes.resize(length.ok() ? length.value() : 0);
  return decode_bytes(bytes, Config{});
}

TEST(PusConsoleTable, AcceptanceReportOfAKnownTc) {
  const Row row = decoded_row(make_tm(1, 1, verification(tc_apid_12_seq_5())));
  EXPECT_EQ(format_row(row),
            "1     TM  1    1    100.500       0x12   7      3      ok        "
            "TM[1,1] acceptance success of TC apid 0x12 seq 5");
}

TEST(PusConsoleTable, TheHeaderAlignsWithTheRows) {
  EXPECT_EQ(table_header(),
            "#     dir svc  sub  time          src    dst    seq    status    information");
}

TEST(PusConsoleTable, ConnectionTestReport) {
  EXPECT_EQ(decoded_row(make_tm(17, 2, NoData{})).information,
            "TM[17,2] are-you-alive connection test report");
}

TEST(PusConsoleTable, HousekeepingReport) {
  HousekeepingReport report;
  report.structure_id = 1;
  report.values.push_back(10);
  report.values.push_back(4294967295u);
  const Row row = decoded_row(make_tm(3, 25, report));
  EXPECT_EQ(row.information,
            "TM[3,25] housekeeping parameter report: structure 1, values 10, 4294967295");
  EXPECT_EQ(row.status, "ok");
}

TEST(PusConsoleTable, VerificationFailuresAndSteps) {
  Verification failed = verification(tc_apid_12_seq_5(), 0, 3);
  failed.failure_data.push_back(0x01);
  failed.failure_data.push_back(0xAB);
  const Row rejected = decoded_row(make_tm(1, 2, failed));
  EXPECT_EQ(rejected.status, "failure");
  EXPECT_EQ(rejected.information,
            "TM[1,2] acceptance failure of TC apid 0x12 seq 5, code 3, data 01 ab");
  const Verification step = verification(tc_apid_12_seq_5(), 2);
  EXPECT_EQ(decoded_row(make_tm(1, 5, step)).information,
            "TM[1,5] progress success of TC apid 0x12 seq 5, step 2");
  EXPECT_EQ(decoded_row(make_tm(1, 7, verification(tc_apid_12_seq_5()))).information,
            "TM[1,7] completion success of TC apid 0x12 seq 5");
  EXPECT_EQ(decoded_row(make_tm(1, 8, verification(tc_apid_12_seq_5()))).information,
            "TM[1,8] completion failure of TC apid 0x12 seq 5, code 0");
}

TEST(PusConsoleTable, EventParameterAndTimeReports) {
  EventReport event;
  event.event_id = 9;
  event.aux_data.push_back(0x7F);
  EXPECT_EQ(decoded_row(make_tm(5, 3, event)).information,
            "TM[5,3] medium severity anomaly report: event 9, data 7f");
  ParameterValues values;
  values.values.push_back(IdValue{7, 42});
  EXPECT_EQ(decoded_row(make_tm(20, 2, values)).information,
            "TM[20,2] parameter value report: values 7=42");
  const TimeReport time{.rate_exponent = 2, .time = CucTime{3600, 0x4000}};
  EXPECT_EQ(decoded_row(make_tm(9, 2, time)).information,
            "TM[9,2] CUC time report: rate exponent 2, time 3600.250");
}

TEST(PusConsoleTable, TimeIsTruncatedToMilliseconds) {
  EXPECT_EQ(format_time(CucTime{1, 0xFFFF}, Config{}), "1.999");
  EXPECT_EQ(format_time(CucTime{0, 0}, Config{}), "0.000");
  Config coarse_only;
  coarse_only.cuc_fine_bytes = 0;
  EXPECT_EQ(format_time(CucTime{42, 0}, coarse_only), "42.000");
}

TEST(PusConsoleTable, MalformedPacketsAreRefusedWithReasonAndOffset) {
  std::vector<std::uint8_t> bytes(512);
  auto length = encode(make_tm(17, 2, NoData{}), Config{}, bytes);
  ASSERT_TRUE(length.ok());
  bytes.resize(length.value());
  bytes.back() ^= 1;
  try {
    decode_bytes(bytes, Config{});
    ADD_FAILURE() << "a bad CRC was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("malformed packet: bad-crc at byte ", 0), 0u) << e.what();
  }
  const Row row = malformed_row(4, bytes, Error{Reason::BadCrc, "crc", 17});
  EXPECT_EQ(row.status, "malformed");
  EXPECT_EQ(row.kind, "TM");
  EXPECT_EQ(row.information.rfind("bad-crc at byte 17: crc (21 octets: ", 0), 0u)
      << row.information;
}

TEST(PusConsoleTable, HexTextIsCheckedCharacterByCharacter) {
  EXPECT_EQ(bytes_of_hex("0x18 00:c0", "HEX"), (std::vector<std::uint8_t>{0x18, 0x00, 0xC0}));
  EXPECT_EQ(to_hex(bytes_of_hex("ABcd", "HEX")), "abcd");
  EXPECT_THROW(bytes_of_hex("18 0", "HEX"), InputError);
  EXPECT_THROW(bytes_of_hex("", "HEX"), InputError);
  try {
    bytes_of_hex("18 0g", "HEX");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "HEX: expected the second hex digit of an octet at character 5");
  }
}

}  // namespace
}  // namespace smcbip::pus::console
