// The optimised scheduler's count of enabled items per listing position, so that a step finds
// the item it chose without listing them all.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace smcbip::engines {

/// The descent of a Fenwick tree (1-based, `tree[i]` the sum of the counts over
/// [i - lowbit(i), i), padded to `top_step` leaves, a power of two): the number of leaves whose
/// counts sum to at most k, which is the leaf holding the k-th counted unit; `k` ends as that
/// unit's rank within its leaf. k must be below the total. Without branches: which way it goes
/// is as random as the unit sought, and mispredictions cost more than the loads.
inline std::size_t fenwick_find(const std::size_t* tree, std::size_t top_step, std::size_t& k) {
  std::size_t below = 0;
  for (std::size_t step = top_step; step != 0; step >>= 1) {
    const std::size_t sum = tree[below + step];
    // All ones when the k-th unit lies past this node (compilers keep a branch for `?:` here).
    const std::size_t past = std::size_t{0} - static_cast<std::size_t>(sum <= k);
    below += step & past;
    k -= sum & past;
  }
  return below;
}

/// Adds `delta` (two's complement for a decrease) to leaf `leaf` (0-based) of a Fenwick tree as
/// fenwick_find reads it, of `size` entries including the unused tree[0].
inline void fenwick_add(std::size_t* tree, std::size_t size, std::size_t leaf, std::size_t delta) {
  for (std::size_t i = leaf + 1; i < size; i += i & (~i + 1)) tree[i] += delta;
}

/// Counts of items at positions 0..n-1 (for the runtime: the listed connectors, then the
/// internal ports, in the order Runtime::compute_items lists their items) kept in a Fenwick tree
/// (P. M. Fenwick, "A new data structure for cumulative frequency tables", Software: Practice
/// and Experience 24(3), 1994): changing one count and finding the position of the k-th item
/// both take O(log n), so a step that changed a few counts costs no O(n) work.
class ItemIndex {
 public:
  /// `positions` positions, every count 0.
  void reset(std::size_t positions);
  std::size_t positions() const { return counts_.size(); }
  void set(std::size_t position, std::uint32_t count);
  std::uint32_t count(std::size_t position) const { return counts_[position]; }
  /// The sum of all counts.
  std::size_t total() const { return total_; }
  /// The position holding the k-th item (k < total(), counting from 0 over the positions in
  /// order) and the item's rank among that position's items.
  std::pair<std::size_t, std::uint32_t> find(std::size_t k) const;

 private:
  std::vector<std::uint32_t> counts_;
  // tree_[i] (1-based): the sum of counts_ over positions [i - lowbit(i), i).
  std::vector<std::size_t> tree_;
  std::size_t total_ = 0;
  std::size_t top_step_ = 0;  // the smallest power of two at least positions(); tree_ is one more
};

}  // namespace smcbip::engines
