// A set of positions in a listing, visited in listing order in time proportional to its words.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

namespace smcbip::engines {

/// Positions 0 .. size-1 as a bitset: the optimised scheduler marks the listed connectors that
/// have values, so the per-step walks over them skip the (many) others a word at a time.
class PositionSet {
 public:
  void resize(std::size_t size) { words_.assign((size + 63) / 64, 0); }
  void clear() { words_.assign(words_.size(), 0); }
  void insert(std::size_t position) {
    words_[position / 64] |= std::uint64_t{1} << (position % 64);
  }
  void erase(std::size_t position) {
    words_[position / 64] &= ~(std::uint64_t{1} << (position % 64));
  }

  /// Calls `visit(position)` for each position of the set, in increasing order.
  template <class Visit>
  void for_each(Visit visit) const {
    for (std::size_t w = 0; w < words_.size(); ++w) {
      for (std::uint64_t bits = words_[w]; bits != 0; bits &= bits - 1) {
        visit(w * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
      }
    }
  }

 private:
  std::vector<std::uint64_t> words_;
};

}  // namespace smcbip::engines
