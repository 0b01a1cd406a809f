// Interface views built in tests: interfaces and parameters with the view's other attributes
// unset.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "taste2bip/interface_view/interface_view.h"

namespace smcbip::taste2bip::test {

/// An interface of `kind` with these parameters.
inline Interface interface(const std::string& name, InterfaceKind kind,
                           std::vector<Parameter> parameters = {}) {
  Interface i;
  i.name = name;
  i.kind = kind;
  i.parameters = std::move(parameters);
  return i;
}

inline Parameter parameter(Parameter::Direction direction, const std::string& name,
                           const std::string& type) {
  Parameter p;
  p.direction = direction;
  p.name = name;
  p.type = type;
  return p;
}

}  // namespace smcbip::taste2bip::test
