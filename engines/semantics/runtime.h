// One running instance of a system: its state, the items enabled in it (interactions, internal
// and extern ports with their timing constraints), and the execution of a chosen item. The
// schedulers (reference, optimised, multithread) drive it; the semantics lives here once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_priorities.h"
#include "engines/semantics/compound_priorities.h"
#include "engines/semantics/connector_cache.h"
#include "engines/semantics/connector_values.h"
#include "engines/semantics/extern_ports.h"
#include "engines/semantics/index_list.h"
#include "engines/semantics/index_set.h"
#include "engines/semantics/item_listing.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime_types.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

struct ParallelFiring;

class Runtime {
 public:
  Runtime(const Model& model, const Layout& layout, const BoundFunctions& functions,
          StringPool& strings, std::ostream& out, RandomStream& random,
          const RuntimeOptions& options);
  ~Runtime();
  Runtime(const Runtime&) = delete;
  Runtime& operator=(const Runtime&) = delete;

  /// Initial actions, internal transitions and checks (also to start a run over); false with
  /// error() set on failure.
  bool initialize();
  /// Computes the enabled items of the current state; false with error() set on failure.
  bool compute_items();
  /// Replaces the state (e.g. one the explorer kept) and recomputes every atom's offers.
  bool restore(const RunState& state);
  /// Executes an item at date `at`; false with error() set on failure.
  bool execute(const Item& item, TimeValue at);
  /// The interval in which time may pass from now (urgencies, invariants, resume).
  Interval wait_interval() const;
  /// Ends the pending `resume` of every atom at `now` (the reference engine resumes right
  /// after each step); false with error() set when an atom's update fails.
  bool resume_atoms(TimeValue now);
  /// The pending resume windows intersected (all dates when none is pending).
  Interval resume_window() const;
  std::string format_value(Val v, bipc::ir::ValueKind kind) const;

  /// The enabled items computed by the last compute_items, valid until the next execute. The
  /// optimised scheduler lists them only when asked (see item()).
  const std::vector<Item>& items() const { return listing_.items(); }
  /// items().size() and items()[k], without listing the items when the optimised scheduler
  /// counts them (untimed layouts): then in O(log n).
  std::size_t item_count() const { return listing_.count(); }
  Item item(std::size_t k) const { return listing_.item(k); }
  /// The waiting interval the last compute_items cut the items' windows to. With an untimed
  /// layout it is every item's window (their own constraints hold at all dates).
  const Interval& items_window() const { return listing_.window(); }
  /// Interaction values by index (Item::value, PortValue::sub). The optimised scheduler reuses
  /// slots, so slots no item or value refers to may hold values of earlier steps.
  const std::vector<InteractionValue>& values() const { return connectors_.values(); }
  const ModelError& error() const { return error_; }
  /// The model's code this runtime runs on (its thread's).
  ModelCode& code() { return eval_; }
  RunState& state() { return state_; }
  const RunState& state() const { return state_; }
  const Layout& layout() const { return layout_; }
  const bipc::ir::System& system() const { return system_; }

  /// The earliest date at which a pending extern event that its port cannot take arrives.
  std::optional<TimeValue> next_unexpected_arrival() const {
    // Inline for models without extern ports: the optional then stays in registers.
    if (extern_ports_.empty()) return std::nullopt;
    return extern_ports_.first_unexpected_arrival();
  }
  /// The unexpected events arriving until `upto` arrive: policy error stops the run with error
  /// 6, policy ignore drops them. False with error() set on error 6.
  bool receive_unexpected_events(TimeValue upto);
  /// The source of extern port `port` of `atom` has events again after it said it had no more
  /// (a port its host feeds): the next computation of the items pulls from it again.
  void wake_extern_port(Index atom, Index port);
  /// Sets data `slot` of `atom` from outside the model (a host), as if the atom's own action
  /// had: its invariants are checked, its internal transitions run and its offers recomputed
  /// (the optimised scheduler recomputes what depends on the atom). False with error() set.
  bool write_data(Index atom, Index slot, Val value);
  /// Appends the atom ports (atom, port) an item fires to `out`, in execution order.
  void append_atom_ports(const Item& item, std::vector<std::pair<Index, Index>>& out) const;
  /// The value of clock `clock` of `atom` at date `at`, in the clock's unit.
  double clock_value(Index atom, Index clock, TimeValue at) const;
  /// The first date from `now` at which that clock reaches `value` (kPlusInfinity if never).
  TimeValue clock_reaches(Index atom, Index clock, double value) const;
  /// The parameters of the @stochastic annotation of `atom`'s `port`, evaluated now, in `out`
  /// (a buffer the caller reuses).
  void stochastic_params(Index atom, Index port, std::vector<double>& out);
  /// `holder.port(d=1;)` entries of an interaction, as the trace prints them.
  std::string format_ports(const InteractionValue& value) const;
  /// The violated deadlines at `now` (real time), as trace lines without the prefix.
  std::vector<std::string> late_constraints(TimeValue now) const;

