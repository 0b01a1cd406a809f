// Whether a step of the compiled step path (flat_steps.h) kept the places and data, told from
// the slices of the state its item may write: the scheduler's absorbing-state check
// (Scheduler::discrete_state_kept) without a copy of the whole state at every step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engines/semantics/flat_tables.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

class WrittenSlices {
 public:
  /// The slices of each position of `t`: a connector's data and every bound atom's data and
  /// places (its `down` writes to their data), or an internal port's atom's; adjacent ones
  /// merged, so that a broadcast over neighbouring atoms copies one run of bytes, not one per
  /// atom.
  explicit WrittenSlices(const FlatTables& t);

  /// Before firing position `p` in `state`: copies the slices it may write.
  void remember(const RunState& state, std::uint32_t p);
  /// After: whether they hold the bytes remembered (bytes, as the scheduler compares them).
  bool kept(const RunState& state, std::uint32_t p) const;

 private:
  /// A run of bytes of the state's data (else of its marking).
  struct Slice {
    std::uint32_t first = 0, size = 0;
    bool data = true;
  };
  static const unsigned char* bytes_of(const RunState& state, const Slice& slice);

  std::vector<Slice> slices_;               // per position, merged
  std::vector<std::uint32_t> first_slice_;  // per position, into slices_ (one past the last)
  std::vector<unsigned char> before_;       // the largest position's bytes
};

}  // namespace smcbip::engines
