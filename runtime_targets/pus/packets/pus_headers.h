// The PUS-C (ECSS-E-ST-70-41C section 7.4) telecommand and telemetry secondary headers.
#pragma once

#include <cstddef>
#include <cstdint>

#include "config.h"
#include "cuc_time.h"
#include "detail/byte_io.h"
#include "result.h"

namespace smcbip::pus {

/// PUS version number of ECSS-E-ST-70-41C.
inline constexpr std::uint8_t kPusVersionC = 2;
/// TC secondary header length: 4 + 4 bits, 8, 8, 16 bits (no spare).
inline constexpr std::size_t kTcSecondaryHeaderLength = 5;
/// Packet error control length.
inline constexpr std::size_t kCrcLength = 2;

/// TC secondary header (7.4.3.1): PUS version (4 bits), acknowledgement flags (4 bits:
/// acceptance, start, progress, completion from the least significant bit up), service type
/// ID (8), message subtype ID (8), source ID (16).
struct TcSecondaryHeader {
  std::uint8_t pus_version = kPusVersionC;
  std::uint8_t ack_flags = 0xF;
  std::uint8_t service = 0;
  std::uint8_t subtype = 0;
  std::uint16_t source_id = 0;
  friend bool operator==(const TcSecondaryHeader&, const TcSecondaryHeader&) = default;
};

/// TM secondary header (7.4.3.2): PUS version (4 bits), spacecraft time reference status
/// (4 bits), service type ID (8), message subtype ID (8), message type counter (16),
/// destination ID (16), time (CUC, config's widths). No spare field.
struct TmSecondaryHeader {
  std::uint8_t pus_version = kPusVersionC;
  std::uint8_t time_reference_status = 0;
  std::uint8_t service = 0;
  std::uint8_t subtype = 0;
  std::uint16_t message_type_counter = 0;
  std::uint16_t destination_id = 0;
  CucTime time{};
  friend bool operator==(const TmSecondaryHeader&, const TmSecondaryHeader&) = default;
};

/// TM secondary header length under a config: 7 octets plus the time.
std::size_t tm_secondary_header_length(const Config& config);

/// Appends the five octets of a TC secondary header; BadField if a 4-bit field exceeds 15.
Result<Done> encode_tc_secondary_header(const TcSecondaryHeader& header, detail::Writer& out);
/// Appends a TM secondary header and its time; BadField if a field exceeds its width.
Result<Done> encode_tm_secondary_header(const TmSecondaryHeader& header, const Config& config,
                                        detail::Writer& out);
/// Read the fields (TooShort if the octets run out); the packet decoder checks the version.
Result<TcSecondaryHeader> decode_tc_secondary_header(detail::Reader& in);
Result<TmSecondaryHeader> decode_tm_secondary_header(const Config& config, detail::Reader& in);

}  // namespace smcbip::pus
