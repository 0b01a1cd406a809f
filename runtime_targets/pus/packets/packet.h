// Whole PUS-C packets: primary header, secondary header, application data and CRC.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>

#include "ccsds.h"
#include "config.h"
#include "messages.h"
#include "pus_headers.h"
#include "result.h"

namespace smcbip::pus {

/// A telecommand: its primary header (type TC, secondary header flag set), its PUS-C TC
/// secondary header and its application data. `primary.data_length` is set by encoding.
struct Telecommand {
  PrimaryHeader primary{};
  TcSecondaryHeader header{};
  Message data{};
  friend bool operator==(const Telecommand&, const Telecommand&) = default;
};

/// A telemetry packet: primary header (type TM), PUS-C TM secondary header, source data.
struct Telemetry {
  PrimaryHeader primary{.type = PacketType::Tm};
  TmSecondaryHeader header{};
  Message data{};
  friend bool operator==(const Telemetry&, const Telemetry&) = default;
};

/// Either kind of packet, as the decoder of a mixed stream returns it.
using Packet = std::variant<Telecommand, Telemetry>;

/// Encodes the packet into `out` with its data length and CRC; returns the packet's length.
/// Refuses what the decoder would refuse (WrongVersion, WrongPusVersion, WrongPacketType,
/// NoSecondaryHeader, UnknownService, UnknownSubtype), a field over its width (BadField) and
/// a too small `out` (BufferTooSmall).
Result<std::size_t> encode(const Telecommand& tc, const Config& config,
                           std::span<std::uint8_t> out);
Result<std::size_t> encode(const Telemetry& tm, const Config& config, std::span<std::uint8_t> out);

/// Decodes exactly one telecommand filling `bytes`. Refuses, in this order: TooShort (under
/// six octets), WrongVersion, WrongPacketType, LengthMismatch (fewer octets than the length
/// field says), TrailingBytes (more), TooShort (a data field too short for the secondary
/// header and CRC), BadCrc, NoSecondaryHeader, WrongPusVersion, UnknownService,
/// UnknownSubtype, then what the application data decoder refuses (TooShort, TrailingBytes,
/// BadField, CapacityExceeded).
Result<Telecommand> decode_tc(std::span<const std::uint8_t> bytes, const Config& config);
/// The same for one telemetry packet.
Result<Telemetry> decode_tm(std::span<const std::uint8_t> bytes, const Config& config);
/// Decodes one packet of either kind, chosen by its packet type bit.
Result<Packet> decode(std::span<const std::uint8_t> bytes, const Config& config);

/// The length of the whole, valid TC at the start of `bytes` (an embedded request of [11,4] or
/// [19,1]); refuses as decode_tc does, and CapacityExceeded above kMaxEmbeddedTc octets.
Result<std::size_t> embedded_tc_length(std::span<const std::uint8_t> bytes, const Config& config);

/// The supported message type of a packet's header (never fails for a decoded packet).
Result<const MessageType*> message_type_of(const Telecommand& tc);
Result<const MessageType*> message_type_of(const Telemetry& tm);

}  // namespace smcbip::pus
