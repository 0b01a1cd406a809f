// Encode/decode round trips of random valid packets of every supported message type.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "packets/packets.h"
#include "random_packets.h"

namespace smcbip::pus {
namespace {

constexpr int kPacketsPerType = 200;

// The configurations the round trips cover: the default, the seven-octet time of the
// reference TM, a P-field with two-octet counts, and the widest fields.
std::vector<Config> configs() {
  Config seven;
  seven.cuc_fine_bytes = 3;
  Config p_field;
  p_field.cuc_p_field = true;
  p_field.cuc_coarse_bytes = 3;
  p_field.cuc_fine_bytes = 1;
  p_field.count_bytes = 2;
  Config wide;
  wide.cuc_fine_bytes = 0;
  wide.failure_code_bytes = wide.step_id_bytes = wide.structure_id_bytes = 4;
  wide.event_id_bytes = wide.function_id_bytes = wide.argument_id_bytes = 8;
  wide.parameter_id_bytes = wide.value_bytes = wide.pmon_id_bytes = 8;
  return {Config{}, seven, p_field, wide};
}

// Encoding, decoding and encoding again gives the same packet and the same octets.
template <class Packet, class Decode>
void check_round_trip(Packet packet, const Config& config, Decode decode_fn) {
  std::array<std::uint8_t, 4096> first{};
  auto length = encode(packet, config, first);
  ASSERT_TRUE(length.ok()) << reason_name(length.reason()) << ": " << length.error().message;
  const std::span<const std::uint8_t> bytes(first.data(), length.value());
  auto back = decode_fn(bytes, config);
  ASSERT_TRUE(back.ok()) << reason_name(back.reason()) << ": " << back.error().message;
  packet.primary.data_length = static_cast<std::uint16_t>(length.value() - 7);
  EXPECT_EQ(back.value(), packet);
  std::array<std::uint8_t, 4096> second{};
  auto again = encode(back.value(), config, second);
  ASSERT_TRUE(again.ok());
  EXPECT_TRUE(
      std::equal(bytes.begin(), bytes.end(), second.begin(), second.begin() + again.value()));
  auto any = decode(bytes, config);
  ASSERT_TRUE(any.ok());
  EXPECT_TRUE(std::holds_alternative<Packet>(any.value()));
}

TEST(PusRoundTrip, EveryMessageTypeUnderEveryConfig) {
  std::uint64_t seed = 20261126;
  for (const Config& config : configs()) {
    testing::RandomPackets random(seed++, config);
    for (const MessageType& type : message_types()) {
      SCOPED_TRACE(type.name);
      for (int i = 0; i < kPacketsPerType; ++i) {
        if (type.direction == PacketType::Tc) {
          check_round_trip(random.telecommand(type), config, decode_tc);
        } else {
          check_round_trip(random.telemetry(type), config, decode_tm);
        }
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
}

TEST(PusRoundTrip, PrimaryHeaderAlone) {
  testing::RandomPackets random(7, Config{});
  for (int i = 0; i < 1000; ++i) {
    PrimaryHeader h;
    h.version = static_cast<std::uint8_t>(random.rng()() % 8);
    h.type = static_cast<PacketType>(random.rng()() % 2);
    h.secondary_header = random.rng()() % 2 == 1;
    h.apid = static_cast<std::uint16_t>(random.rng()() % (kMaxApid + 1));
    h.sequence_flags = static_cast<SequenceFlags>(random.rng()() % 4);
    h.sequence_count = static_cast<std::uint16_t>(random.rng()() % (kMaxSequenceCount + 1));
    h.data_length = static_cast<std::uint16_t>(random.rng()());
    std::array<std::uint8_t, 6> out{};
    ASSERT_TRUE(encode_primary_header(h, out).ok());
    auto back = decode_primary_header(out);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back.value(), h);
    const auto id = encode_request_id(RequestId::of(h));
    EXPECT_TRUE(std::equal(id.begin(), id.end(), out.begin()));
    EXPECT_EQ(decode_request_id(id), RequestId::of(h));
  }
}

TEST(PusRoundTrip, EncoderRefusesFieldsOverTheirWidth) {
  std::array<std::uint8_t, 64> out{};
  PrimaryHeader h;
  h.apid = kMaxApid + 1;
  EXPECT_EQ(encode_primary_header(h, out).reason(), Reason::BadField);
  h.apid = 1;
  h.sequence_count = kMaxSequenceCount + 1;
  EXPECT_EQ(encode_primary_header(h, out).reason(), Reason::BadField);

  Telecommand tc;
  tc.header.service = 20;
  tc.header.subtype = 1;
  IdList ids;
  ids.ids.push_back(0x10000);  // parameter IDs take two octets by default
  tc.data = ids;
  EXPECT_EQ(encode(tc, Config{}, out).reason(), Reason::BadField);
  tc.data = NoData{};  // not the shape of [20,1]
  EXPECT_EQ(encode(tc, Config{}, out).reason(), Reason::BadField);
  tc.header.service = 42;
  EXPECT_EQ(encode(tc, Config{}, out).reason(), Reason::UnknownService);
  tc.header.service = 17;
  tc.header.subtype = 2;  // [17,2] is a TM
  EXPECT_EQ(encode(tc, Config{}, out).reason(), Reason::UnknownSubtype);
  tc.header.subtype = 1;
  tc.header.pus_version = 1;
  EXPECT_EQ(encode(tc, Config{}, out).reason(), Reason::WrongPusVersion);
  tc.header.pus_version = kPusVersionC;
  tc.primary.version = 1;
  EXPECT_EQ(encode(tc, Config{}, out).reason(), Reason::WrongVersion);
  tc.primary.version = 0;
  tc.primary.type = PacketType::Tm;
  EXPECT_EQ(encode(tc, Config{}, out).reason(), Reason::WrongPacketType);
  tc.primary.type = PacketType::Tc;
  tc.primary.secondary_header = false;
  EXPECT_EQ(encode(tc, Config{}, out).reason(), Reason::NoSecondaryHeader);
  tc.primary.secondary_header = true;
  EXPECT_EQ(encode(tc, Config{}, std::span<std::uint8_t>(out.data(), 12)).reason(),
            Reason::BufferTooSmall);
  Config bad;
  bad.cuc_coarse_bytes = 5;
  EXPECT_EQ(encode(tc, bad, out).reason(), Reason::BadConfig);
}

}  // namespace
}  // namespace smcbip::pus
