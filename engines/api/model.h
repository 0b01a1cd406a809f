// The model interface of the engines: a system's structure (the IR's atoms, connectors and
// priorities, as tables) and its code (every guard, action, timing constraint and stochastic
// parameter, found by Code::id). The semantics (engines/semantics) and the schedulers run over
// it, whether the code is interpreted from the IR or compiled from generated C++.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/time_value.h"
#include "engines/api/value.h"

namespace smcbip::engines {

struct Frame;  // compiled_model.h
struct BoundFunctions;
class GuardBounds;
struct Layout;
class CompiledSteps;

/// A timing constraint: when an item may execute, and how urgent it is.
struct Constraint {
  Interval interval;
  bipc::Urgency urgency = bipc::Urgency::Lazy;
};

/// What an atom's port offers in the current state.
struct AtomPortValue {
  bipc::ir::Index transition = bipc::ir::kNone;
  Constraint constraint;
};

/// One atom type's steps as generated code exports them (ModelCode::atom_offers, atom_internal
/// and atom_fire for that type): plain functions over the code's own context, which the
/// engines' compiled step path calls through these pointers.
struct CompiledAtomSteps {
  bipc::ir::Index (*offers)(void* context, const std::uint8_t* marking, const Frame& frame,
                            std::optional<AtomPortValue>* offers) = nullptr;
  bipc::ir::Index (*internal)(void* context, const std::uint8_t* marking,
                              const Frame& frame) = nullptr;
  bool (*fire)(void* context, bipc::ir::Index transition, std::uint8_t* marking,
               const Frame& frame) = nullptr;
  /// The three in one call, as a fired port of the atom needs them: fire `transition`, then
  /// the internal transitions it enables one by one, then reset every port's offer and set
  /// them afresh (offers). False where one of them fails: a token on a marked place, several
  /// internal transitions enabled, a second enabled transition on a port.
  bool (*fire_and_offer)(void* context, bipc::ir::Index transition, std::uint8_t* marking,
                         const Frame& frame, std::optional<AtomPortValue>* offers) = nullptr;
};

/// A Code of the system compiled (ModelCode::evaluate or execute of that Code alone), found by
/// Code::id: `evaluate` for an expression or guard, `execute` for a statement block; both null
/// for empty code and code the generator left to the interface.
struct CompiledCode {
  Val (*evaluate)(void* context, const Frame& frame) = nullptr;
  void (*execute)(void* context, const Frame& frame) = nullptr;
};

/// Every atom type's steps (indexed by the IR's atom type) and every Code (indexed by
/// Code::id; may be shorter, or empty), and the context they take.
struct CompiledAtoms {
  std::span<const CompiledAtomSteps> types;
  void* context = nullptr;
  std::span<const CompiledCode> code;
};

/// Runs a model's code over one frame (an atom's or a connector's slots, and the date). One per
/// thread: an implementation may keep a stack. Faults (division by zero, a missing extern) are
/// thrown as CodeFault.
class ModelCode {
 public:
  virtual ~ModelCode() = default;
  /// The value of an expression (an empty one is `true`).
  virtual Val evaluate(const bipc::ir::Code& code, const Frame& frame) = 0;
  /// Runs a statement block.
  virtual void execute(const bipc::ir::Code& code, const Frame& frame) = 0;
  /// The dates (absolute) at which a guard over clocks holds, data read as they are now; empty
  /// code holds always.
  virtual Interval holds_when(const bipc::ir::Code& code, const Frame& frame) = 0;

  bool holds(const bipc::ir::Code& code, const Frame& frame) {
    return code.empty() || evaluate(code, frame).b;
  }

  // Compiled atom steps: generated code may take over an atom type's transitions as straight
  // C++ (the places it reads and writes are the atom's own marking, `marking[p]` for place p).
  // The engines keep the rest of the semantics (resume, invariants, priorities, errors).

