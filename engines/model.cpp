// The model interface's own code, the interpreted model and the compiled one.
#include "engines/api/model.h"

#include <memory>
#include <string>

#include "engines/api/compiled_model.h"
#include "engines/interpreter/clock_bounds.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/plugin_steps.h"

namespace smcbip::engines {

namespace {

[[noreturn]] void not_compiled(bipc::ir::Index type) {
  throw CodeFault{"atom type " + std::to_string(type) + " has no compiled steps"};
}

}  // namespace

bipc::ir::Index ModelCode::atom_offers(bipc::ir::Index type, const std::uint8_t*, const Frame&,
                                       std::optional<AtomPortValue>*) {
  not_compiled(type);
}

bipc::ir::Index ModelCode::atom_internal(bipc::ir::Index type, const std::uint8_t*, const Frame&) {
  not_compiled(type);
}

bool ModelCode::atom_fire(bipc::ir::Index type, bipc::ir::Index, std::uint8_t*, const Frame&) {
  not_compiled(type);
}

std::unique_ptr<CompiledSteps> ModelCode::make_steps(const bipc::ir::System& system,
                                                     const Layout& layout) {
  const CompiledAtoms atoms = compiled_atoms();
  if (atoms.types.empty()) return nullptr;
  return make_plugin_steps(*this, atoms, system, layout);
}

std::unique_ptr<ModelCode> make_interpreted_code(const bipc::ir::System& system,
                                                 const BoundFunctions& functions, CallContext& call,
                                                 const GuardBounds* guard_bounds) {
  return std::make_unique<CodeEvaluator>(system, functions, call, guard_bounds);
}

InterpretedModel::InterpretedModel(const bipc::ir::System& system)
    : system_(system), guard_bounds_(std::make_unique<const GuardBounds>(system)) {}

InterpretedModel::~InterpretedModel() = default;

std::unique_ptr<ModelCode> InterpretedModel::make_code(const BoundFunctions& functions,
                                                       CallContext& call) const {
  return std::make_unique<CodeEvaluator>(system_, functions, call, guard_bounds_.get());
}

CompiledModel::CompiledModel(const bipc::ir::System& system, CodeFactory factory)
    : system_(system),
      factory_(factory),
      guard_bounds_(std::make_unique<const GuardBounds>(system)) {}

CompiledModel::~CompiledModel() = default;

std::unique_ptr<ModelCode> CompiledModel::make_code(const BoundFunctions& functions,
                                                    CallContext& call) const {
  return factory_(system_, functions, call, guard_bounds_.get());
}

}  // namespace smcbip::engines
