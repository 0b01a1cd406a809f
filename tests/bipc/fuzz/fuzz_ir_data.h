// The IR decoder driven from memory, for the fuzzer and its regression replay.
#pragma once

#include <cstddef>
#include <cstdint>

namespace smcbip::bipc::fuzz {

/// Decodes `size` bytes as the IR's data encoding: JSON text when the first byte that is not
/// white space is '{', CBOR otherwise. What the decoder accepts must encode again to bytes that
/// decode to the same encoding, and print as text and JSON; must never crash or hang.
void run_ir_data_on(const std::uint8_t* data, std::size_t size);

}  // namespace smcbip::bipc::fuzz
