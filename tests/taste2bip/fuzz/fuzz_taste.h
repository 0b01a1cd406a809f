// The readers of TASTE designs driven from memory, for the fuzzers and their replay.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace smcbip::taste2bip::fuzz {

/// Which reader a fuzzer drives.
enum class Reader : std::uint8_t { Asn1, Aadl, Xml, Sdl, SdlAtom };

/// The reader's name as the fuzzers and the replay spell it (`asn1`, `aadl`, `xml`, `sdl`,
/// `sdlatom`), or false.
bool reader_named(std::string_view name, Reader& out);

/// Reads `size` bytes with `reader` (then resolves the data view, or flattens the interface
/// view; SDL is read alone). Every diagnostic must be located at a line and column from 1 within
/// the text, and errors stay bounded; must never crash or hang.
void run_reader_on(Reader reader, const std::uint8_t* data, std::size_t size);

/// SdlAtom: reads SDL and translates each process of it to a BIP atom (the signature from its
/// system's signals when it has one), over a small fixed data view. A translation that succeeds
/// must give a package that bipc's front end accepts; one that fails must say where.
void translate_sdl_on(const std::string& text);

}  // namespace smcbip::taste2bip::fuzz
