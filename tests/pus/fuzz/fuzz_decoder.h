// The property the PUS fuzzer checks on any input: decoding never crashes, what decodes
// encodes back to the same octets, and refusals point inside the input.
#pragma once

#include <cstddef>
#include <cstdint>

namespace smcbip::pus::fuzz {

/// Decodes `data` under each fuzzed config; aborts if an accepted packet does not re-encode
/// to exactly the input, or if a refusal's offset lies past the input.
void check_decoder(const std::uint8_t* data, std::size_t size);

}  // namespace smcbip::pus::fuzz
