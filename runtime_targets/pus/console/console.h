// The ground console of the PUS target: telecommands from words, packets as table rows,
// scripts and sessions over a link.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "console/hex.h"           // IWYU pragma: export
#include "console/link.h"          // IWYU pragma: export
#include "console/link_options.h"  // IWYU pragma: export
#include "console/script.h"        // IWYU pragma: export
#include "console/session.h"       // IWYU pragma: export
#include "console/table.h"         // IWYU pragma: export
#include "console/tc_options.h"    // IWYU pragma: export
#include "packets/packets.h"

namespace smcbip::pus::console {

/// The octets of hex text given as `what` (e.g. "HEX"); throws InputError saying what was
/// expected at which character.
std::vector<std::uint8_t> bytes_of_hex(std::string_view text, const std::string& what);

/// The TC the words describe, encoded (`pus-console encode`); throws UsageError naming the
/// word and what was expected of it.
std::vector<std::uint8_t> encode_words(const TcWords& words, const Config& config);

/// The table row (index 1) of one packet (`pus-console decode`); throws InputError with the
/// decoder's reason and byte offset when it refuses the octets.
Row decode_bytes(std::span<const std::uint8_t> bytes, const Config& config);

}  // namespace smcbip::pus::console
