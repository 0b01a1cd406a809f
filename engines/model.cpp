// The interpreted model.
#include "engines/model.h"

#include "engines/interpreter/code_eval.h"

namespace smcbip::engines {

std::unique_ptr<ModelCode> InterpretedModel::make_code(const BoundFunctions& functions,
                                                       CallContext& call) const {
  return std::make_unique<CodeEvaluator>(system_, functions, call);
}

}  // namespace smcbip::engines
