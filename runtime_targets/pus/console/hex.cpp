// Hexadecimal text to octets and back.
#include "console/hex.h"

namespace smcbip::pus::console {
namespace {

constexpr char kDigits[] = "0123456789abcdef";

int digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ':'; }

}  // namespace

std::string to_hex(std::span<const std::uint8_t> bytes) {
  std::string text;
  text.reserve(2 * bytes.size());
  for (std::uint8_t b : bytes) {
    text += kDigits[b >> 4];
    text += kDigits[b & 0xF];
  }
  return text;
}

std::string to_spaced_hex(std::span<const std::uint8_t> bytes) {
  std::string text;
  for (std::uint8_t b : bytes) {
    if (!text.empty()) text += ' ';
    text += kDigits[b >> 4];
    text += kDigits[b & 0xF];
  }
  return text;
}

bool parse_hex(std::string_view text, std::vector<std::uint8_t>& out, HexError& error) {
  out.clear();
  std::size_t i = 0;
  while (i < text.size() && is_separator(text[i])) ++i;
  if (text.substr(i, 2) == "0x" || text.substr(i, 2) == "0X") i += 2;
  int high = -1;
  std::size_t high_offset = 0;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    const int value = digit_value(c);
    if (value < 0 && is_separator(c) && high < 0) continue;
    if (value < 0) {
      error = {i, high < 0 ? "a hex digit or a separator" : "the second hex digit of an octet"};
      return false;
    }
    if (high < 0) {
      high = value;
      high_offset = i;
    } else {
      out.push_back(static_cast<std::uint8_t>(high << 4 | value));
      high = -1;
    }
  }
  if (high >= 0) {
    error = {high_offset, "an even number of hex digits (this octet lacks its second digit)"};
    return false;
  }
  if (out.empty()) {
    error = {text.size(), "at least one octet of hex digits"};
    return false;
  }
  return true;
}

}  // namespace smcbip::pus::console
