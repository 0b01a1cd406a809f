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
  const std::vector<InteractionValue>& values() const { return values_; }
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
  // Reusable buffers of compute_connector, one per depth of sub-connector recursion.
  struct ConnectorScratch {
    std::vector<PortValue> offers;           // the ports' offers, port after port
    std::vector<std::uint32_t> first_offer;  // per port, its first offer; then offers.size()
    std::vector<Index> members;              // the ports of the port set being combined
    std::vector<std::uint32_t> pick;         // per member, the offer of the combination
    std::vector<std::uint8_t> enabled;       // per port parameter: whether it has an offer
  };
  // What the values of one port set of a connector share.
  struct ValueShape {
    Index connector = 0;
    std::uint32_t defined = 0;  // InteractionValue::defined
    PortSet ports = 0;
    int code = -1;  // InteractionValue::code
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
  void compute_connector(Index connector);
  /// Fills required_offers_ and has_sub_connectors_.
  void index_required_offers();
  /// Whether a port every interaction of the connector contains binds only atom ports, none of
  /// which offers anything: then the connector has no interaction.
  bool misses_required_atom_port(Index connector) const;
  /// Whether the connector had no values and, its atoms' offers being what they are, still
  /// has none: the optimised scheduler then leaves it as it is.
  bool keeps_no_values(Index connector) const;
  /// Computes the connectors bound to the connector's ports, in port order.
  void compute_sub_connectors(Index connector);
  /// Frees the connector's values of the last computation.
  void release_values(Index connector);
  /// Whether the connector's values may come from add_largest_values: a maximal_only connector
  /// under maximal progress that is not a rendezvous (one defined interaction is its own
  /// largest, and enumerating it is as quick).
  bool tries_largest(Index connector) const;
  /// The connector's interaction values, from its ports' offers.
  void compute_interactions(Index connector);
  /// Per port parameter, the offers of the atom ports and sub-connectors it binds.
  void gather_offers(Index connector, ConnectorScratch& scratch);
  /// Values of a maximal_only connector under maximal progress when its offers allow
  /// (maximal_interaction.h); false when they do not and the defined ones must be enumerated.
  bool add_largest_values(Index connector, ConnectorScratch& scratch);
  /// The values of defined interaction `d`: one per combination of its ports' offers.
  void add_interactions(Index connector, std::uint32_t d, ConnectorScratch& scratch);
  /// The values of a port set (`scratch.members`, increasing; `scratch.pick` at their first
  /// offers): one per combination of the members' offers, the last member varying fastest.
  void add_combinations(const ValueShape& shape, ConnectorScratch& scratch);
  /// compute_interactions for a connector whose ports each bind one atom port.
  void compute_single_offer_interactions(Index connector);
  /// Fills single_atom_ports_.
  void index_single_atom_ports();
  /// Tells the cache which connectors have values from their offers alone
  /// (ConnectorCache::note_offers_only); after index_single_atom_ports.
  void index_direct_connectors();
  /// A new value of the shape, with no port chosen yet.
  [[gnu::always_inline]] inline Index start_value(const ValueShape& shape);
  /// Chooses the offer for the value's next port.
  [[gnu::always_inline]] static inline void add_choice(InteractionValue& value,
                                                       const PortValue& offer);
  /// Keeps the value among the connector's if its constraint and guard allow, else frees it.
  void keep_value_if_allowed(Index connector, Index slot);
  /// Copies the connector's data into the value and runs the guard, then `up` if it holds.
  bool connector_code_allows(InteractionValue& value);
  /// A free slot of values_ for a new value (its vectors keep their capacity).
  [[gnu::always_inline]] inline Index acquire_value();
  void begin_values(bool full);
  /// Every connector's values, or (incremental) those of the connectors the cache finds stale.
  void compute_values(bool full);
  void compute_compound(const std::vector<Index>& connectors);
  /// The connector's values after priorities (CompoundPriorities::recompute), counted.
  void recompute_priorities(Index connector);
  /// compute_connector for CompoundPriorities.
  static void compute_connector_of(void* runtime, Index connector);
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
  bool maximal_progress_;
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
  // Per atom port (flattened likewise): its first entry in port_data_slots_, which lists the
  // state slots of the ports' parameters (connector code reads and writes them).
  std::vector<std::size_t> port_data_begin_;
  std::vector<std::size_t> port_data_slots_;
  std::vector<Interval> atom_invariant_;  // time bound of each atom's clock invariants
  Interval time_bound_;                   // time_bound() of the state items are computed in
  // The atoms whose pending resume or invariant bounds the time that may pass (the others
  // leave wait_interval as it is), and those with a pending resume.
  IndexSet bounding_atoms_, resuming_atoms_;
  std::vector<Index> resume_order_;  // resume_atoms' buffer
  // Per connector: enabled interaction values (indices into values_), computed bottom up. The
  // optimised scheduler keeps them between steps: values_ is then a pool whose free slots are
  // listed in free_values_.
  std::vector<IndexList> connector_values_;
  // Per connector whose port parameters each bind exactly one atom port: those atom ports, in
  // parameter order (empty for other connectors).
  struct SingleAtomPort {
    Index atom = 0, port = 0;
    std::size_t offer = 0;  // index into port_values_
  };
  std::vector<std::vector<SingleAtomPort>> single_atom_ports_;
  // Per connector: the atom ports bound to its port parameters that every defined interaction
  // contains (parameters binding atom ports only), parameter by parameter; and whether a
  // parameter binds a sub-connector.
  struct RequiredOffer {
    Index atom = 0;
    std::size_t port_value = 0;  // index into port_values_
    bool ends_group = false;     // the last atom port of its parameter
  };
  std::vector<std::vector<RequiredOffer>> required_offers_;
  std::vector<std::uint8_t> has_sub_connectors_;
  std::vector<InteractionValue> values_;
  std::vector<Index> free_values_;
  std::deque<ConnectorScratch> scratch_;  // deque: outer frames keep their references
  std::size_t scratch_depth_ = 0;
  ConnectorCache cache_;
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
