// Interned strings of run-time values.
#include "engines/api/value.h"

namespace smcbip::engines {

std::uint64_t StringPool::intern(std::string_view text) {
  std::lock_guard lock(mutex_);
  if (auto found = ids_.find(text); found != ids_.end()) return found->second;
  texts_.emplace_back(text);
  const std::uint64_t id = texts_.size() - 1;
  ids_.emplace(texts_.back(), id);
  return id;
}

const std::string& StringPool::text(std::uint64_t id) const {
  std::lock_guard lock(mutex_);
  static const std::string kUnknown;
  return id < texts_.size() ? texts_[id] : kUnknown;
}

}  // namespace smcbip::engines
