// A set of small indices (atoms, connectors, ports) that the optimised scheduler keeps up to date
// step by step, so that the per-step walks visit its members rather than every index.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::engines {

/// A set of indices below a bound with O(1) insertion, removal and membership test, whose
/// members are iterated in no particular order (callers combine them with order-free
/// operations, or sort a copy).
class IndexSet {
 public:
  using Index = bipc::ir::Index;

  /// The empty set of indices below `bound`.
  void reset(std::size_t bound) {
    where_.assign(bound, kAbsent);
    members_.clear();
  }
  bool contains(Index i) const { return where_[i] != kAbsent; }
  void insert(Index i) {
    if (contains(i)) return;
    where_[i] = static_cast<Index>(members_.size());
    members_.push_back(i);
  }
  void erase(Index i) {
    if (!contains(i)) return;
    const Index last = members_.back();
    members_[where_[i]] = last;
    where_[last] = where_[i];
    members_.pop_back();
    where_[i] = kAbsent;
  }
  /// Inserts `i` when `member`, else removes it.
  void assign(Index i, bool member) {
    if (member) {
      insert(i);
    } else {
      erase(i);
    }
  }
  void clear() {
    for (Index i : members_) where_[i] = kAbsent;
    members_.clear();
  }
  std::size_t size() const { return members_.size(); }
  bool empty() const { return members_.empty(); }
  std::vector<Index>::const_iterator begin() const { return members_.begin(); }
  std::vector<Index>::const_iterator end() const { return members_.end(); }

 private:
  static constexpr Index kAbsent = std::numeric_limits<Index>::max();
  std::vector<Index> where_;  // per index: its slot in members_, or kAbsent
  std::vector<Index> members_;
};

}  // namespace smcbip::engines
