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
  for (std::size_t i = position + 1; i < tree_.size(); i += i & (~i + 1)) tree_[i] += delta;
}

std::pair<std::size_t, std::uint32_t> ItemIndex::find(std::size_t k) const {
  // Descends the implicit tree: `below` ends as the number of positions whose counts sum to at
  // most k, which is the position of the k-th item. Since k < total(), the descent never takes
  // the whole padded range, so it stays within the tree. Without branches: which way it
  // goes is as random as the chosen item, and mispredictions cost more than the loads.
  std::size_t below = 0;
  for (std::size_t step = top_step_; step != 0; step >>= 1) {
    const std::size_t sum = tree_[below + step];
    // All ones when the k-th item lies past this node (compilers keep a branch for `?:` here).
    const std::size_t past = std::size_t{0} - static_cast<std::size_t>(sum <= k);
    below += step & past;
    k -= sum & past;
  }
  return {below, static_cast<std::uint32_t>(k)};
}

}  // namespace smcbip::engines
