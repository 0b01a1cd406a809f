// `--interactive`: a person picks each item at a prompt.
#pragma once

#include <cstddef>
#include <istream>
#include <optional>
#include <ostream>

namespace smcbip::engines {

/// Asks for an index in [0, count) on `out` and reads lines from `in` until one is valid;
/// nullopt when the person quits (`q`, or the end of the input, or no input at all).
std::optional<std::size_t> prompt_choice(std::ostream& out, std::istream* in, std::size_t count);

}  // namespace smcbip::engines
