// The console table of the ground side: one row per TC sent or TM received, with the
// application data in words.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "packets/packets.h"

namespace smcbip::pus::console {

/// One row: index, TC/TM, service, subtype, time, source, destination, sequence count,
/// status and the decoded information. For a TC the source is its source ID and the
/// destination its APID; for a TM the source is its APID and the destination its destination
/// ID. Absent fields are "-".
struct Row {
  std::size_t index = 0;
  std::string kind, service, subtype, time, source, destination, sequence, status, information;
  friend bool operator==(const Row&, const Row&) = default;
};

/// The column titles, aligned like format_row.
std::string table_header();
/// The row as one line of aligned columns (no newline).
std::string format_row(const Row& row);

/// A CUC time as seconds with milliseconds (the fine time truncated), e.g. "100.500".
std::string format_time(const CucTime& time, const Config& config);

/// The application data of a TC or TM in words, e.g. "TM[1,1] acceptance success of TC apid
/// 0x12 seq 5".
std::string describe(const Telecommand& tc, const Config& config);
std::string describe(const Telemetry& tm, const Config& config);

/// The row of a TC with the given status ("sent", "not sent", "valid").
Row tc_row(std::size_t index, const Telecommand& tc, const Config& config,
           const std::string& status);
/// The row of a TM; its status is "failure" for the failure reports of ST01, else "ok".
Row tm_row(std::size_t index, const Telemetry& tm, const Config& config);
/// The row of a decoded packet of either kind (a TC's status is "valid").
Row packet_row(std::size_t index, const Packet& packet, const Config& config);
/// The row of octets the decoder refused: status "malformed", the reason and its offset.
Row malformed_row(std::size_t index, std::span<const std::uint8_t> bytes, const Error& error);

/// "REASON at byte N: MESSAGE", how the console reports a refused packet.
std::string refusal_text(const Error& error);

}  // namespace smcbip::pus::console
