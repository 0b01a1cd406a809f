// One running instance of a system: its state, the items enabled in it (interactions, internal
// and extern ports with their timing constraints), and the execution of a chosen item. The
// schedulers (reference, optimised, multithread) drive it; the semantics lives here once.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/externs.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/connector_cache.h"
#include "engines/semantics/index_list.h"
#include "engines/semantics/layout.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

/// A timing constraint: when an item may execute, and how urgent it is.
struct Constraint {
  Interval interval;
  bipc::Urgency urgency = bipc::Urgency::Lazy;
};

/// The complete state of a run (copyable: the explorer keeps states).
struct RunState {
  TimeValue now = 0;
  std::vector<Val> data;
  std::vector<std::uint8_t> marking;
  std::vector<ClockState> clocks;
  std::vector<std::uint8_t> resume_pending;  // per atom
  std::vector<Interval> resume_interval;     // per atom, absolute
};

/// What an atom's port offers in the current state.
struct AtomPortValue {
  Index transition = bipc::ir::kNone;
  Constraint constraint;
};

/// One value a connector port parameter may take: an atom port's offer or one enabled
/// interaction of a sub-connector (with that connector's data after its `up`).
struct PortValue {
  bool from_atom = true;
  Index atom = 0, port = 0;     // atom offers
  Index sub = bipc::ir::kNone;  // sub-connector offers: index into Runtime::values_
  Constraint constraint;
};

/// An enabled interaction value of a connector.
struct InteractionValue {
  Index connector = 0;
  std::uint32_t defined = 0;  // index into Layout::defined[connector]
  PortSet ports = 0;
  std::vector<PortValue> choice;  // one per port parameter in `ports`, in declaration order
  Constraint raw;                 // intersection of the chosen port values' constraints
  Constraint after;               // after maximal progress and priorities
  std::vector<Val> data;          // connector data after `up`
};

/// An item the engine may execute at a state: an interaction, an internal port, an extern port.
struct Item {
  enum class Kind : std::uint8_t { Interaction, Internal, External } kind = Kind::Interaction;
  Index value = 0;           // Interaction: index into values()
  Index atom = 0, port = 0;  // Internal / External
  Constraint constraint;
};

/// How the semantics is computed: the schedulers share it and differ only here.
struct RuntimeOptions {
  bool maximal_progress = true;
  /// Optimised scheduler: keep each connector's interactions between steps and recompute only
  /// those of connectors whose atoms (or sub-connectors) an execution touched.
  bool incremental = false;
  /// Multithread scheduler: the atoms of one interaction execute on this many threads.
  unsigned threads = 1;
};

/// A run-time error of the model, with the reference engine's code and message.
struct ModelError {
  int code = 0;
  std::string message;
};

class Runtime {
 public:
  Runtime(const bipc::ir::System& system, const Layout& layout, const BoundFunctions& functions,
          StringPool& strings, std::ostream& out, RandomStream& random,
          const RuntimeOptions& options);

  /// Initial actions, internal transitions and checks; false with error() set on failure.
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

  const std::vector<Item>& items() const { return items_; }
  /// Interaction values by index (Item::value, PortValue::sub). The optimised scheduler reuses
  /// slots, so slots no item or value refers to may hold values of earlier steps.
  const std::vector<InteractionValue>& values() const { return values_; }
  const ModelError& error() const { return error_; }
  RunState& state() { return state_; }
  const RunState& state() const { return state_; }
  const Layout& layout() const { return layout_; }
  const bipc::ir::System& system() const { return system_; }

  /// The atom ports (atom, port) an item fires, in execution order.
  std::vector<std::pair<Index, Index>> atom_ports(const Item& item) const;
  /// `holder.port(d=1;)` entries of an interaction, as the trace prints them.
  std::string format_ports(const InteractionValue& value) const;
  /// The violated deadlines at `now` (real time), as trace lines without the prefix.
  std::vector<std::string> late_constraints(TimeValue now) const;

 private:
  friend struct RuntimeDetail;
  Frame atom_frame(Index atom);
  bool update_atom(Index atom);
  bool run_internal_transitions(Index atom);
  bool fire_transition(Index atom, Index transition, Index port_label);
  bool check_invariants(Index atom);
  bool check_atom_priority_cycle(Index atom);
  bool check_compound_priority_cycles();
  void compute_connector(Index connector);
  Index store_value(InteractionValue&& value);
  void begin_values(bool full);
  void compute_compound(Index compound);
  void recompute_priorities(Index connector);
  bool dominated_locally(const InteractionValue& low, const InteractionValue& high) const;
  void apply_priorities(InteractionValue& value, Index connector_index);
  bool rule_guard(const PriorityRule& rule);
  /// An interaction named by a priority rule: its connector and port set.
  using RuleNode = std::pair<Index, PortSet>;
  bool applies_low(const PriorityRule& rule, const RuleNode& interaction) const;
  std::vector<RuleNode> high_side(const PriorityRule& rule) const;
  std::vector<RuleNode> low_side(const PriorityRule& rule) const;
  void add_defined(Index connector, std::vector<RuleNode>& out) const;
  void restrict_by(Constraint& c, const Constraint& dominator) const;
  bool execute_value(Index value);
  bool fire_port(Index atom, Index port);
  bool fail(int code, std::string message);
  /// Keeps time_bound_atoms_ up to date after the atom's resume state or invariant changed.
  void note_time_bound(Index atom);

  const bipc::ir::System& system_;
  const Layout& layout_;
  StringPool& strings_;
  CallContext call_;
  CodeEvaluator eval_;
  RuntimeOptions options_;
  bool maximal_progress_;
  RunState state_;
  ModelError error_;
  // Per atom port (flattened by atom, port): its offer, if any.
  std::vector<std::size_t> port_offset_;
  std::vector<std::optional<AtomPortValue>> port_values_;
  std::vector<Interval> atom_invariant_;  // time bound of each atom's clock invariants
  // Per atom: whether a pending resume or an invariant bounds the time that may pass; atoms
  // without either leave wait_interval as it is, so it skips the atoms when none has.
  std::vector<std::uint8_t> time_bound_;
  std::size_t time_bound_atoms_ = 0;
  // Per connector: enabled interaction values (indices into values_), computed bottom up. The
  // optimised scheduler keeps them between steps: values_ is then a pool whose free slots are
  // listed in free_values_.
  std::vector<IndexList> connector_values_;
  std::vector<InteractionValue> values_;
  std::vector<Index> free_values_;
  ConnectorCache cache_;
  std::vector<Item> items_;
};

}  // namespace smcbip::engines
