// What the multithread scheduler adds to the execution of interactions: which atom types may
// fire in parallel, the thread pool, and one evaluator per thread.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/parallel/fork_join_pool.h"
#include "engines/semantics/atom_priorities.h"
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

/// The state of the multithread scheduler inside an InteractionExecution.
struct ParallelFiring {
  ParallelFiring(const Model& model, const BoundFunctions& functions, const CallContext& main,
                 unsigned threads);

  parallel::ForkJoinPool pool;
  std::vector<std::unique_ptr<ThreadEvaluator>> evaluators;  // one per pool thread
  std::vector<std::uint8_t> safe_type;                       // parallel_safe_atom_types
  std::vector<std::size_t> cost;                             // atom_type_firing_costs
  // The interaction being executed: its atom ports in reference order, and per port whether it
  // fired without error (else its error).
  std::vector<std::pair<bipc::ir::Index, bipc::ir::Index>> ports;
  std::vector<std::uint8_t> fired;
  std::vector<ModelError> errors;
  // Per atom, the last execution that listed it (to find an atom listed twice).
  std::vector<std::uint64_t> seen;
  std::uint64_t execution = 0;
};

}  // namespace smcbip::engines
