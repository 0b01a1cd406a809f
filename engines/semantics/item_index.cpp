// The Fenwick tree of the optimised scheduler's item counts.
#include "engines/semantics/item_index.h"

#include <bit>

namespace smcbip::engines {

void ItemIndex::reset(std::size_t positions) {
  counts_.assign(positions, 0);
  // Padded to a power of two (positions past the last count 0): find() then descends without
  // bounds checks.
  const std::size_t padded = positions == 0 ? 0 : std::bit_ceil(positions);
  tree_.assign(padded + 1, 0);
  total_ = 0;
  top_step_ = padded;
}

void ItemIndex::set(std::size_t position, std::uint32_t count) {
  if (counts_[position] == count) return;
  // Unsigned wrap-around: adding the two's complement of a decrease subtracts it.
  const std::size_t delta = static_cast<std::size_t>(count) - counts_[position];
  counts_[position] = count;
  total_ += delta;
  fenwick_add(tree_.data(), tree_.size(), position, delta);
}

std::pair<std::size_t, std::uint32_t> ItemIndex::find(std::size_t k) const {
  // Since k < total(), the descent never takes the whole padded range: it stays in the tree.
  const std::size_t position = fenwick_find(tree_.data(), top_step_, k);
  return {position, static_cast<std::uint32_t>(k)};
}

}  // namespace smcbip::engines
