// How far the atoms of a run let time pass: their clock invariants and pending resume windows,
// with the atoms that bound it kept up to date as they change.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/semantics/index_set.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

/// The time bounds of a run's atoms. It reads the resume state of the run's `state` (which its
/// owner keeps); the invariants' bounds are written by whoever checks the invariants. Only
/// invariant(atom) of distinct atoms may be written on several threads at once.
class AtomTimeBounds {
 public:
  AtomTimeBounds(const RunState& state, std::size_t atoms) : state_(state) {
    invariant_.assign(atoms, Interval::all());
    bounding_.reset(atoms);
    resuming_.reset(atoms);
  }

  /// Keeps the bounding and resuming atoms up to date after the atom's resume state or
  /// invariant changed.
  void note(Index atom) {
    const bool pending = state_.resume_pending[atom] != 0;
    resuming_.assign(atom, pending);
    bounding_.assign(atom, pending || !(invariant_[atom] == Interval::all()));
  }
  /// note() for every atom (a run starts or its state is replaced).
  void note_all() {
    for (Index a = 0; a < invariant_.size(); ++a) note(a);
  }
  /// The time bound of the atom's clock invariants (all dates when none bounds it).
  Interval& invariant(Index atom) { return invariant_[atom]; }
  const Interval& invariant(Index atom) const { return invariant_[atom]; }
  /// The atoms' clock invariants and pending resume windows intersected: time cannot pass
  /// beyond it whatever is chosen.
  Interval bound() const {
    Interval w = Interval::all();
    for (Index a : bounding_) {
      narrow(w, state_.resume_pending[a] ? state_.resume_interval[a] : invariant_[a]);
    }
    return w;
  }
  /// The pending resume windows intersected (all dates when none is pending).
  Interval resume_window() const {
    Interval w = Interval::all();
    for (Index a : resuming_) w = w.intersect(state_.resume_interval[a]);
    return w;
  }
  /// The atoms with a pending resume in atom order, the order the reference engine resumes
  /// them in; a buffer valid until the next call.
  const std::vector<Index>& resuming_in_order() {
    resume_order_.clear();
    if (!resuming_.empty()) {
      resume_order_.assign(resuming_.begin(), resuming_.end());
      std::sort(resume_order_.begin(), resume_order_.end());
    }
    return resume_order_;
  }

 private:
  const RunState& state_;
  std::vector<Interval> invariant_;  // per atom
  // The atoms whose pending resume or invariant bounds the time that may pass (the others
  // leave the bound as it is), and those with a pending resume.
  IndexSet bounding_, resuming_;
  std::vector<Index> resume_order_;
};

}  // namespace smcbip::engines
