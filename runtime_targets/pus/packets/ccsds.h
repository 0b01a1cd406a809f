// The CCSDS space packet primary header (CCSDS 133.0-B-2 section 4.1.3), six octets.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "result.h"

namespace smcbip::pus {

/// Packet type bit: 0 telemetry, 1 telecommand.
enum class PacketType : std::uint8_t { Tm = 0, Tc = 1 };

/// Sequence flags: 0b00 continuation, 0b01 first, 0b10 last, 0b11 unsegmented.
enum class SequenceFlags : std::uint8_t { Continuation = 0, First = 1, Last = 2, Unsegmented = 3 };

inline constexpr std::size_t kPrimaryHeaderLength = 6;
inline constexpr std::uint16_t kMaxApid = 0x7FF;
inline constexpr std::uint16_t kMaxSequenceCount = 0x3FFF;

/// The fields of a primary header. `data_length` is the packet data field length minus one.
struct PrimaryHeader {
  std::uint8_t version = 0;  ///< 3 bits; always 0 for CCSDS version-1 packets
  PacketType type = PacketType::Tc;
  bool secondary_header = true;
  std::uint16_t apid = 0;  ///< 11 bits
  SequenceFlags sequence_flags = SequenceFlags::Unsegmented;
  std::uint16_t sequence_count = 0;  ///< 14 bits
  std::uint16_t data_length = 0;

  /// The whole packet's length in octets: data_length + 7.
  std::size_t packet_length() const { return std::size_t{data_length} + 7; }
  friend bool operator==(const PrimaryHeader&, const PrimaryHeader&) = default;
};

/// Writes the six octets; BadField if a field exceeds its width.
Result<Done> encode_primary_header(const PrimaryHeader& header, std::span<std::uint8_t> out);

/// Reads the first six octets. Only the width of the input is checked here (TooShort); the
/// packet decoder checks version and length against its expectations.
Result<PrimaryHeader> decode_primary_header(std::span<const std::uint8_t> bytes);

/// The 32-bit request ID of ECSS-E-ST-70-41C 5.4.11.4: the first four octets of a TC's
/// primary header (version, type, secondary header flag, APID, sequence flags and count).
struct RequestId {
  std::uint8_t version = 0;
  PacketType type = PacketType::Tc;
  bool secondary_header = true;
  std::uint16_t apid = 0;
  SequenceFlags sequence_flags = SequenceFlags::Unsegmented;
  std::uint16_t sequence_count = 0;

  /// The request ID of a telecommand with this primary header.
  static RequestId of(const PrimaryHeader& tc);
  friend bool operator==(const RequestId&, const RequestId&) = default;
};

/// The four octets of a request ID.
std::array<std::uint8_t, 4> encode_request_id(const RequestId& id);
/// A request ID from four octets (every bit pattern is a request ID).
RequestId decode_request_id(std::span<const std::uint8_t, 4> bytes);

}  // namespace smcbip::pus
