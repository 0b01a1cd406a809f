// Name lookup inside a data view, shared by its public lookups and the resolver.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "taste2bip/asn1/data_view.h"

namespace smcbip::taste2bip::asn1::detail {

/// Identifies a value assignment: `modules[module].values[index]`.
struct ValueId {
  std::size_t module = 0;
  std::size_t index = 0;
};

/// Indexes the names of a view (built once, then each lookup is logarithmic). Lookups from a
/// module see its own assignments, then what it imports, following chains of IMPORTS.
class Lookup {
 public:
  explicit Lookup(const DataView& view);
  /// The first module named `name`.
  std::optional<std::size_t> module(std::string_view name) const;
  std::optional<TypeId> type(std::size_t module, std::string_view name) const;
  std::optional<ValueId> value(std::size_t module, std::string_view name) const;

 private:
  using Names = std::map<std::string, std::size_t, std::less<>>;
  /// The module that `module` imports `name` from, if it imports it from a known one.
  std::optional<std::size_t> imported_from(std::size_t module, std::string_view name) const;

  Names modules_;
  std::vector<Names> types_, values_, imports_;  // imports_: name -> index of the module
};

/// What a type of this kind maps to in BIP, Unknown for a reference.
BipData bip_of_kind(TypeKind kind);

}  // namespace smcbip::taste2bip::asn1::detail
