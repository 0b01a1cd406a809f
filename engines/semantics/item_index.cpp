// The Fenwick tree of the optimised scheduler's item counts.
#include "engines/semantics/item_index.h"

#include <bit>

namespace smcbip::engines {

void ItemIndex::reset(std::size_t positions) {
  counts_.assign(positions, 0);
  tree_.assign(positions + 1, 0);
  total_ = 0;
  top_step_ = positions == 0 ? 0 : std::bit_floor(positions);
}

void ItemIndex::set(std::size_t position, std::uint32_t count) {
  if (counts_[position] == count) return;
  // Unsigned wrap-around: adding the two's complement of a decrease subtracts it.
  const std::size_t delta = static_cast<std::size_t>(count) - counts_[position];
  counts_[position] = count;
  total_ += delta;
  for (std::size_t i = position + 1; i < tree_.size(); i += i & (~i + 1)) tree_[i] += delta;
}

std::pair<std::size_t, std::uint32_t> ItemIndex::find(std::size_t k) const {
  // Descends the implicit tree: `below` ends as the number of positions whose counts sum to at
  // most k, which is the position of the k-th item.
  std::size_t below = 0;
  for (std::size_t step = top_step_; step != 0; step >>= 1) {
    const std::size_t next = below + step;
    if (next < tree_.size() && tree_[next] <= k) {
      below = next;
      k -= tree_[next];
    }
  }
  return {below, static_cast<std::uint32_t>(k)};
}

}  // namespace smcbip::engines
