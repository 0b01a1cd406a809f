// An engine's firing of one interaction's atoms on threads of its own (the multithread engine's
// pool, engines/multithread/). The semantics knows it only through this interface.
#pragma once

#include <optional>

#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

class InteractionExecution;

class ParallelFiring {
 public:
  virtual ~ParallelFiring() = default;
  /// Executes interaction value `value` of `execution` with its atoms fired in parallel when
  /// that is observably the same as firing them in sequence: the result of
  /// InteractionExecution::execute. nullopt, with nothing done, when it is not.
  virtual std::optional<bool> execute(InteractionExecution& execution, Index value) = 0;
};

}  // namespace smcbip::engines
