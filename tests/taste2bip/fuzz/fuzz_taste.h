// The readers of TASTE designs driven from memory, for the fuzzers and their replay.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace smcbip::taste2bip::fuzz {

/// Which reader a fuzzer drives.
enum class Reader : std::uint8_t { Asn1, Aadl, Xml, Sdl };

/// The reader's name as the fuzzers and the replay spell it (`asn1`, `aadl`, `xml`, `sdl`), or false.
bool reader_named(std::string_view name, Reader& out);

/// Reads `size` bytes with `reader` (then resolves the data view, or flattens the interface
/// view; SDL is read alone). Every diagnostic must be located at a line and column from 1 within the text, and
/// errors stay bounded; must never crash or hang.
void run_reader_on(Reader reader, const std::uint8_t* data, std::size_t size);

}  // namespace smcbip::taste2bip::fuzz
