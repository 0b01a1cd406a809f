// Byte-exact checks against vectors published with other implementations and the standards.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "packets/packets.h"

namespace smcbip::pus {
namespace {

std::vector<std::uint8_t> bytes_of(std::string_view text) { return {text.begin(), text.end()}; }

// The check value of CRC-16/CCITT-FALSE (CRC-16/IBM-3740 in the reveng CRC catalogue), also
// asserted by DLR-RY/outpost-core modules/utils/test/outpost/utils/coding/crc16_test.cpp
// (testRandom2) and by dueca/dueca test/crc-ccitt/crctest.cxx.
TEST(PusCrc, CheckValueOf123456789) { EXPECT_EQ(crc16(bytes_of("123456789")), 0x29B1); }

// ECSS-E-70-41A annex A test sequences, as asserted by DLR-RY/outpost-core
// modules/utils/test/outpost/utils/coding/crc16_test.cpp (testEcssPus1..4, testEcssPus4Total).
TEST(PusCrc, EcssAnnexSequences) {
  EXPECT_EQ(crc16(std::vector<std::uint8_t>{0x00, 0x00}), 0x1D0F);
  EXPECT_EQ(crc16(std::vector<std::uint8_t>{0x00, 0x00, 0x00}), 0xCC9C);
  EXPECT_EQ(crc16(std::vector<std::uint8_t>{0xAB, 0xCD, 0xEF, 0x01}), 0x04A2);
  EXPECT_EQ(crc16(std::vector<std::uint8_t>{0x14, 0x56, 0xF8, 0x9A, 0x00, 0x01}), 0x7FD5);
  EXPECT_EQ(crc16(std::vector<std::uint8_t>{0x14, 0x56, 0xF8, 0x9A, 0x00, 0x01, 0x7F, 0xD5}), 0);
  // outpost-core testRandom3: two 0xFF octets give 0.
  EXPECT_EQ(crc16(std::vector<std::uint8_t>{0xFF, 0xFF}), 0);
}

// The PUS-C ping TC[17,1] with APID 0x02 and sequence count 0x34 of us-irs/spacepackets-py
// tests/ecss/test_pus_tc.py (test_packed) and us-irs/spacepackets-rs src/ecss/tc.rs
// (verify_test_tc_raw, verify_crc_no_app_data): 18 02 C0 34 00 06 2F 11 01 00 00 EE 63.
constexpr std::array<std::uint8_t, 13> kPingTc{0x18, 0x02, 0xC0, 0x34, 0x00, 0x06, 0x2F,
                                               0x11, 0x01, 0x00, 0x00, 0xEE, 0x63};

Telecommand ping_tc() {
  Telecommand tc;
  tc.primary.apid = 0x02;
  tc.primary.sequence_count = 0x34;
  tc.header.service = 17;
  tc.header.subtype = 1;
  tc.data = NoData{};
  return tc;
}

TEST(PusReferenceVectors, PingTcEncodesByteExact) {
  std::array<std::uint8_t, 64> out{};
  auto length = encode(ping_tc(), Config{}, out);
  ASSERT_TRUE(length.ok()) << length.error().message;
  ASSERT_EQ(length.value(), kPingTc.size());
  EXPECT_TRUE(std::equal(kPingTc.begin(), kPingTc.end(), out.begin()));
}

TEST(PusReferenceVectors, PingTcDecodes) {
  auto tc = decode_tc(kPingTc, Config{});
  ASSERT_TRUE(tc.ok()) << tc.error().message;
  const Telecommand& t = tc.value();
  EXPECT_EQ(t.primary.version, 0);
  EXPECT_EQ(t.primary.type, PacketType::Tc);
  EXPECT_TRUE(t.primary.secondary_header);
  EXPECT_EQ(t.primary.apid, 0x02);
  EXPECT_EQ(t.primary.sequence_flags, SequenceFlags::Unsegmented);
  EXPECT_EQ(t.primary.sequence_count, 0x34);
  EXPECT_EQ(t.primary.data_length, 6);
  EXPECT_EQ(t.header.pus_version, 2);
  EXPECT_EQ(t.header.ack_flags, 0xF);
  EXPECT_EQ(t.header.service, 17);
  EXPECT_EQ(t.header.subtype, 1);
  EXPECT_EQ(t.header.source_id, 0);
  EXPECT_TRUE(std::holds_alternative<NoData>(t.data));
}

// us-irs/spacepackets-rs src/ecss/tc.rs test_custom_setters: APID 0x7FF, sequence count
// 0x3FFF, ack flags 0b0011 and source ID 0xFFFF give octets 1F FF FF FF, 23 at offset 6 and
// FF FF at offsets 9 and 10.
TEST(PusReferenceVectors, TcFieldsAtTheirMaximum) {
  Telecommand tc = ping_tc();
  tc.primary.apid = 0x7FF;
  tc.primary.sequence_count = 0x3FFF;
  tc.header.ack_flags = 0b0011;
  tc.header.source_id = 0xFFFF;
  std::array<std::uint8_t, 64> out{};
  ASSERT_TRUE(encode(tc, Config{}, out).ok());
  EXPECT_EQ(out[0], 0x1F);
  EXPECT_EQ(out[1], 0xFF);
  EXPECT_EQ(out[2], 0xFF);
  EXPECT_EQ(out[3], 0xFF);
  EXPECT_EQ(out[6], 0x23);
  EXPECT_EQ(out[9], 0xFF);
  EXPECT_EQ(out[10], 0xFF);
}

// The PUS-C ping reply TM[17,2] of us-irs/spacepackets-py tests/ecss/test_pus_tm.py
// (test_raw) and us-irs/spacepackets-rs src/ecss/tm.rs (verify_raw_ping_reply): APID 0x123,
// sequence count 0x234, time stamp 00 01 02 03 04 05 06, data length 15, 22 octets; the
// references check the CRC with crc-ccitt-false over the first 20 octets, so it is not
// repeated here: the packet must decode and its CRC over all 22 octets must be 0.
constexpr std::array<std::uint8_t, 20> kPingReplyWithoutCrc{
    0x09, 0x23, 0xC2, 0x34, 0x00, 0x0F, 0x20, 0x11, 0x02, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06};

// A seven-octet time as in the reference: four coarse and three fine octets, no P-field.
Config seven_octet_time() {
  Config config;
  config.cuc_fine_bytes = 3;
  return config;
}

TEST(PusReferenceVectors, PingReplyTmEncodesByteExact) {
  Telemetry tm;
  tm.primary.apid = 0x123;
  tm.primary.sequence_count = 0x234;
  tm.header.service = 17;
  tm.header.subtype = 2;
  tm.header.time = CucTime{0x00010203, 0x040506};
  std::array<std::uint8_t, 64> out{};
  auto length = encode(tm, seven_octet_time(), out);
  ASSERT_TRUE(length.ok()) << length.error().message;
  ASSERT_EQ(length.value(), 22u);
  EXPECT_TRUE(std::equal(kPingReplyWithoutCrc.begin(), kPingReplyWithoutCrc.end(), out.begin()));
  EXPECT_EQ(crc16(std::span<const std::uint8_t>(out.data(), 22)), 0);

  auto back = decode_tm(std::span<const std::uint8_t>(out.data(), 22), seven_octet_time());
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back.value().primary.apid, 0x123);
  EXPECT_EQ(back.value().primary.sequence_count, 0x234);
  EXPECT_EQ(back.value().primary.data_length, 15);
  EXPECT_EQ(back.value().header.time, (CucTime{0x00010203, 0x040506}));
}

// ECSS-E-ST-70-41C 5.4.11.4 (and us-irs/spacepackets-py RequestId.from_sp_header): the request
// ID is the TC's packet ID and sequence control, i.e. the first four octets of the ping TC.
TEST(PusReferenceVectors, AcceptanceReportCarriesTheRequestIdOfThePing) {
  auto tc = decode_tc(kPingTc, Config{});
  ASSERT_TRUE(tc.ok());
  Telemetry tm;
  tm.primary.apid = 0x02;
  tm.header.service = 1;
  tm.header.subtype = 1;
  tm.data = Verification{RequestId::of(tc.value().primary), 0, 0, {}};
  std::array<std::uint8_t, 64> out{};
  auto length = encode(tm, Config{}, out);
  ASSERT_TRUE(length.ok());
  const std::size_t data_at = 6 + tm_secondary_header_length(Config{});
  ASSERT_EQ(length.value(), data_at + 4 + 2);
  EXPECT_TRUE(std::equal(kPingTc.begin(), kPingTc.begin() + 4, out.begin() + data_at));
}

// us-irs/spacepackets-rs src/time/cuc.rs: test_write_no_fractions (CCSDS epoch, four-octet
// counter 0x20102030, no fractions: P-field time code 0b001, coarse bits 0b11, fine bits 0b00)
// and test_write_with_medium_fractions (counter 0x30303030, two fine octets 30000).
TEST(PusReferenceVectors, CucWithPField) {
  Config config;
  config.cuc_p_field = true;
  config.cuc_time_code = 0b001;
  config.cuc_fine_bytes = 0;
  std::array<std::uint8_t, 8> out{};
  auto written = encode_cuc(CucTime{0x20102030, 0}, config, out);
  ASSERT_TRUE(written.ok());
  EXPECT_EQ(written.value(), 5u);
  EXPECT_EQ(out[0], 0x1C);
  EXPECT_EQ(out[1], 0x20);
  EXPECT_EQ(out[2], 0x10);
  EXPECT_EQ(out[3], 0x20);
  EXPECT_EQ(out[4], 0x30);

  config.cuc_fine_bytes = 2;
  written = encode_cuc(CucTime{0x30303030, 30000}, config, out);
  ASSERT_TRUE(written.ok());
  EXPECT_EQ(written.value(), 7u);
  EXPECT_EQ(out[0] >> 4 & 0x7, 0b001);
  EXPECT_EQ(out[0] >> 2 & 0x3, 0b11);
  EXPECT_EQ(out[0] & 0x3, 2);
  EXPECT_EQ(out[1], 0x30);
  EXPECT_EQ(out[4], 0x30);
  EXPECT_EQ(out[5] << 8 | out[6], 30000);

  auto back = decode_cuc(config, std::span<const std::uint8_t>(out.data(), 7));
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back.value(), (CucTime{0x30303030, 30000}));
  EXPECT_EQ(decode_cuc(config, std::span<const std::uint8_t>(out.data(), 6)).reason(),
            Reason::TooShort);
}

}  // namespace
}  // namespace smcbip::pus
