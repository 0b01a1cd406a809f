// The flat step path over generated code's exported atom steps.
#include "engines/semantics/plugin_steps.h"

#include <optional>
#include <utility>

#include "engines/api/compiled_model.h"
#include "engines/semantics/flat_steps.h"

namespace smcbip::engines {

namespace {

/// Generated code seen through its exported table: the atom steps and the compiled Code are
/// calls through the table's pointers (one indirect call each, as a switch on the type or id
/// would cost), the rest goes to the code. Final, so that the flat step path binds its calls to
/// these statically.
class TableAtoms final : public ModelCode {
 public:
  TableAtoms(ModelCode& code, const CompiledAtoms& atoms) : code_(code), atoms_(atoms) {}

  Val evaluate(const bipc::ir::Code& code, const Frame& frame) override {
    if (code.id < atoms_.code.size()) {
      if (const auto compiled = atoms_.code[code.id].evaluate) {
        return compiled(atoms_.context, frame);
      }
    }
    return code_.evaluate(code, frame);
  }
  void execute(const bipc::ir::Code& code, const Frame& frame) override {
    if (code.empty()) return;
    if (code.id < atoms_.code.size()) {
      if (const auto compiled = atoms_.code[code.id].execute) {
        return compiled(atoms_.context, frame);
      }
    }
    code_.execute(code, frame);
  }
  Interval holds_when(const bipc::ir::Code& code, const Frame& frame) override {
    return code_.holds_when(code, frame);
  }
  bool compiles_atom_type(bipc::ir::Index type) const override {
    return type < atoms_.types.size();
  }
  bipc::ir::Index atom_offers(bipc::ir::Index type, const std::uint8_t* marking, const Frame& frame,
                              std::optional<AtomPortValue>* offers) override {
    return atoms_.types[type].offers(atoms_.context, marking, frame, offers);
  }
  bipc::ir::Index atom_internal(bipc::ir::Index type, const std::uint8_t* marking,
                                const Frame& frame) override {
    return atoms_.types[type].internal(atoms_.context, marking, frame);
  }
  bool atom_fire(bipc::ir::Index type, bipc::ir::Index transition, std::uint8_t* marking,
                 const Frame& frame) override {
    return atoms_.types[type].fire(atoms_.context, transition, marking, frame);
  }
  /// The flat step path's fired port in one call (CompiledAtomSteps::fire_and_offer).
  bool atom_fire_and_offer(bipc::ir::Index type, bipc::ir::Index transition, std::uint8_t* marking,
                           const Frame& frame, std::optional<AtomPortValue>* offers) {
    return atoms_.types[type].fire_and_offer(atoms_.context, transition, marking, frame, offers);
  }

 private:
  ModelCode& code_;
  const CompiledAtoms atoms_;
};

/// The flat steps with the table they call.
class PluginSteps final : public CompiledSteps {
 public:
  PluginSteps(ModelCode& code, const CompiledAtoms& atoms, const bipc::ir::System& system,
              const Layout& layout)
      : atoms_(code, atoms) {
    if (std::optional<FlatTables> tables = flat_tables(system, layout, atoms_)) {
      steps_.emplace(atoms_, system, layout, std::move(*tables));
    }
  }
  bool covered() const { return steps_.has_value(); }
  bool begin(const Run& run) override { return steps_->begin(run); }
  Outcome step(bool at_limit, StepInfo& info) override { return steps_->step(at_limit, info); }
  bool step_kept_state() const override { return steps_->step_kept_state(); }
  void check_kept_state() override { steps_->check_kept_state(); }

 private:
  TableAtoms atoms_;
  // Held by its final type: the forwarding calls bind statically.
  std::optional<FlatSteps<TableAtoms>> steps_;
};

}  // namespace

std::unique_ptr<CompiledSteps> make_plugin_steps(ModelCode& code, const CompiledAtoms& atoms,
                                                 const bipc::ir::System& system,
                                                 const Layout& layout) {
  for (const CompiledAtomSteps& type : atoms.types) {
    if (type.offers == nullptr || type.internal == nullptr || type.fire == nullptr ||
        type.fire_and_offer == nullptr) {
      return nullptr;
    }
  }
  auto steps = std::make_unique<PluginSteps>(code, atoms, system, layout);
  if (!steps->covered()) return nullptr;
  return steps;
}

}  // namespace smcbip::engines
