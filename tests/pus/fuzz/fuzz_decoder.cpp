// Decode, re-encode and compare: the fuzzed property of the PUS packet decoder.
#include "fuzz_decoder.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <variant>

#include "packets/packets.h"

namespace smcbip::pus::fuzz {
namespace {

// The default config, and one with P-fields, two-octet counts and one-octet IDs.
std::array<Config, 2> fuzzed_configs() {
  Config other;
  other.cuc_p_field = true;
  other.cuc_fine_bytes = 3;
  other.count_bytes = 2;
  other.event_id_bytes = other.parameter_id_bytes = other.structure_id_bytes = 1;
  return {Config{}, other};
}

[[noreturn]] void mismatch(const char* what) {
  std::fprintf(stderr, "pus fuzz: %s\n", what);
  std::abort();
}

void check_with(std::span<const std::uint8_t> input, const Config& config) {
  auto packet = decode(input, config);
  if (!packet) {
    if (packet.error().offset > input.size()) mismatch("a refusal points past the input");
    return;
  }
  static std::array<std::uint8_t, 70000> out;
  auto length = std::visit([&](const auto& p) { return encode(p, config, out); }, packet.value());
  if (!length) mismatch("a decoded packet does not encode");
  if (length.value() != input.size() || !std::equal(input.begin(), input.end(), out.begin())) {
    mismatch("a decoded packet encodes to other octets");
  }
  auto again = decode(std::span<const std::uint8_t>(out.data(), length.value()), config);
  if (!again || !(again.value() == packet.value())) mismatch("re-decoding differs");
}

// The input with its length field and CRC made consistent, so that mutations reach the
// secondary headers and the application data instead of stopping at the CRC.
std::span<const std::uint8_t> with_consistent_frame(std::span<const std::uint8_t> input) {
  static std::array<std::uint8_t, 70000> fixed;
  if (input.size() < kPrimaryHeaderLength + kCrcLength || input.size() - 7 > 0xFFFF) return {};
  std::copy(input.begin(), input.end(), fixed.begin());
  const std::size_t n = input.size();
  fixed[4] = static_cast<std::uint8_t>((n - 7) >> 8);
  fixed[5] = static_cast<std::uint8_t>(n - 7);
  const std::uint16_t crc = crc16(std::span<const std::uint8_t>(fixed.data(), n - 2));
  fixed[n - 2] = static_cast<std::uint8_t>(crc >> 8);
  fixed[n - 1] = static_cast<std::uint8_t>(crc);
  return {fixed.data(), n};
}

}  // namespace

void check_decoder(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  const std::span<const std::uint8_t> consistent = with_consistent_frame(input);
  for (const Config& config : fuzzed_configs()) {
    check_with(input, config);
    if (!consistent.empty()) check_with(consistent, config);
  }
}

}  // namespace smcbip::pus::fuzz
