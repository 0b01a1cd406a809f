// Whether a step of the compiled step path (flat_steps.h) kept the places and data, told from
// the transitions it fires when one of them always changes its atom (FlatTables::changing),
// else from the slices of the state its item may write: the scheduler's absorbing-state check
// (Scheduler::discrete_state_kept) without a copy of the whole state at every step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "engines/api/model.h"
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

  /// Before firing position `p` with the atoms' `offers`: whether a transition it fires always
  /// changes its atom, so that the step cannot keep the state and needs no comparison.
  bool surely_changed(std::uint32_t p, const std::optional<AtomPortValue>* offers) const {
    for (std::uint32_t i = first_changer_[p]; i < first_changer_[p + 1]; ++i) {
      const Changer& changer = changers_[i];
      const std::optional<AtomPortValue>& offer = offers[changer.offer];
      if (offer && (changing_[changer.first_transition + offer->transition] & changer.mask)) {
        return true;
      }
    }
    return false;
  }

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
  /// An atom port a position fires whose transition alone may tell that the step changes the
  /// state: its atom fires no internal transitions after it, and no other port of the item
  /// binds that atom.
  struct Changer {
    std::uint32_t offer = 0, first_transition = 0;
    std::uint8_t mask = FlatTables::kChanges;  // kChangesAfterDown under a `down`
  };
  /// The changers of position `p` of `t`, added to changers_.
  void add_changers(const FlatTables& t, std::uint32_t p);

  std::vector<Slice> slices_;                 // per position, merged
  std::vector<std::uint32_t> first_slice_;    // per position, into slices_ (one past the last)
  std::vector<unsigned char> before_;         // the largest position's bytes
  std::vector<Changer> changers_;             // per position
  std::vector<std::uint32_t> first_changer_;  // per position, into changers_ (one past the last)
  std::vector<std::uint8_t> changing_;        // FlatTables::changing
};

}  // namespace smcbip::engines
