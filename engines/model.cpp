// The interpreted model.
#include "engines/model.h"

#include "engines/interpreter/clock_bounds.h"
#include "engines/interpreter/code_eval.h"

namespace smcbip::engines {

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