  /// Whether atom_offers, atom_internal and atom_fire answer for atom type `type`.
  virtual bool compiles_atom_type(bipc::ir::Index /*type*/) const { return false; }
  /// Sets `offers[port]` for every labelled transition enabled in `marking` whose guard holds at
  /// some date (the offers arrive reset), examined as the engines do: from the one marked place
  /// of a state machine, else all, in declaration order. Returns bipc::ir::kNone, or the port
  /// of a second enabled transition (a non-deterministic choice; the offers are then partial).
  virtual bipc::ir::Index atom_offers(bipc::ir::Index type, const std::uint8_t* marking,
                                      const Frame& frame, std::optional<AtomPortValue>* offers);
  /// The unlabelled internal transition enabled in `marking` whose guard holds now:
  /// bipc::ir::kNone when none, kSeveralTransitions when more than one.
  virtual bipc::ir::Index atom_internal(bipc::ir::Index type, const std::uint8_t* marking,
                                        const Frame& frame);
  /// Moves the tokens of `transition` and runs its action; false, before the action, when a
  /// token would land on a marked place (the net is not 1-safe).
  virtual bool atom_fire(bipc::ir::Index type, bipc::ir::Index transition, std::uint8_t* marking,
                         const Frame& frame);
  static constexpr bipc::ir::Index kSeveralTransitions = bipc::ir::kNone - 1;

  /// Generated code's atom steps, for the engines' compiled step path (empty when the code
  /// has none: the interpreter's path then runs).
  virtual CompiledAtoms compiled_atoms() { return {}; }

  /// The compiled step path over this code's compiled_atoms() for `system` laid out as
  /// `layout`, if it has them and the path covers the system (nullptr otherwise). The code must
  /// outlive it. Not virtual: the path is the engines' own, whichever code it calls.
  std::unique_ptr<CompiledSteps> make_steps(const bipc::ir::System& system, const Layout& layout);
};

/// A runnable model: its structure, and code runners for it.
class Model {
 public:
  virtual ~Model() = default;
  /// The structure (immutable, shared by every run and thread).
  virtual const bipc::ir::System& system() const = 0;
  /// A code runner for one thread; extern calls go through `functions` (bound from the run's
  /// registry) and see `call` (the run's output, strings and random stream).
  virtual std::unique_ptr<ModelCode> make_code(const BoundFunctions& functions,
                                               CallContext& call) const = 0;
};

/// The model interpreted from its IR: expressions run on a stack machine over Code::instrs.
class InterpretedModel final : public Model {
 public:
  explicit InterpretedModel(const bipc::ir::System& system);
  ~InterpretedModel() override;
  const bipc::ir::System& system() const override { return system_; }
  std::unique_ptr<ModelCode> make_code(const BoundFunctions& functions,
                                       CallContext& call) const override;

 private:
  const bipc::ir::System& system_;
  std::unique_ptr<const GuardBounds> guard_bounds_;  // shared by the threads' evaluators
};

/// A model whose code was compiled from the C++ that `bipc gen` generated for `system`: the
/// structure is that System (it must be the one generated from, with the same Code numbering),
/// the code comes from the generated factory (`make_model_code`).
class CompiledModel final : public Model {
 public:
  using CodeFactory = std::unique_ptr<ModelCode> (*)(const bipc::ir::System& system,
                                                     const BoundFunctions& functions,
                                                     CallContext& call,
                                                     const GuardBounds* guard_bounds);
  CompiledModel(const bipc::ir::System& system, CodeFactory factory);
  ~CompiledModel() override;
  const bipc::ir::System& system() const override { return system_; }
  std::unique_ptr<ModelCode> make_code(const BoundFunctions& functions,
                                       CallContext& call) const override;

 private:
  const bipc::ir::System& system_;
  CodeFactory factory_;
  std::unique_ptr<const GuardBounds> guard_bounds_;
};

}  // namespace smcbip::engines
