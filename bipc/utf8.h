// UTF-8 as the front end and what writes BIP text take it: the Unicode Standard's well-formed
// sequences (table 3-7), without overlong forms, surrogates or code points beyond U+10FFFF (what
// JSON output and other UTF-8 readers accept).
#pragma once

#include <cstddef>
#include <string_view>

namespace smcbip::bipc {

/// The length of the well-formed UTF-8 sequence starting at text[pos], or 0 when none starts
/// there.
std::size_t well_formed_utf8(std::string_view text, std::size_t pos);

/// Whether all of `text` is well-formed UTF-8.
bool is_utf8(std::string_view text);

}  // namespace smcbip::bipc
