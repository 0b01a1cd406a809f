// The atoms of one run: where each one's slots are, its ports' offers, its internal transitions,
// the firing of its transitions and its invariants: the atom side that every interpreted engine shares.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_priorities.h"
#include "engines/semantics/atom_time_bounds.h"
#include "engines/semantics/connector_cache.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

/// Where atom code runs: one thread's evaluator (it has a stack) and the error its failures
/// record. The atoms of one interaction may fire on several threads at once (multithread
/// scheduler); each touches only its own slots of the state.
struct AtomScratch {
  ModelCode& eval;
  ModelError& error;
  /// When set, the data of the one atom being fired: a private copy, so that threads firing
  /// neighbouring atoms do not write to the same cache lines of the state.
  Val* atom_data = nullptr;
  /// Firing on a worker thread: the scheduler's shared bookkeeping is left to the caller.
  bool on_worker = false;
  AtomPriorities* priorities = nullptr;  // the thread's own
  bool fail(int code, std::string message, std::string where = {}) const {
    error = {code, std::move(message), std::move(where)};
    return false;
  }
};

/// The atoms of a run over its `state` (which the owner keeps): their offers, internal
/// transitions, firings and invariants. Functions without a scratch run on the owner's thread
/// (main_scratch); those with one may run on several threads at once for distinct atoms. Every
/// change of an atom is noted in `cache` (on a worker thread the caller notes it, note_changed).
class AtomFiring {
 public:
  AtomFiring(const bipc::ir::System& system, const Layout& layout, ModelCode& eval,
             RunState& state, ModelError& error, ConnectorCache& cache);
  // The main scratch and the frames refer to this object.
  AtomFiring(const AtomFiring&) = delete;
  AtomFiring& operator=(const AtomFiring&) = delete;

  /// The atom ports' offers, flattened by atom, port (the atom's first at port_offset()[atom]).
  const std::vector<std::optional<AtomPortValue>>& port_values() const { return port_values_; }
  const std::vector<std::size_t>& port_offset() const { return port_offset_; }
  /// Withdraws every offer (a run starts).
  void clear_offers() {
    for (std::optional<AtomPortValue>& offer : port_values_) offer.reset();
  }
  AtomTimeBounds& time_bounds() { return time_bounds_; }
  const AtomTimeBounds& time_bounds() const { return time_bounds_; }

  /// The frame of the atom's code over the state, at the state's date.
  Frame frame(Index atom);
  /// Sets every atom's data to its initial values.
  void initialize_data();
  /// The atom's initial places, action and resume, then as settle; false with the error set.
  bool start(Index atom);
  /// After a change that is no firing of the atom (a start, a host writing its data): checks its
  /// invariants, runs its internal transitions and recomputes its offers unless it resumes.
  /// False with the error set.
  bool settle(Index atom);
  /// Checks the atom's invariants and notes their time bound; false with the error set.
  bool check_invariants(Index atom) { return check_invariants(main_scratch_, atom); }
  /// Recomputes the atom's offers; false with the error set.
  bool update(Index atom) { return update(main_scratch_, atom, frame(atom)); }
  /// Fires the transition the atom offers on `port` (none: nothing), its internal transitions,
  /// and recomputes its offers unless it resumes; false with the error set.
  bool fire_port(Index atom, Index port) { return fire_port(main_scratch_, atom, port); }
  /// fire_port with the scratch of the thread it runs on.
  bool fire_port(const AtomScratch& s, Index atom, Index port);
  /// Ends the pending resume of every atom, in atom order; false with the error set when an
  /// atom's update fails.
  bool resume();
  /// An atom fired on a worker thread: its connectors are stale, its time bound may differ.
  void note_changed(Index atom) {
    cache_.touch_atom(atom);
    time_bounds_.note(atom);
  }

 private:
  /// Where atom code finds other atoms' data (Frame::instance_slot).
  static Val* instance_slot(const void* context, Index atom, std::uint16_t slot);
  Frame frame(const AtomScratch& s, Index atom);
  /// `f`: the atom's frame.
  bool update(const AtomScratch& s, Index atom, const Frame& f);
  /// The error of two enabled transitions labelled by `port` (update).
  bool non_deterministic_offers(const AtomScratch& s, Index atom, Index port);
  /// Withdraws the offers of ports that the atom type's active priority rules disable
  /// (update, after the offers; `f`: the atom's frame).
  bool apply_priorities(const AtomScratch& s, Index atom, const Frame& f);
  bool run_internal_transitions(const AtomScratch& s, Index atom);
  /// The one internal transition enabled now, kNone, or ModelCode::kSeveralTransitions.
  Index enabled_internal_transition(const AtomScratch& s, Index atom, const Frame& f);
  bool fire_transition(const AtomScratch& s, Index atom, Index transition, Index port_label,
                       const Frame& f);
  bool check_invariants(const AtomScratch& s, Index atom);

  const bipc::ir::System& system_;
  const Layout& layout_;
  ModelCode& eval_;
  RunState& state_;
  ConnectorCache& cache_;
  AtomPriorities priorities_;  // the main thread's
  // Passed by reference: a copy made on the stack per call stalled on store forwarding.
  const AtomScratch main_scratch_;
  // Per atom: where its slots are (frame).
  struct AtomSlots {
    std::size_t data = 0;
    const Val* params = nullptr;
    std::size_t clocks = 0;
    const TimeValue* clock_units = nullptr;
    bool has_clocks = false;
  };
  std::vector<AtomSlots> slots_;
  // Per atom type: whether the model's code compiles its steps (ModelCode::atom_offers...).
  std::vector<std::uint8_t> compiled_type_;
  // Per atom port (flattened by atom, port): its offer, if any.
  std::vector<std::size_t> port_offset_;
  std::vector<std::optional<AtomPortValue>> port_values_;
  AtomTimeBounds time_bounds_;
};

}  // namespace smcbip::engines
