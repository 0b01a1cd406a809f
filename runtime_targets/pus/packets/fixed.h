// Fixed-capacity containers for decoded application data: no heap, bounded sizes.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace smcbip::pus {

/// A vector of at most N elements stored inline; push_back refuses beyond N.
template <class T, std::size_t N>
class FixedVector {
 public:
  static constexpr std::size_t kCapacity = N;

  FixedVector() = default;
  /// Copies the elements of a span; false (and empty) if it holds more than N.
  bool assign(std::span<const T> items) {
    if (items.size() > N) {
      size_ = 0;
      return false;
    }
    std::copy(items.begin(), items.end(), items_.begin());
    size_ = items.size();
    return true;
  }
  /// Appends one element; false when full.
  bool push_back(const T& item) {
    if (size_ == N) return false;
    items_[size_++] = item;
    return true;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; }
  const T& operator[](std::size_t i) const { return items_[i]; }
  T& operator[](std::size_t i) { return items_[i]; }
  const T* begin() const { return items_.data(); }
  const T* end() const { return items_.data() + size_; }
  std::span<const T> span() const { return {items_.data(), size_}; }

  friend bool operator==(const FixedVector& a, const FixedVector& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  std::array<T, N> items_{};
  std::size_t size_ = 0;
};

/// At most N bytes stored inline.
template <std::size_t N>
using FixedBytes = FixedVector<std::uint8_t, N>;

}  // namespace smcbip::pus
