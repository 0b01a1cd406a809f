// The data a running system is made of: its state, the interaction values and items of a state,
// the errors of a run, and the options that choose how the semantics is computed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/copy_over.h"
#include "engines/semantics/layout.h"

namespace smcbip::engines {

/// The complete state of a run (copyable: the explorer keeps states).
struct RunState {
  TimeValue now = 0;
  std::vector<Val> data;
  std::vector<std::uint8_t> marking;
  std::vector<ClockState> clocks;
  std::vector<std::uint8_t> resume_pending;  // per atom
  std::vector<Interval> resume_interval;     // per atom, absolute
};

/// `to = from`, in place (copy_over): a statistical check restores the start state every run.
inline void assign_state(RunState& to, const RunState& from) {
  // A field added to RunState must be copied here too.
  static_assert(sizeof(RunState) == sizeof(TimeValue) + 5 * sizeof(std::vector<Val>));
  to.now = from.now;
  copy_over(from.data, to.data);
  copy_over(from.marking, to.marking);
  copy_over(from.clocks, to.clocks);
  copy_over(from.resume_pending, to.resume_pending);
  copy_over(from.resume_interval, to.resume_interval);
}

/// One value a connector port parameter may take: an atom port's offer or one enabled
/// interaction of a sub-connector (with that connector's data after its `up`).
struct PortValue {
  bool from_atom = true;
  Index atom = 0, port = 0;     // atom offers
  Index sub = bipc::ir::kNone;  // sub-connector offers: index into Runtime::values()
  Constraint constraint;
  Index param = 0;  // the connector's port parameter this value is offered to
};

/// An enabled interaction value of a connector.
struct InteractionValue {
  Index connector = 0;
  /// Index into Layout::defined[connector]; kLargest for the largest enabled interaction of a
  /// maximal_only connector.
  std::uint32_t defined = 0;
  static constexpr std::uint32_t kLargest = 0xffffffffu;
  int code = -1;                  // index into ConnectorType::interactions (guard, up, down), or -1
  PortSet ports = 0;              // empty on connectors wider than a PortSet
  std::vector<PortValue> choice;  // one per port parameter taking part, in declaration order
  Constraint raw;                 // intersection of the chosen port values' constraints
  Constraint after;               // after maximal progress and priorities
  std::vector<Val> data;          // connector data after `up`
};

/// An item the engine may execute at a state: an interaction, an internal port, an extern port.
struct Item {
  enum class Kind : std::uint8_t { Interaction, Internal, External } kind = Kind::Interaction;
  Index value = 0;           // Interaction: index into values()
  Index atom = 0, port = 0;  // Internal / External
  Constraint constraint;     // cut to the admissible waiting interval from now
  Constraint offered;        // before that cut: unchanged while the item's atoms do not move
};

class ParallelFiring;
struct RuntimeOptions;
/// Makes the parallel firing of one run: its own evaluators run the model's code as `main`'s
/// does (the multithread engine's make_pool_firing).
using ParallelFiringMaker = std::unique_ptr<ParallelFiring> (*)(const Model& model,
                                                                const BoundFunctions& functions,
                                                                const CallContext& main,
                                                                const RuntimeOptions& options);

/// How the semantics is computed: the engines share it and differ only here (engines/engine.h
/// says how each sets it).
struct RuntimeOptions {
  bool maximal_progress = true;
  /// The incremental cache (optimised and multithread engines): each connector's interactions
  /// are kept between steps, and only those of connectors whose atoms (or sub-connectors) an
  /// execution touched are computed again.
  bool incremental = false;
  /// The firing of an interaction's atoms on other threads (multithread engine); null: they
  /// fire in sequence.
  ParallelFiringMaker parallel_firing = nullptr;
  /// For parallel_firing: the threads, the caller's included.
  unsigned threads = 1;
  /// For parallel_firing: the least estimated work of an interaction's atoms, in
  /// instructions, for which they fire in parallel (0: always; tests use it).
  std::size_t parallel_min_work = 1000;
};

/// A run-time error of the model, with the reference engine's code and message, and where in
/// the model's source it arose (`file:line:column`, empty when unknown).
struct ModelError {
  int code = 0;
  std::string message;
  std::string where;
};

/// `file:line:column` of a source location of the system; empty when unknown.
std::string source_position(const bipc::ir::System& system, const bipc::Location& at);
/// The error of a fault of the model's code, at the source location of its instruction.
ModelError fault_error(const bipc::ir::System& system, const CodeFault& fault);

/// A state the engines cannot compute (thrown inside compute_items, reported as an input error).
struct UnsupportedRun {
  std::string message;
};

}  // namespace smcbip::engines
