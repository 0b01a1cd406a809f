// Run-time values of BIP data: one machine word per slot, typed by the IR, with strings interned.
#pragma once

#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>

namespace smcbip::engines {

/// One data slot. The IR knows each slot's kind statically, so no tag is stored: bool in `b`,
/// int in `i`, float in `f`, string as an interned id in `s` (see StringPool), extern data as
/// an opaque handle in `i`.
union Val {
  bool b;
  std::int64_t i;
  double f;
  std::uint64_t s;
};
static_assert(sizeof(Val) == 8);

inline Val make_bool(bool v) {
  Val x;
  x.i = 0;
  x.b = v;
  return x;
}
inline Val make_int(std::int64_t v) {
  Val x;
  x.i = v;
  return x;
}
inline Val make_float(double v) {
  Val x;
  x.f = v;
  return x;
}

/// Interned strings, shared by every run of a model: ids are stable, lookups are thread-safe,
/// and equal strings get equal ids (so string equality is id equality).
class StringPool {
 public:
  StringPool() { intern(""); }
  std::uint64_t intern(std::string_view text);
  /// The text of an id; the reference stays valid for the pool's lifetime.
  const std::string& text(std::uint64_t id) const;

 private:
  mutable std::mutex mutex_;
  std::deque<std::string> texts_;  // deque: references survive growth
  std::unordered_map<std::string_view, std::uint64_t> ids_;
};

}  // namespace smcbip::engines
