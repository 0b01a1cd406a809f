// Packets as hexadecimal text, the form the console reads and prints them in.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace smcbip::pus::console {

/// Lower-case hex digits, two per octet, without separators.
std::string to_hex(std::span<const std::uint8_t> bytes);

/// Octets in the form "01 02" (spaced), for decoded information.
std::string to_spaced_hex(std::span<const std::uint8_t> bytes);

/// Where hex text stops being hex: the offset of the offending character and what was expected.
struct HexError {
  std::size_t offset = 0;
  std::string expected;
};

/// Reads hex digits (either case) into octets; spaces, tabs, newlines and ':' may separate
/// octets, and an optional leading "0x" is skipped. False with `error` set on anything else or
/// an odd number of digits.
bool parse_hex(std::string_view text, std::vector<std::uint8_t>& out, HexError& error);

}  // namespace smcbip::pus::console
