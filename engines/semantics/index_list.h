// A short list of indices stored inline while it is short: each connector's enabled values.
#pragma once

#include <cstdint>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::engines {

/// A list of indices whose first few live in the object itself. Most connectors have one or two
/// enabled values; the per-step walks over every connector's values (items, waiting window) then
/// read one contiguous array instead of following a heap pointer per connector.
class IndexList {
 public:
  using Index = bipc::ir::Index;

  const Index* begin() const { return spilled() ? heap_.data() : inline_; }
  const Index* end() const { return begin() + size_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  /// Back to inline storage; a spilled list keeps its heap capacity for the next time.
  void clear() {
    size_ = 0;
    heap_.clear();
  }
  void push_back(Index index) {
    if (!spilled() && size_ < kInline) {
      inline_[size_++] = index;
      return;
    }
    if (!spilled()) heap_.assign(inline_, inline_ + size_);
    heap_.push_back(index);
    ++size_;
  }

 private:
  static constexpr std::uint32_t kInline = 3;
  bool spilled() const { return !heap_.empty(); }

  std::uint32_t size_ = 0;
  Index inline_[kInline] = {};
  std::vector<Index> heap_;
};

}  // namespace smcbip::engines
