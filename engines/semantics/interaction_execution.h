// The execution of an interaction value: the connectors' `down`s and the firing of the atom
// ports it chose, in the reference engine's order, in sequence or through an engine's parallel
// firing (parallel_firing.h) when that is observably the same.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_firing.h"
#include "engines/semantics/connector_values.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/parallel_firing.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

/// Executes the interaction values of a run's connectors over its state, its connectors' values
/// and its atoms (which the owner keeps), recording failures in `error`.
class InteractionExecution {
 public:
  /// `parallel`: the engine's parallel firing, or null to fire atoms in sequence.
  InteractionExecution(const bipc::ir::System& system, const Layout& layout, ModelCode& eval,
                       RunState& state, ModelError& error, ConnectorValues& connectors,
                       AtomFiring& atoms, std::unique_ptr<ParallelFiring> parallel);
  ~InteractionExecution();
  InteractionExecution(const InteractionExecution&) = delete;
  InteractionExecution& operator=(const InteractionExecution&) = delete;

  /// Executes interaction value `value` (an index into ConnectorValues::values()); false with
  /// the error set on failure. A fault of the model's code on this thread is thrown.
  bool execute(Index value) {
    if (parallel_) {
      if (const std::optional<bool> done = parallel_->execute(*this, value)) return *done;
    }
    return execute_in_sequence(value);
  }
  /// Appends the atom ports (atom, port) the value fires to `out`, in execution order.
  void append_atom_ports(Index value, std::vector<std::pair<Index, Index>>& out) const;

  // What a parallel firing works on.
  /// The connector's `down` of an interaction value, and its data written back to the state.
  /// A fault of the model's code is thrown.
  void run_down(Index value);
  const bipc::ir::System& system() const { return system_; }
  const Layout& layout() const { return layout_; }
  RunState& state() { return state_; }
  ModelError& error() { return error_; }
  AtomFiring& atoms() { return atoms_; }
  const std::vector<InteractionValue>& values() const { return connectors_.values(); }

 private:
  bool execute_in_sequence(Index value);

  const bipc::ir::System& system_;
  const Layout& layout_;
  ModelCode& eval_;
  RunState& state_;
  ModelError& error_;
  ConnectorValues& connectors_;
  AtomFiring& atoms_;
  std::unique_ptr<ParallelFiring> parallel_;
};

}  // namespace smcbip::engines
