// The decoder refuses every class of malformed packet with its reason.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "packets/packets.h"
#include "random_packets.h"

namespace smcbip::pus {
namespace {

using Bytes = std::vector<std::uint8_t>;

// The reference ping TC[17,1] (us-irs/spacepackets-py tests/ecss/test_pus_tc.py).
const Bytes kPingTc{0x18, 0x02, 0xC0, 0x34, 0x00, 0x06, 0x2F, 0x11, 0x01, 0x00, 0x00, 0xEE, 0x63};

// Sets the length field to the octets present and recomputes the CRC: only the change made
// by the test is wrong in the packet.
Bytes refresh(Bytes packet) {
  const std::size_t n = packet.size();
  packet[4] = static_cast<std::uint8_t>((n - 7) >> 8);
  packet[5] = static_cast<std::uint8_t>(n - 7);
  const std::uint16_t crc = crc16(std::span<const std::uint8_t>(packet.data(), n - 2));
  packet[n - 2] = static_cast<std::uint8_t>(crc >> 8);
  packet[n - 1] = static_cast<std::uint8_t>(crc);
  return packet;
}

// A valid TC of the given type and application data octets (CRC and length fixed up).
Bytes tc_with_data(std::uint8_t service, std::uint8_t subtype, const Bytes& data) {
  Bytes packet(kPingTc.begin(), kPingTc.begin() + 11);
  packet[7] = service;
  packet[8] = subtype;
  packet.insert(packet.end(), data.begin(), data.end());
  packet.resize(packet.size() + 2);
  return refresh(packet);
}

Reason tc_reason(const Bytes& packet, const Config& config = Config{}) {
  auto result = decode_tc(packet, config);
  EXPECT_FALSE(result.ok());
  return result.ok() ? Reason::BadConfig : result.reason();
}

TEST(PusMalformed, TheReferencePacketIsAccepted) {
  EXPECT_TRUE(decode_tc(kPingTc, Config{}).ok());
  EXPECT_TRUE(decode_tc(refresh(kPingTc), Config{}).ok());
}

TEST(PusMalformed, TooShort) {
  EXPECT_EQ(tc_reason(Bytes{0x18, 0x02, 0xC0}), Reason::TooShort);
  EXPECT_EQ(tc_reason(Bytes{}), Reason::TooShort);
  // A consistent length field, but no room for the secondary header and the CRC.
  EXPECT_EQ(tc_reason(refresh(Bytes{0x18, 0x02, 0xC0, 0x34, 0, 0, 0x2F, 0x11, 0, 0})),
            Reason::TooShort);
  // [20,1] announcing three parameter IDs and carrying two.
  EXPECT_EQ(tc_reason(tc_with_data(20, 1, {3, 0, 1, 0, 2})), Reason::TooShort);
}

TEST(PusMalformed, LengthMismatch) {
  Bytes truncated(kPingTc.begin(), kPingTc.end() - 1);
  EXPECT_EQ(tc_reason(truncated), Reason::LengthMismatch);
  Bytes too_long = kPingTc;
  too_long[4] = 0xFF;
  too_long[5] = 0xFF;
  EXPECT_EQ(tc_reason(too_long), Reason::LengthMismatch);
}

TEST(PusMalformed, TrailingBytes) {
  Bytes extra = kPingTc;
  extra.push_back(0);
  EXPECT_EQ(tc_reason(extra), Reason::TrailingBytes);
  // [17,1] carries no application data.
  EXPECT_EQ(tc_reason(tc_with_data(17, 1, {0x55})), Reason::TrailingBytes);
  // [20,1] with one ID and one octet more.
  EXPECT_EQ(tc_reason(tc_with_data(20, 1, {1, 0, 7, 9})), Reason::TrailingBytes);
}

TEST(PusMalformed, BadCrc) {
  Bytes packet = kPingTc;
  packet.back() ^= 1;
  EXPECT_EQ(tc_reason(packet), Reason::BadCrc);
  auto result = decode_tc(packet, Config{});
  EXPECT_EQ(result.error().offset, 11u);
}

TEST(PusMalformed, WrongVersion) {
  Bytes packet = kPingTc;
  packet[0] |= 0x20;  // packet version number 1
  EXPECT_EQ(tc_reason(refresh(packet)), Reason::WrongVersion);
}

TEST(PusMalformed, WrongPusVersion) {
  Bytes packet = kPingTc;
  packet[6] = 0x1F;  // PUS-A/B version 1
  EXPECT_EQ(tc_reason(refresh(packet)), Reason::WrongPusVersion);
}

TEST(PusMalformed, WrongPacketTypeAndNoSecondaryHeader) {
  EXPECT_EQ(decode_tm(kPingTc, Config{}).reason(), Reason::WrongPacketType);
  Bytes packet = kPingTc;
  packet[0] &= static_cast<std::uint8_t>(~0x08);
  EXPECT_EQ(tc_reason(refresh(packet)), Reason::NoSecondaryHeader);
}

TEST(PusMalformed, UnknownServiceAndSubtype) {
  EXPECT_EQ(tc_reason(tc_with_data(42, 1, {})), Reason::UnknownService);
  EXPECT_EQ(tc_reason(tc_with_data(17, 3, {})), Reason::UnknownSubtype);
  // [17,2] exists, but as telemetry.
  EXPECT_EQ(tc_reason(tc_with_data(17, 2, {})), Reason::UnknownSubtype);
}

TEST(PusMalformed, CapacityExceeded) {
  Bytes ids{static_cast<std::uint8_t>(kMaxItems + 1)};
  for (std::size_t i = 0; i <= kMaxItems; ++i) ids.insert(ids.end(), {0, 1});
  EXPECT_EQ(tc_reason(tc_with_data(20, 1, ids)), Reason::CapacityExceeded);
}

TEST(PusMalformed, BadPFieldIsABadField) {
  Config config;
  config.cuc_p_field = true;
  Telemetry tm;
  tm.header.service = 17;
  tm.header.subtype = 2;
  std::array<std::uint8_t, 64> out{};
  auto length = encode(tm, config, out);
  ASSERT_TRUE(length.ok());
  Bytes packet(out.begin(), out.begin() + length.value());
  EXPECT_TRUE(decode_tm(packet, config).ok());
  packet[13] ^= 0x10;  // the P-field follows the seven fixed octets of the TM header
  auto result = decode_tm(refresh(packet), config);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.reason(), Reason::BadField);
  EXPECT_EQ(result.error().offset, 13u);
}

TEST(PusMalformed, EmbeddedRequestIsCheckedToo) {
  // [11,4]: N = 1, release time (4 + 2 octets), then the ping TC with a broken CRC.
  Bytes data{1, 0, 0, 0, 10, 0, 0};
  Bytes request = kPingTc;
  data.insert(data.end(), request.begin(), request.end());
  EXPECT_TRUE(decode_tc(tc_with_data(11, 4, data), Config{}).ok());
  data.back() ^= 0xFF;
  auto result = decode_tc(tc_with_data(11, 4, data), Config{});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.reason(), Reason::BadCrc);
  EXPECT_EQ(result.error().offset, 11u + 7u + 11u);
}

