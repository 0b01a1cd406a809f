// The single-packet commands: encode words, decode octets.
#include "bipc/errors.h"
#include "console/console.h"

namespace smcbip::pus::console {

std::vector<std::uint8_t> bytes_of_hex(std::string_view text, const std::string& what) {
  std::vector<std::uint8_t> bytes;
  HexError error;
  if (!parse_hex(text, bytes, error)) {
    throw InputError(what + ": expected " + error.expected + " at character " +
                     std::to_string(error.offset + 1));
  }
  return bytes;
}

std::vector<std::uint8_t> encode_words(const TcWords& words, const Config& config) {
  try {
    return encode_tc(build_tc(words, config).tc, config);
  } catch (const TcSyntaxError& e) {
    throw UsageError(e.what());
  }
}

Row decode_bytes(std::span<const std::uint8_t> bytes, const Config& config) {
  auto packet = decode(bytes, config);
  if (!packet) throw InputError("malformed packet: " + refusal_text(packet.error()));
  return packet_row(1, packet.value(), config);
}

}  // namespace smcbip::pus::console