 private:
  friend struct RuntimeDetail;
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
  // Passed by reference: a copy made on the stack per call stalled on store forwarding.
  const AtomScratch& main_scratch() const { return main_scratch_; }
  Frame atom_frame(Index atom);
  Frame atom_frame(const AtomScratch& s, Index atom);
  bool update_atom(Index atom) { return update_atom(main_scratch(), atom, atom_frame(atom)); }
  /// `f`: the atom's frame (atom_frame).
  bool update_atom(const AtomScratch& s, Index atom, const Frame& f);
  /// The error of two enabled transitions labelled by `port` (update_atom).
  bool non_deterministic_offers(const AtomScratch& s, Index atom, Index port);
  /// Withdraws the offers of ports that the atom type's active priority rules disable
  /// (update_atom, after the offers; `f`: the atom's frame).
  bool apply_atom_priorities(const AtomScratch& s, Index atom, const Frame& f);
  bool run_internal_transitions(Index atom) {
    return run_internal_transitions(main_scratch(), atom);
  }
  bool run_internal_transitions(const AtomScratch& s, Index atom);
  /// The one internal transition enabled now, kNone, or ModelCode::kSeveralTransitions.
  Index enabled_internal_transition(const AtomScratch& s, Index atom, const Frame& f);
  bool fire_transition(const AtomScratch& s, Index atom, Index transition, Index port_label,
                       const Frame& f);
  bool check_invariants(Index atom) { return check_invariants(main_scratch(), atom); }
  bool check_invariants(const AtomScratch& s, Index atom);
  /// The atoms' clock invariants and pending resume windows intersected: time cannot pass
  /// beyond it whatever is chosen.
  Interval time_bound() const;
  bool execute_value(Index value);
  /// The connector's `down` of an interaction value, and its data written back to the state.
  void run_down(Index value);
  /// execute_value, with the atoms fired on the thread pool when that is observably the same
  /// (runtime_parallel.cpp).
  bool execute_value_in_parallel(Index value);
  /// Whether the atoms of the value fire on the thread pool (parallel_->ports: its atom ports).
  bool fires_in_parallel(Index value);
  /// The connectors' downs of the value, in the reference order: the number of its atom ports
  /// before the first down that faults (then in `fault`), else all of them.
  std::size_t run_downs(Index value, std::optional<CodeFault>& fault);
  /// Fires the first `count` atom ports of parallel_->ports on the pool; false with error() set.
  bool fire_ports_in_parallel(std::size_t count);
  bool fire_port(Index atom, Index port) { return fire_port(main_scratch(), atom, port); }
  bool fire_port(const AtomScratch& s, Index atom, Index port);
  bool fail(int code, std::string message);
  /// A fault of the model's code, at the source location of its instruction.
  bool fail(const CodeFault& fault);
  ModelError fault_error(const CodeFault& fault) const;
  /// `file:line:column` of a source location of the model; empty when unknown.
  std::string where(const bipc::Location& at) const;
  void append_value_ports(Index value, std::vector<std::pair<Index, Index>>& out) const;
  bool fire_extern(const Item& item);
  /// Keeps bounding_atoms_ and resuming_atoms_ up to date after the atom's resume state or
  /// invariant changed.
  void note_time_bound(Index atom);
  /// An atom fired on a worker thread: its connectors are stale, its time bound may differ.
  void note_atom_changed(Index atom);

  const bipc::ir::System& system_;
  const Layout& layout_;
  const BoundFunctions& functions_;
  StringPool& strings_;
  CallContext call_;
  std::unique_ptr<ModelCode> code_;
  ModelCode& eval_;  // *code_
  RuntimeOptions options_;
  RunState state_;
  ModelError error_;
  AtomPriorities atom_priorities_;  // the main thread's
  const AtomScratch main_scratch_{eval_, error_, nullptr, false, &atom_priorities_};
  // Per atom: where its slots are (atom_frame).
  struct AtomSlots {
    std::size_t data = 0;
    const Val* params = nullptr;
    std::size_t clocks = 0;
    const TimeValue* clock_units = nullptr;
    bool has_clocks = false;
  };
  std::vector<AtomSlots> atom_slots_;
  // Per atom type: whether the model's code compiles its steps (ModelCode::atom_offers...).
  std::vector<std::uint8_t> compiled_type_;
  // Per atom port (flattened by atom, port): its offer, if any.
  std::vector<std::size_t> port_offset_;
  std::vector<std::optional<AtomPortValue>> port_values_;
  std::vector<Interval> atom_invariant_;  // time bound of each atom's clock invariants
  Interval time_bound_;                   // time_bound() of the state items are computed in
  // The atoms whose pending resume or invariant bounds the time that may pass (the others
  // leave wait_interval as it is), and those with a pending resume.
  IndexSet bounding_atoms_, resuming_atoms_;
  std::vector<Index> resume_order_;  // resume_atoms' buffer
  ConnectorCache cache_;
  ConnectorValues connectors_;
  ExternPorts extern_ports_;
  ItemListing listing_;
  CompoundPriorities priorities_;
  // Multithread scheduler only (threads > 1): the pool and per-thread evaluators.
  std::unique_ptr<ParallelFiring> parallel_;
};

/// The value of a @stochastic parameter written as a number (the usual case), which needs no
/// frame; nullopt for any other expression.
std::optional<double> number_param(const bipc::ir::Code& code);

}  // namespace smcbip::engines
