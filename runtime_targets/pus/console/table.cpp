// Rows of the console table and their aligned text.
#include "console/table.h"

#include <cstdio>

#include "console/hex.h"

namespace smcbip::pus::console {
namespace {

std::string apid_text(std::uint16_t apid) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%x", static_cast<unsigned>(apid));
  return text;
}

std::string line(const std::string& index, const Row& r) {
  char text[160];
  std::snprintf(text, sizeof text, "%-5s %-3s %-4s %-4s %-13s %-6s %-6s %-6s %-9s", index.c_str(),
                r.kind.c_str(), r.service.c_str(), r.subtype.c_str(), r.time.c_str(),
                r.source.c_str(), r.destination.c_str(), r.sequence.c_str(), r.status.c_str());
  return std::string(text) + " " + r.information;
}

}  // namespace

std::string table_header() {
  Row titles{0, "dir", "svc", "sub", "time", "src", "dst", "seq", "status", "information"};
  return line("#", titles);
}

std::string format_row(const Row& row) { return line(std::to_string(row.index), row); }

std::string format_time(const CucTime& time, const Config& config) {
  const unsigned fine_bits = 8u * config.cuc_fine_bytes;
  const std::uint64_t millis = fine_bits == 0 ? 0 : (std::uint64_t{time.fine} * 1000) >> fine_bits;
  char text[32];
  std::snprintf(text, sizeof text, "%lu.%03lu", static_cast<unsigned long>(time.coarse),
                static_cast<unsigned long>(millis));
  return text;
}

Row tc_row(std::size_t index, const Telecommand& tc, const Config& config,
           const std::string& status) {
  return {index,
          "TC",
          std::to_string(tc.header.service),
          std::to_string(tc.header.subtype),
          "-",
          std::to_string(tc.header.source_id),
          apid_text(tc.primary.apid),
          std::to_string(tc.primary.sequence_count),
          status,
          describe(tc, config)};
}

Row tm_row(std::size_t index, const Telemetry& tm, const Config& config) {
  const bool failure = tm.header.service == 1 && tm.header.subtype % 2 == 0;
  return {index,
          "TM",
          std::to_string(tm.header.service),
          std::to_string(tm.header.subtype),
          format_time(tm.header.time, config),
          apid_text(tm.primary.apid),
          std::to_string(tm.header.destination_id),
          std::to_string(tm.primary.sequence_count),
          failure ? "failure" : "ok",
          describe(tm, config)};
}

Row packet_row(std::size_t index, const Packet& packet, const Config& config) {
  if (const auto* tc = std::get_if<Telecommand>(&packet))
    return tc_row(index, *tc, config, "valid");
  return tm_row(index, std::get<Telemetry>(packet), config);
}

Row malformed_row(std::size_t index, std::span<const std::uint8_t> bytes, const Error& error) {
  const bool tc = !bytes.empty() && (bytes[0] & 0x10) != 0;
  return {index,
          bytes.empty() ? "-" : (tc ? "TC" : "TM"),
          "-",
          "-",
          "-",
          "-",
          "-",
          "-",
          "malformed",
          refusal_text(error) + " (" + std::to_string(bytes.size()) +
              " octets: " + to_hex(bytes.first(std::min<std::size_t>(bytes.size(), 16))) +
              (bytes.size() > 16 ? "...)" : ")")};
}

std::string refusal_text(const Error& error) {
  return std::string(reason_name(error.reason)) + " at byte " + std::to_string(error.offset) +
         ": " + error.message;
}

}  // namespace smcbip::pus::console
