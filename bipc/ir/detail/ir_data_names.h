// The spellings of the IR's enumerations in its data encoding, shared by writer and reader.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir::detail {

/// Names in enumerator order: the enumerator with value i is written as names[i]. Each table's
/// size is asserted against the enumeration's last member, so one added without a name fails
/// to compile.
inline constexpr std::array<const char*, 6> kValueKindNames = {"void",  "bool",   "int",
                                                               "float", "string", "extern"};
static_assert(kValueKindNames.size() == static_cast<std::size_t>(ValueKind::Extern) + 1);

inline constexpr std::array<const char*, 6> kScopeNames = {
    "atom_data", "atom_param", "clock", "connector_data", "port_param", "instance_data"};
static_assert(kScopeNames.size() == static_cast<std::size_t>(Scope::InstanceData) + 1);

inline constexpr std::array<const char*, 31> kOpNames = {"push_bool",
                                                         "push_int",
                                                         "push_float",
                                                         "push_string",
                                                         "load",
                                                         "store",
                                                         "store_rate",
                                                         "neg",
                                                         "not",
                                                         "bit_not",
                                                         "add",
                                                         "sub",
                                                         "mul",
                                                         "div",
                                                         "mod",
                                                         "bit_and",
                                                         "bit_or",
                                                         "bit_xor",
                                                         "eq",
                                                         "ne",
                                                         "lt",
                                                         "le",
                                                         "gt",
                                                         "ge",
                                                         "int_to_float",
                                                         "call",
                                                         "jump",
                                                         "jump_if_false",
                                                         "jump_if_false_keep",
                                                         "jump_if_true_keep",
                                                         "pop"};
static_assert(kOpNames.size() == static_cast<std::size_t>(Op::Pop) + 1);

inline constexpr std::array<const char*, 7> kTimeUnitNames = {
    "nanosecond", "microsecond", "millisecond", "second", "minute", "hour", "day"};
static_assert(kTimeUnitNames.size() == static_cast<std::size_t>(TimeUnit::Day) + 1);

inline constexpr std::array<const char*, 3> kUrgencyNames = {"lazy", "delayable", "eager"};
static_assert(kUrgencyNames.size() == static_cast<std::size_t>(Urgency::Eager) + 1);

inline constexpr std::array<const char*, 3> kExternPolicyNames = {"remember", "ignore", "error"};
static_assert(kExternPolicyNames.size() == static_cast<std::size_t>(ExternPolicy::Error) + 1);

inline constexpr std::array<const char*, 8> kDistributionNames = {
    "normal", "exponential", "gamma", "chi2", "uniform", "lognormal", "weibull", "custom"};
static_assert(kDistributionNames.size() == static_cast<std::size_t>(Distribution::Custom) + 1);

inline constexpr std::array<const char*, 3> kConnectorResumeNames = {"none", "sync", "async"};
static_assert(kConnectorResumeNames.size() ==
              static_cast<std::size_t>(ConnectorType::Resume::Async) + 1);

inline constexpr std::array<const char*, 2> kPortRefKindNames = {"atom", "connector"};
static_assert(kPortRefKindNames.size() == static_cast<std::size_t>(PortRef::Kind::Connector) + 1);

/// The enumerator spelled `name` in `names`, if any.
template <typename Enum, std::size_t N>
std::optional<Enum> enum_of(const std::array<const char*, N>& names, std::string_view name) {
  for (std::size_t i = 0; i < N; ++i) {
    if (name == names[i]) return static_cast<Enum>(i);
  }
  return std::nullopt;
}

}  // namespace smcbip::bipc::ir::detail
