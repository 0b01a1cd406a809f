// One running instance of a system: its state, the items enabled in it (interactions, internal
// and extern ports with their timing constraints), and the execution of a chosen item. The
// schedulers (reference, optimised, multithread) drive it; the semantics lives here once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_firing.h"
#include "engines/semantics/compound_priorities.h"
#include "engines/semantics/connector_cache.h"
#include "engines/semantics/connector_values.h"
#include "engines/semantics/extern_ports.h"
#include "engines/semantics/index_list.h"
#include "engines/semantics/interaction_execution.h"
#include "engines/semantics/item_listing.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime_types.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

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
  /// The texts of the run's string values.
  const StringPool& strings() const { return strings_; }

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
  /// The parameters of the @stochastic annotation of `atom`'s `port`, evaluated now, in `out`
  /// (a buffer the caller reuses).
  void stochastic_params(Index atom, Index port, std::vector<double>& out);
  /// The violated deadlines at `now` (real time), as trace lines without the prefix.
  std::vector<std::string> late_constraints(TimeValue now) const;

 private:
  const bipc::ir::System& system_;
  const Layout& layout_;
  StringPool& strings_;
  CallContext call_;
  std::unique_ptr<ModelCode> code_;
  ModelCode& eval_;  // *code_
  RuntimeOptions options_;
  RunState state_;
  ModelError error_;
  ConnectorCache cache_;
  AtomFiring atoms_;
  Interval time_bound_;  // the atoms' time bound in the state items are computed in
  ConnectorValues connectors_;
  ExternPorts extern_ports_;
  ItemListing listing_;
  CompoundPriorities priorities_;
  InteractionExecution execution_;
};

/// A value as the trace prints it (strings by their text in `strings`).
std::string format_value(const StringPool& strings, Val v, bipc::ir::ValueKind kind);
/// `holder.port(d=1;)` entries of an interaction of `runtime`'s state, as the trace prints them.
std::string format_ports(const Runtime& runtime, const InteractionValue& value);

/// The value of a @stochastic parameter written as a number (the usual case), which needs no
/// frame; nullopt for any other expression.
std::optional<double> number_param(const bipc::ir::Code& code);

}  // namespace smcbip::engines
