// Encoding and decoding of whole packets, with the checks that refuse malformed ones.
#include "packet.h"

#include "crc16.h"
#include "detail/byte_io.h"

namespace smcbip::pus {
namespace {

using detail::Reader;
using detail::Writer;

// Refuses to encode what the decoder would refuse: a version other than 0 or PUS-C, a type
// bit contradicting the packet kind, a clear secondary header flag.
Result<Done> check_primary(const PrimaryHeader& p, PacketType kind, std::uint8_t pus_version) {
  if (p.version != 0) return fail(Reason::WrongVersion, "packet version number is not 0");
  if (pus_version != kPusVersionC) return fail(Reason::WrongPusVersion, "PUS version is not 2");
  if (p.type != kind) return fail(Reason::WrongPacketType, "packet type bit contradicts kind");
  if (!p.secondary_header) return fail(Reason::NoSecondaryHeader, "PUS needs the flag set");
  return Done{};
}

// Writes the primary header with the data length of `total` octets, then the CRC.
Result<std::size_t> finish(PrimaryHeader primary, std::size_t total, std::span<std::uint8_t> out) {
  if (total - 7 > 0xFFFF) return fail(Reason::CapacityExceeded, "packet over 65542 octets");
  if (out.size() < total) return fail(Reason::BufferTooSmall, "output full", out.size());
  primary.data_length = static_cast<std::uint16_t>(total - 7);
  SMCBIP_PUS_TRY(encode_primary_header(primary, out));
  const std::uint16_t crc = crc16(out.first(total - kCrcLength));
  out[total - 2] = static_cast<std::uint8_t>(crc >> 8);
  out[total - 1] = static_cast<std::uint8_t>(crc);
  return total;
}

// The checks common to TC and TM up to the CRC; returns the primary header.
Result<PrimaryHeader> check_frame(std::span<const std::uint8_t> bytes, PacketType kind,
                                  std::size_t min_data) {
  auto primary = decode_primary_header(bytes);
  if (!primary) return primary;
  const PrimaryHeader& p = primary.value();
  if (p.version != 0) return fail(Reason::WrongVersion, "packet version number is not 0", 0);
  if (p.type != kind) return fail(Reason::WrongPacketType, "packet type bit contradicts kind");
  if (p.packet_length() > bytes.size()) {
    return fail(Reason::LengthMismatch, "length field exceeds the octets given", 4);
  }
  if (p.packet_length() < bytes.size()) {
    return fail(Reason::TrailingBytes, "octets after the packet", p.packet_length());
  }
  if (p.packet_length() < kPrimaryHeaderLength + min_data) {
    return fail(Reason::TooShort, "data field too short for secondary header and CRC", 4);
  }
  const std::size_t crc_at = bytes.size() - kCrcLength;
  const auto stored = static_cast<std::uint16_t>(bytes[crc_at] << 8 | bytes[crc_at + 1]);
  if (crc16(bytes.first(crc_at)) != stored) {
    return fail(Reason::BadCrc, "packet error control does not match", crc_at);
  }
  if (!p.secondary_header) return fail(Reason::NoSecondaryHeader, "PUS needs the flag set");
  return primary;
}

// The part of the packet between the secondary header and the CRC.
Reader app_data_reader(std::span<const std::uint8_t> bytes, std::size_t header_end) {
  return Reader(bytes.subspan(header_end, bytes.size() - kCrcLength - header_end), header_end);
}

}  // namespace

Result<std::size_t> encode(const Telecommand& tc, const Config& config,
                           std::span<std::uint8_t> out) {
  SMCBIP_PUS_TRY(validate(config));
  SMCBIP_PUS_TRY(check_primary(tc.primary, PacketType::Tc, tc.header.pus_version));
  auto type = message_type_of(tc);
  if (!type) return type.error();
  if (out.size() < kPrimaryHeaderLength) return fail(Reason::BufferTooSmall, "output full");
  Writer body(out.subspan(kPrimaryHeaderLength));
  SMCBIP_PUS_TRY(encode_tc_secondary_header(tc.header, body));
  SMCBIP_PUS_TRY(encode_app_data(*type.value(), tc.data, config, body));
  return finish(tc.primary, kPrimaryHeaderLength + body.written() + kCrcLength, out);
}

Result<std::size_t> encode(const Telemetry& tm, const Config& config, std::span<std::uint8_t> out) {
  SMCBIP_PUS_TRY(validate(config));
  SMCBIP_PUS_TRY(check_primary(tm.primary, PacketType::Tm, tm.header.pus_version));
  auto type = message_type_of(tm);
  if (!type) return type.error();
  if (out.size() < kPrimaryHeaderLength) return fail(Reason::BufferTooSmall, "output full");
  Writer body(out.subspan(kPrimaryHeaderLength));
  SMCBIP_PUS_TRY(encode_tm_secondary_header(tm.header, config, body));
  SMCBIP_PUS_TRY(encode_app_data(*type.value(), tm.data, config, body));
  return finish(tm.primary, kPrimaryHeaderLength + body.written() + kCrcLength, out);
}

Result<Telecommand> decode_tc(std::span<const std::uint8_t> bytes, const Config& config) {
  SMCBIP_PUS_TRY(validate(config));
  auto primary = check_frame(bytes, PacketType::Tc, kTcSecondaryHeaderLength + kCrcLength);
  if (!primary) return primary.error();
  Telecommand tc;
  tc.primary = primary.value();
  Reader header_in(bytes.subspan(kPrimaryHeaderLength), kPrimaryHeaderLength);
  auto header = decode_tc_secondary_header(header_in);
  if (!header) return header.error();
  tc.header = header.value();
  if (tc.header.pus_version != kPusVersionC) {
    return fail(Reason::WrongPusVersion, "TC PUS version is not 2", kPrimaryHeaderLength);
  }
  auto type = message_type_of(tc);
  if (!type) return type.error();
  Reader in = app_data_reader(bytes, kPrimaryHeaderLength + kTcSecondaryHeaderLength);
  auto data = decode_app_data(*type.value(), config, in);
  if (!data) return data.error();
  tc.data = data.value();
  return tc;
}

Result<Telemetry> decode_tm(std::span<const std::uint8_t> bytes, const Config& config) {
  SMCBIP_PUS_TRY(validate(config));
  const std::size_t header_length = tm_secondary_header_length(config);
  auto primary = check_frame(bytes, PacketType::Tm, header_length + kCrcLength);
  if (!primary) return primary.error();
  Telemetry tm;
  tm.primary = primary.value();
  Reader header_in(bytes.subspan(kPrimaryHeaderLength), kPrimaryHeaderLength);
  if ((bytes[kPrimaryHeaderLength] >> 4) != kPusVersionC) {
    return fail(Reason::WrongPusVersion, "TM PUS version is not 2", kPrimaryHeaderLength);
  }
  auto header = decode_tm_secondary_header(config, header_in);
  if (!header) return header.error();
  tm.header = header.value();
  auto type = message_type_of(tm);
  if (!type) return type.error();
  Reader in = app_data_reader(bytes, kPrimaryHeaderLength + header_length);
  auto data = decode_app_data(*type.value(), config, in);
  if (!data) return data.error();
  tm.data = data.value();
  return tm;
}

Result<Packet> decode(std::span<const std::uint8_t> bytes, const Config& config) {
  auto primary = decode_primary_header(bytes);
  if (!primary) return primary.error();
  if (primary.value().type == PacketType::Tc) {
    auto tc = decode_tc(bytes, config);
    if (!tc) return tc.error();
    return Packet{tc.value()};
  }
  auto tm = decode_tm(bytes, config);
  if (!tm) return tm.error();
  return Packet{tm.value()};
}

Result<std::size_t> embedded_tc_length(std::span<const std::uint8_t> bytes, const Config& config) {
  auto primary = decode_primary_header(bytes);
  if (!primary) return primary.error();
  const std::size_t length = primary.value().packet_length();
  if (length > kMaxEmbeddedTc) {
    return fail(Reason::CapacityExceeded, "embedded TC exceeds capacity", 4);
  }
  if (length > bytes.size()) {
    return fail(Reason::LengthMismatch, "embedded TC longer than what follows", 4);
  }
  auto tc = decode_tc(bytes.first(length), config);
  if (!tc) return tc.error();
  return length;
}

Result<const MessageType*> message_type_of(const Telecommand& tc) {
  return find_message_type(PacketType::Tc, tc.header.service, tc.header.subtype);
}

Result<const MessageType*> message_type_of(const Telemetry& tm) {
  return find_message_type(PacketType::Tm, tm.header.service, tm.header.subtype);
}

}  // namespace smcbip::pus