TEST(PusMalformed, BadConfigIsRefusedBeforeDecoding) {
  Config config;
  config.value_bytes = 0;
  EXPECT_EQ(tc_reason(kPingTc, config), Reason::BadConfig);
}

// CRC-16 detects every single-bit error; a flip in the length field is caught by the length
// checks: no single-bit corruption of a valid packet is accepted.
TEST(PusMalformed, EverySingleBitFlipIsRefused) {
  testing::RandomPackets random(99, Config{});
  for (const MessageType& type : message_types()) {
    std::array<std::uint8_t, 4096> out{};
    auto length = type.direction == PacketType::Tc ? encode(random.telecommand(type), Config{}, out)
                                                   : encode(random.telemetry(type), Config{}, out);
    ASSERT_TRUE(length.ok());
    Bytes packet(out.begin(), out.begin() + length.value());
    for (std::size_t bit = 0; bit < packet.size() * 8; ++bit) {
      Bytes flipped = packet;
      flipped[bit / 8] ^= static_cast<std::uint8_t>(1 << (bit % 8));
      EXPECT_FALSE(decode(flipped, Config{}).ok()) << type.name << " bit " << bit;
    }
    for (std::size_t n = 0; n < packet.size(); ++n) {
      EXPECT_FALSE(decode(std::span<const std::uint8_t>(packet.data(), n), Config{}).ok());
    }
  }
}

TEST(PusMalformed, ReasonNamesAreDistinct) {
  EXPECT_EQ(reason_name(Reason::BadCrc), "bad-crc");
  EXPECT_EQ(reason_name(Reason::TrailingBytes), "trailing-bytes");
  EXPECT_NE(reason_name(Reason::UnknownService), reason_name(Reason::UnknownSubtype));
}

}  // namespace
}  // namespace smcbip::pus
