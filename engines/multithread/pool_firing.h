// The multithread engine's parallel firing: which atom types may fire in parallel, the thread
// pool, and one evaluator per thread.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/multithread/fork_join_pool.h"
#include "engines/semantics/atom_priorities.h"
#include "engines/semantics/interaction_execution.h"
#include "engines/semantics/parallel_firing.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

/// Per atom type, whether its atoms can fire on a thread of their own with the same observable
/// result as in sequence: the code of its transitions (guards, actions, resume guards), of its
/// invariants and of its priority guards calls no function that is not declared pure (see
/// Externs::declare_pure) and touches no slot outside its atom. Output, random numbers and
/// sleeping are side effects whose order the reference engine fixes.
std::vector<std::uint8_t> parallel_safe_atom_types(const bipc::ir::System& system,
                                                   const BoundFunctions& functions);

/// Per atom type, an estimate of the work of firing one of its atoms: the most instructions of
/// one transition (guard, action, resume guard). Forking costs about as much as a thousand
/// instructions, so interactions whose atoms' estimates sum to less than
/// RuntimeOptions::parallel_min_work run inline.
std::vector<std::size_t> atom_type_firing_costs(const bipc::ir::System& system);

/// The evaluator of one pool thread, with the call context its extern calls see and the copy
/// of the data of the atom it fires. Cache-line aligned: the evaluator writes its stack's end
/// at every instruction, which must not share a line with another thread's.
struct alignas(64) ThreadEvaluator {
  ThreadEvaluator(const Model& model, const BoundFunctions& functions, const CallContext& main)
      : call(main), eval(model.make_code(functions, call)) {}
  CallContext call;
  std::unique_ptr<ModelCode> eval;
  std::vector<Val> data;
  AtomPriorities priorities;
};

/// The atoms of an interaction fired on a fork-join pool, each thread with its own evaluator,
/// when that is observably the same as in sequence: at least two atoms with enough work
/// between them, each of a parallel-safe type, none listed twice. The connectors' downs run
/// first, in the reference order.
class PoolFiring final : public ParallelFiring {
 public:
  PoolFiring(const Model& model, const BoundFunctions& functions, const CallContext& main,
             const RuntimeOptions& options);

  std::optional<bool> execute(InteractionExecution& execution, Index value) override;

 private:
  /// Whether the atoms of the value fire on the pool (ports_: its atom ports).
  bool fires_in_parallel(const InteractionExecution& execution, Index value);
  /// The connectors' downs of the value, in the reference order: the number of its atom ports
  /// before the first down that faults (then in `fault`), else all of them.
  std::size_t run_downs(InteractionExecution& execution, Index value,
                        std::optional<CodeFault>& fault);
  /// Fires the first `count` atom ports of ports_ on the pool; false with the error set.
  bool fire_ports(InteractionExecution& execution, std::size_t count);

  multithread::ForkJoinPool pool_;
  std::size_t min_work_;                                      // RuntimeOptions::parallel_min_work
  std::vector<std::unique_ptr<ThreadEvaluator>> evaluators_;  // one per pool thread
  std::vector<std::uint8_t> safe_type_;                       // parallel_safe_atom_types
  std::vector<std::size_t> cost_;                             // atom_type_firing_costs
  // The interaction being executed: its atom ports in reference order, and per port whether it
  // fired without error (else its error).
  std::vector<std::pair<bipc::ir::Index, bipc::ir::Index>> ports_;
  std::vector<std::uint8_t> fired_;
  std::vector<ModelError> errors_;
  // Per atom, the last execution that listed it (to find an atom listed twice).
  std::vector<std::uint64_t> seen_;
  std::uint64_t execution_ = 0;
};

/// A PoolFiring for RuntimeOptions::parallel_firing.
std::unique_ptr<ParallelFiring> make_pool_firing(const Model& model,
                                                 const BoundFunctions& functions,
                                                 const CallContext& main,
                                                 const RuntimeOptions& options);

}  // namespace smcbip::engines
