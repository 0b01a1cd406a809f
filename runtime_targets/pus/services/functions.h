// ST08 function management: performs the mission's functions, whose effects set parameters.
#pragma once

#include <cstdint>

#include "mission/mission.h"
#include "packets/packets.h"
#include "parameters.h"
#include "verification.h"

namespace smcbip::pus::services {

/// Performs [8,1]: the function must be defined (UnknownId) and the call must give each of its
/// arguments exactly once, with a value of the argument's type (InvalidArgument, the argument
/// ID as datum); then each effect sets its parameter (InvalidArgument if out of its limits;
/// then no effect applies).
class FunctionManagement {
 public:
  FunctionManagement(const mission::Mission& mission, ParameterStore& parameters)
      : mission_(mission), parameters_(parameters) {}

  /// What perform() would refuse, without performing.
  Outcome check(const FunctionCall& call) const;
  Outcome perform(const FunctionCall& call);
  /// The last function performed and how many were.
  std::uint64_t last_function() const { return last_function_; }
  std::uint64_t performed() const { return performed_; }

 private:
  Outcome check_arguments(const mission::Function& function, const FunctionCall& call) const;
  ParameterValues effects_of(const mission::Function& function, const FunctionCall& call) const;

  const mission::Mission& mission_;
  ParameterStore& parameters_;
  std::uint64_t last_function_ = 0;
  std::uint64_t performed_ = 0;
};

}  // namespace smcbip::pus::services
