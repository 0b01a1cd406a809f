// Parameter and argument values: the raw bits of the four-octet value field and lookups.
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "mission.h"

namespace smcbip::pus::mission {

std::uint64_t to_raw(ValueType type, double value) {
  switch (type) {
    case ValueType::Uint32:
      return static_cast<std::uint32_t>(value);
    case ValueType::Int32:
      return static_cast<std::uint32_t>(static_cast<std::int32_t>(value));
    case ValueType::Float32:
      return std::bit_cast<std::uint32_t>(static_cast<float>(value));
    case ValueType::Bool:
      return value != 0 ? 1 : 0;
  }
  return 0;
}

double from_raw(ValueType type, std::uint64_t raw) {
  const auto bits = static_cast<std::uint32_t>(raw);
  switch (type) {
    case ValueType::Uint32:
      return bits;
    case ValueType::Int32:
      return static_cast<std::int32_t>(bits);
    case ValueType::Float32:
      return std::bit_cast<float>(bits);
    case ValueType::Bool:
      return bits != 0 ? 1 : 0;
  }
  return 0;
}

bool representable(ValueType type, double value) {
  if (!std::isfinite(value)) return false;
  switch (type) {
    case ValueType::Uint32:
      return value == std::floor(value) && value >= 0 &&
             value <= std::numeric_limits<std::uint32_t>::max();
    case ValueType::Int32:
      return value == std::floor(value) && value >= std::numeric_limits<std::int32_t>::min() &&
             value <= std::numeric_limits<std::int32_t>::max();
    case ValueType::Float32:
      return std::fabs(value) <= std::numeric_limits<float>::max();
    case ValueType::Bool:
      return value == 0 || value == 1;
  }
  return false;
}

std::string_view type_name(ValueType type) {
  switch (type) {
    case ValueType::Uint32:
      return "uint32";
    case ValueType::Int32:
      return "int32";
    case ValueType::Float32:
      return "float32";
    case ValueType::Bool:
      return "bool";
  }
  return "?";
}

const Parameter* Mission::find_parameter(std::uint64_t id) const {
  const std::size_t i = parameter_index(id);
  return i < parameters.size() ? &parameters[i] : nullptr;
}

std::size_t Mission::parameter_index(std::uint64_t id) const {
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (parameters[i].id == id) return i;
  }
  return parameters.size();
}

const Event* Mission::find_event(std::uint64_t id) const {
  for (const Event& event : events) {
    if (event.id == id) return &event;
  }
  return nullptr;
}

const Function* Mission::find_function(std::uint64_t id) const {
  for (const Function& function : functions) {
    if (function.id == id) return &function;
  }
  return nullptr;
}

}  // namespace smcbip::pus::mission
