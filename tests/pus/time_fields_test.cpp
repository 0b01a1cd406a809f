// Where tm_time_fields says the CUC times sit: the octets there are the times' encodings, found
// by encoding the same packet with another time and seeing which octets change (nothing else
// does), under the default config and one with P-fields and other widths.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "packets/packets.h"

namespace smcbip::pus {
namespace {

std::vector<std::uint8_t> bytes_of(const Telemetry& tm, const Config& config) {
  std::array<std::uint8_t, 256> out{};
  const auto length = encode(tm, config, out);
  EXPECT_TRUE(length.ok());
  return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(length.ok() ? length.value() : 0)};
}

/// The octets that differ between the packet stamped (and, for [9,2], reporting) time 0 and
/// time `other`, which differs from 0 in every octet of the encoding.
std::vector<std::size_t> changed(Telemetry tm, const Config& config, const CucTime& other) {
  const std::vector<std::uint8_t> zero = bytes_of(tm, config);
  tm.header.time = other;
  if (auto* report = std::get_if<TimeReport>(&tm.data)) report->time = other;
  const std::vector<std::uint8_t> stamped = bytes_of(tm, config);
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i + kCrcLength < zero.size(); ++i) {
    if (zero[i] != stamped[i]) at.push_back(i);
  }
  return at;
}

std::vector<std::size_t> spanned(const Telemetry& tm, const Config& config) {
  std::vector<std::size_t> at;
  for (const FieldSpan& field : tm_time_fields(tm, config)) {
    // A P-field does not change with the time, but is part of the field.
    const std::size_t p = config.cuc_p_field ? 1 : 0;
    for (std::size_t i = field.offset + p; i < field.offset + field.length; ++i) at.push_back(i);
  }
  return at;
}

TEST(PusTimeFields, TheyCoverExactlyTheOctetsTheTimeChanges) {
  Config other;
  other.cuc_p_field = true;
  other.cuc_coarse_bytes = 3;
  other.cuc_fine_bytes = 1;
  for (const Config& config : {Config{}, other}) {
    // 0x01 in every octet of the configured widths.
    const auto ones = [](std::size_t octets) {
      return static_cast<std::uint32_t>(0x0101010101ULL & ((std::uint64_t{1} << 8 * octets) - 1));
    };
    const CucTime fine_fit{ones(config.cuc_coarse_bytes), ones(config.cuc_fine_bytes)};
    Telemetry ping;
    ping.header.service = 17;
    ping.header.subtype = 2;
    ping.data = NoData{};
    EXPECT_EQ(changed(ping, config, fine_fit), spanned(ping, config));
    EXPECT_EQ(tm_time_fields(ping, config).size(), 1U);
    Telemetry report;
    report.header.service = 9;
    report.header.subtype = 2;
    report.data = TimeReport{3, {}};
    EXPECT_EQ(changed(report, config, fine_fit), spanned(report, config));
    EXPECT_EQ(tm_time_fields(report, config).size(), 2U);
  }
}

}  // namespace
}  // namespace smcbip::pus
