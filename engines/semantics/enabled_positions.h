// The compiled step path's enabled item positions, where each position holds at most one item:
// a bitset, so that finding the k-th enabled position descends a tree over words rather than
// over positions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engines/semantics/item_index.h"

namespace smcbip::engines {

/// Positions 0..n-1, each enabled or not. set() and find() take O(log(n / 64)): a Fenwick tree
/// (as ItemIndex's) counts the enabled positions of each 64-bit word, and the k-th enabled
/// position is found within its word by broadword selection (S. Vigna, "Broadword
/// implementation of rank/select queries", WEA 2008), so a step's search is a dependent load
/// per level of words, six levels fewer than ItemIndex's over positions.
class EnabledPositions {
 public:
  /// `positions` positions, none enabled.
  void reset(std::size_t positions);
  void set(std::size_t position, bool enabled) {
    const std::size_t w = position / 64;
    const std::uint64_t bit = std::uint64_t{1} << (position % 64);
    if (((words_[w] & bit) != 0) == enabled) return;
    words_[w] ^= bit;
    // Unsigned wrap-around: adding 0 - 1 subtracts one.
    const std::size_t delta = enabled ? 1 : std::size_t{0} - 1;
    total_ += delta;
    fenwick_add(tree_.data(), tree_.size(), w, delta);
  }
  bool enabled(std::size_t position) const {
    return (words_[position / 64] >> (position % 64) & 1) != 0;
  }
  /// How many positions are enabled.
  std::size_t total() const { return total_; }
  /// The k-th enabled position (k < total(), counting from 0 in position order).
  std::size_t find(std::size_t k) const {
    const std::size_t word = fenwick_find(tree_.data(), top_step_, k);
    return word * 64 + select_in_word(words_[word], static_cast<unsigned>(k));
  }

  /// The position of the r-th set bit of `word` (r < its number of set bits), from bit 0.
  static inline unsigned select_in_word(std::uint64_t word, unsigned r);

 private:
  std::vector<std::uint64_t> words_;
  // tree_[i] (1-based): the enabled positions of words [i - lowbit(i), i).
  std::vector<std::size_t> tree_;
  std::size_t total_ = 0;
  std::size_t top_step_ = 0;  // the smallest power of two at least the word count
};

namespace detail {

/// select_in_byte[b][r]: the position of the r-th set bit of byte b (8 where it has none).
struct SelectInByte {
  std::uint8_t position[256][8];
};
constexpr SelectInByte make_select_in_byte() {
  SelectInByte table{};
  for (unsigned b = 0; b < 256; ++b) {
    unsigned r = 0;
    for (unsigned bit = 0; bit < 8; ++bit) {
      if ((b >> bit & 1) != 0) table.position[b][r++] = static_cast<std::uint8_t>(bit);
    }
    for (; r < 8; ++r) table.position[b][r] = 8;
  }
  return table;
}
inline constexpr SelectInByte kSelectInByte = make_select_in_byte();

}  // namespace detail

inline unsigned EnabledPositions::select_in_word(std::uint64_t word, unsigned r) {
  constexpr std::uint64_t kOnes = 0x0101010101010101u, kHighs = 0x8080808080808080u;
  // The set bits of each byte, then their running sums: byte i of `prefix` counts the set
  // bits of bytes 0..i (at most 64, so no byte carries into the next).
  std::uint64_t counts = word - ((word >> 1) & 0x5555555555555555u);
  counts = (counts & 0x3333333333333333u) + ((counts >> 2) & 0x3333333333333333u);
  counts = (counts + (counts >> 4)) & 0x0F0F0F0F0F0F0F0Fu;
  const std::uint64_t prefix = counts * kOnes;
  // Byte i of (r, ..., r) + 128 minus prefix_i is in [64, 191]: no borrow between bytes, and
  // its high bit says prefix_i <= r, that is byte i lies wholly before the r-th set bit.
  const std::uint64_t before = ((r * kOnes | kHighs) - prefix) & kHighs;
  const auto byte = static_cast<unsigned>(((before >> 7) * kOnes) >> 56);
  const auto skipped = static_cast<unsigned>(((prefix << 8) >> (8 * byte)) & 0xFF);
  return 8 * byte + detail::kSelectInByte.position[(word >> (8 * byte)) & 0xFF][r - skipped];
}

}  // namespace smcbip::engines
