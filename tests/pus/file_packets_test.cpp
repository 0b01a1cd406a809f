// ST23 file management packets. The layouts are ECSS-E-ST-70-41C 8.23.2: [23,1] create a file
// (repository path, file name, maximum size), [23,2] delete a file and [23,3] report its
// attributes (repository path, file name), [23,4] (repository path, file name, maximum size),
// [23,14] copy a file (operation ID, source repository path, source file name, target
// repository path, target file name); the subtype numbers as AcubeSAT ecss-services lists them
// (inc/Services/FileManagementService.hpp). String and operation ID widths are this project's
// (messages.h). The octets below are derived by hand (the CRC with an independent
// CRC-16/CCITT-FALSE computation).
#include <gtest/gtest.h>

#include <array>
#include <string_view>
#include <vector>

#include "packets/packets.h"

namespace smcbip::pus {
namespace {

FixedBytes<kMaxFileString> text(std::string_view s) {
  FixedBytes<kMaxFileString> out;
  for (char c : s) out.push_back(static_cast<std::uint8_t>(c));
  return out;
}

std::vector<std::uint8_t> encoded(std::uint8_t subtype, const FileRequest& f) {
  Telecommand tc;
  tc.header.service = 23;
  tc.header.subtype = subtype;
  tc.data = f;
  std::array<std::uint8_t, 512> out{};
  const auto length = encode(tc, Config{}, out);
  EXPECT_TRUE(length.ok());
  return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(length.ok() ? length.value() : 0)};
}

std::vector<std::uint8_t> hex(std::string_view h) {
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i + 1 < h.size(); i += 2) {
    out.push_back(static_cast<std::uint8_t>(std::stoi(std::string(h.substr(i, 2)), nullptr, 16)));
  }
  return out;
}

TEST(PusFilePackets, DeleteFileOctets) {
  FileRequest f;
  f.repository = text("a");
  f.file = text("b");
  // Primary header (TC, APID 0, seq 0, length 10), secondary header (PUS 2, ack 0xF, [23,2],
  // source 0), 01 'a', 01 'b', CRC.
  EXPECT_EQ(encoded(2, f), hex("1800c000000a2f17020000016101625c60"));
  auto back = decode_tc(hex("1800c000000a2f17020000016101625c60"), Config{});
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(std::get<FileRequest>(back.value().data), f);
}

TEST(PusFilePackets, CopyFileOctets) {
  FileRequest f;
  f.operation_id = 7;
  f.repository = text("a");
  f.file = text("b");
  f.target_repository = text("c");
  f.target_file = text("d");
  // Operation ID 0007 first, then the source and target (repository, file) strings.
  EXPECT_EQ(encoded(14, f), hex("1800c00000102f170e000000070161016201630164b8b3"));
}

TEST(PusFilePackets, CreateAndReportCarryTheSize) {
  FileRequest f;
  f.repository = text("logs");
  f.file = text("x.bin");
  f.max_size = 0x01020304;
  const std::vector<std::uint8_t> bytes = encoded(1, f);
  // The application data after the 11 header octets: 04 "logs" 05 "x.bin" 01020304.
  const std::vector<std::uint8_t> data(bytes.begin() + 11, bytes.end() - 2);
  EXPECT_EQ(data, hex("046c6f677305782e62696e01020304"));
  Telemetry tm;
  tm.header.service = 23;
  tm.header.subtype = 4;
  tm.data = f;
  std::array<std::uint8_t, 512> out{};
  const auto length = encode(tm, Config{}, out);
  ASSERT_TRUE(length.ok());
  auto back = decode_tm(std::span(out).first(length.value()), Config{});
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(std::get<FileRequest>(back.value().data), f);
}

TEST(PusFilePackets, StringsAreRefusedBeyondTheirLengthOrCapacity) {
  // [23,2] whose file name says 2 octets but one follows: too short at the name's octets.
  FileRequest f;
  f.repository = text("a");
  f.file = text("b");
  std::vector<std::uint8_t> bytes = encoded(2, f);
  bytes[13] = 2;
  const std::uint16_t crc = crc16(std::span(bytes).first(bytes.size() - 2));
  bytes[bytes.size() - 2] = static_cast<std::uint8_t>(crc >> 8);
  bytes[bytes.size() - 1] = static_cast<std::uint8_t>(crc);
  auto refused = decode_tc(bytes, Config{});
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.reason(), Reason::TooShort);
  // A length over the 64-octet capacity.
  bytes[13] = 65;
  const std::uint16_t crc2 = crc16(std::span(bytes).first(bytes.size() - 2));
  bytes[bytes.size() - 2] = static_cast<std::uint8_t>(crc2 >> 8);
  bytes[bytes.size() - 1] = static_cast<std::uint8_t>(crc2);
  refused = decode_tc(bytes, Config{});
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.reason(), Reason::CapacityExceeded);
  EXPECT_EQ(refused.error().offset, 13U);
}

TEST(PusFilePackets, OnlyTheSubtypesInTheirDirection) {
  EXPECT_TRUE(find_message_type(PacketType::Tc, 23, 14).ok());
  EXPECT_TRUE(find_message_type(PacketType::Tm, 23, 4).ok());
  EXPECT_EQ(find_message_type(PacketType::Tc, 23, 4).reason(), Reason::UnknownSubtype);
  EXPECT_EQ(find_message_type(PacketType::Tc, 23, 5).reason(), Reason::UnknownSubtype);
}

}  // namespace
}  // namespace smcbip::pus
