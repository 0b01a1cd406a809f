// ST08: function calls checked against the mission's definitions.
#include "functions.h"

namespace smcbip::pus::services {

Outcome FunctionManagement::check_arguments(const mission::Function& function,
                                            const FunctionCall& call) const {
  for (const IdValue& given : call.arguments) {
    std::size_t matches = 0;
    for (const IdValue& other : call.arguments) matches += other.id == given.id ? 1 : 0;
    const mission::Argument* declared = nullptr;
    for (const mission::Argument& a : function.arguments) {
      if (a.id == given.id) declared = &a;
    }
    const auto datum = static_cast<std::uint32_t>(given.id);
    if (declared == nullptr || matches > 1) return Failure{FailureCode::InvalidArgument, datum};
    const double v = mission::from_raw(declared->type, given.value);
    if (given.value > 0xFFFFFFFFU || mission::to_raw(declared->type, v) != given.value) {
      return Failure{FailureCode::InvalidArgument, datum};
    }
  }
  if (call.arguments.size() != function.arguments.size()) {
    for (const mission::Argument& a : function.arguments) {
      bool given = false;
      for (const IdValue& g : call.arguments) given = given || g.id == a.id;
      if (!given) return Failure{FailureCode::InvalidArgument, static_cast<std::uint32_t>(a.id)};
    }
  }
  return std::nullopt;
}

ParameterValues FunctionManagement::effects_of(const mission::Function& function,
                                               const FunctionCall& call) const {
  ParameterValues sets;
  for (const mission::Effect& effect : function.effects) {
    std::uint64_t raw = 0;
    if (effect.value) {
      raw = mission::to_raw(mission_.find_parameter(effect.parameter)->type, *effect.value);
    } else {
      for (const IdValue& given : call.arguments) {
        if (given.id == *effect.argument) raw = given.value;
      }
    }
    sets.values.push_back(IdValue{effect.parameter, raw});
  }
  return sets;
}

Outcome FunctionManagement::check(const FunctionCall& call) const {
  const mission::Function* function = mission_.find_function(call.function_id);
  if (function == nullptr) {
    return Failure{FailureCode::UnknownId, static_cast<std::uint32_t>(call.function_id)};
  }
  if (Outcome failure = check_arguments(*function, call)) return failure;
  return parameters_.check(effects_of(*function, call));
}

Outcome FunctionManagement::perform(const FunctionCall& call) {
  if (Outcome failure = check(call)) return failure;
  const mission::Function* function = mission_.find_function(call.function_id);
  parameters_.set_all(effects_of(*function, call));
  last_function_ = function->id;
  ++performed_;
  return std::nullopt;
}

}  // namespace smcbip::pus::services
