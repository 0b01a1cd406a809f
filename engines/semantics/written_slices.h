// Whether a step of the compiled step path (flat_steps.h) kept the places and data, told from
// the slices of the state its item may write: the scheduler's absorbing-state check
// (Scheduler::discrete_state_kept) without a copy of the whole state at every step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "engines/semantics/flat_tables.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

class WrittenSlices {
 public:
  /// Before firing position `p` in `state`: copies the slices it may write.
  void remember(const FlatTables& t, const RunState& state, std::uint32_t p) {
    std::size_t at = 0;
    for_each_slice(t, state, p, [&](const unsigned char* bytes, std::size_t size) {
      if (at + size > before_.size()) before_.resize(at + size);
      std::memcpy(before_.data() + at, bytes, size);
      at += size;
    });
  }
  /// After: whether they hold the bytes remembered (bytes, as the scheduler compares them).
  bool kept(const FlatTables& t, const RunState& state, std::uint32_t p) const {
    std::size_t at = 0;
    bool same = true;
    for_each_slice(t, state, p, [&](const unsigned char* bytes, std::size_t size) {
      same = same && std::memcmp(before_.data() + at, bytes, size) == 0;
      at += size;
    });
    return same;
  }

 private:
  /// Calls `f(bytes, size)` on each slice of `state` that firing position `p` may write: a
  /// connector's data and every bound atom's data and places (its `down` writes to their
  /// data), or an internal port's atom's.
  template <class F>
  static void for_each_slice(const FlatTables& t, const RunState& state, std::uint32_t p, F f) {
    const auto atom_slices = [&](const FlatTables::Atom& atom) {
      f(reinterpret_cast<const unsigned char*>(state.data.data() + atom.data),
        atom.data_size * sizeof(Val));
      f(state.marking.data() + atom.places, std::size_t{atom.place_count});
    };
    if (p >= t.connectors.size()) return atom_slices(t.internal[p - t.connectors.size()].of);
    const FlatTables::Connector& c = t.connectors[p];
    f(reinterpret_cast<const unsigned char*>(state.data.data() + c.data),
      c.data_size * sizeof(Val));
    for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) atom_slices(t.ports[i].of);
  }

  std::vector<unsigned char> before_;
};

}  // namespace smcbip::engines
