// Name lookup inside a data view, shared by its public lookups and the resolver.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "taste2bip/asn1/data_view.h"

namespace smcbip::taste2bip::asn1::detail {

/// Identifies a value assignment: `modules[module].values[index]`.
struct ValueId {
  std::size_t module = 0;
  std::size_t index = 0;
};

/// The first module named `name`.
std::optional<std::size_t> module_index(const DataView& view, std::string_view name);
/// The type `name` as module `module` sees it: its own, or imported (chains followed).
std::optional<TypeId> find_type_from(const DataView& view, std::size_t module,
                                     std::string_view name);
/// The value `name` as module `module` sees it.
std::optional<ValueId> find_value_from(const DataView& view, std::size_t module,
                                       std::string_view name);

}  // namespace smcbip::taste2bip::asn1::detail
