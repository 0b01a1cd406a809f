// The compiled step path's bitset of enabled positions.
#include "engines/semantics/enabled_positions.h"

#include <bit>

namespace smcbip::engines {

void EnabledPositions::reset(std::size_t positions) {
  const std::size_t words = (positions + 63) / 64;
  words_.assign(words, 0);
  // Padded to a power of two (words past the last count none): find() then descends without
  // bounds checks.
  const std::size_t padded = words == 0 ? 0 : std::bit_ceil(words);
  tree_.assign(padded + 1, 0);
  total_ = 0;
  top_step_ = padded;
}

}  // namespace smcbip::engines
