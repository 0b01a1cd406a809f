// The execution of an interaction value: the connectors' `down`s and the firing of the atom
// ports it chose, in the reference engine's order, in sequence or (multithread scheduler) with
// the atoms fired on a thread pool when that is observably the same.
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
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

struct ParallelFiring;

/// Executes the interaction values of a run's connectors over its state, its connectors' values
/// and its atoms (which the owner keeps), recording failures in `error`.
class InteractionExecution {
 public:
  /// `parallel`: the thread pool and its evaluators (multithread scheduler), or null.
  InteractionExecution(const bipc::ir::System& system, const Layout& layout,
                       const RuntimeOptions& options, ModelCode& eval, RunState& state,
                       ModelError& error, ConnectorValues& connectors, AtomFiring& atoms,
                       std::unique_ptr<ParallelFiring> parallel);
  ~InteractionExecution();
  InteractionExecution(const InteractionExecution&) = delete;
  InteractionExecution& operator=(const InteractionExecution&) = delete;

  /// Executes interaction value `value` (an index into ConnectorValues::values()); false with
  /// the error set on failure. A fault of the model's code on this thread is thrown.
  bool execute(Index value) {
    return parallel_ ? execute_in_parallel(value) : execute_in_sequence(value);
  }
  /// Appends the atom ports (atom, port) the value fires to `out`, in execution order.
  void append_atom_ports(Index value, std::vector<std::pair<Index, Index>>& out) const;

 private:
  /// The connector's `down` of an interaction value, and its data written back to the state.
  void run_down(Index value);
  bool execute_in_sequence(Index value);
  /// execute_in_sequence, with the atoms fired on the thread pool when that is observably the
  /// same (runtime_parallel.cpp).
  bool execute_in_parallel(Index value);
  /// Whether the atoms of the value fire on the thread pool (parallel_->ports: its atom ports).
  bool fires_in_parallel(Index value);
  /// The connectors' downs of the value, in the reference order: the number of its atom ports
  /// before the first down that faults (then in `fault`), else all of them.
  std::size_t run_downs(Index value, std::optional<CodeFault>& fault);
  /// Fires the first `count` atom ports of parallel_->ports on the pool; false with the error
  /// set.
  bool fire_ports_in_parallel(std::size_t count);

  const bipc::ir::System& system_;
  const Layout& layout_;
  std::size_t parallel_min_work_;  // RuntimeOptions::parallel_min_work
  ModelCode& eval_;
  RunState& state_;
  ModelError& error_;
  ConnectorValues& connectors_;
  AtomFiring& atoms_;
  std::unique_ptr<ParallelFiring> parallel_;
};

}  // namespace smcbip::engines
