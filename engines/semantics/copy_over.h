// Copies of the small arrays a run restores at its start and keeps before a step: a few bytes
// each on most models, where a vector's assignment and memcpy's call and size dispatch would
// cost several times the copy itself.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

namespace smcbip::engines {

/// Copies `n` bytes from `from` to `to` (not overlapping). Up to 64 bytes as two fixed-size
/// copies that overlap in the middle, which compile to a few moves; memcpy beyond.
inline void copy_bytes(unsigned char* to, const unsigned char* from, std::size_t n) {
  const auto twice = [&]<std::size_t k>() {
    std::memcpy(to, from, k);
    std::memcpy(to + n - k, from + n - k, k);
  };
  if (n > 64) {
    std::memcpy(to, from, n);
  } else if (n > 32) {
    twice.template operator()<32>();
  } else if (n > 16) {
    twice.template operator()<16>();
  } else if (n >= 8) {
    twice.template operator()<8>();
  } else if (n >= 4) {
    twice.template operator()<4>();
  } else if (n > 0) {
    to[0] = from[0];
    to[n / 2] = from[n / 2];
    to[n - 1] = from[n - 1];
  }
}

/// `to` made a copy of `from`: in place by copy_bytes when the sizes agree (a run's arrays keep
/// their sizes from run to run), by assignment otherwise.
template <class T>
void copy_over(const std::vector<T>& from, std::vector<T>& to) {
  static_assert(std::is_trivially_copyable_v<T>);
  if (to.size() != from.size()) [[unlikely]] {
    to = from;
    return;
  }
  copy_bytes(reinterpret_cast<unsigned char*>(to.data()),
             reinterpret_cast<const unsigned char*>(from.data()), from.size() * sizeof(T));
}

}  // namespace smcbip::engines
