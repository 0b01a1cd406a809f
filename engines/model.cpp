// The interpreted model.
#include "engines/model.h"

#include <string>

#include "engines/interpreter/clock_bounds.h"
#include "engines/interpreter/code_eval.h"

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
