// Lookups in a data view: modules, and type and value names as a module sees them (IMPORTS).
#include "taste2bip/asn1/data_view.h"

#include <algorithm>

#include "taste2bip/asn1/lookup.h"

namespace smcbip::taste2bip::asn1 {
namespace detail {

// Chains of IMPORTS longer than this are taken to loop (M imports x from N, N from M).
constexpr int kMaxImportHops = 32;

std::optional<std::size_t> module_index(const DataView& view, std::string_view name) {
  for (std::size_t i = 0; i < view.modules.size(); ++i) {
    if (view.modules[i].name == name) return i;
  }
  return std::nullopt;
}

namespace {

template <typename Own>
auto follow_imports(const DataView& view, std::size_t module, std::string_view name, Own own)
    -> decltype(own(module, name)) {
  for (int hops = 0; hops < kMaxImportHops; ++hops) {
    if (auto found = own(module, name)) return found;
    std::optional<std::size_t> from;
    for (const Import& import : view.modules[module].imports) {
      if (std::find(import.names.begin(), import.names.end(), name) != import.names.end()) {
        from = module_index(view, import.module);
        break;
      }
    }
    if (!from) return {};
    module = *from;
  }
  return {};
}

}  // namespace

std::optional<TypeId> find_type_from(const DataView& view, std::size_t module,
                                     std::string_view name) {
  return follow_imports(view, module, name,
                        [&](std::size_t m, std::string_view n) -> std::optional<TypeId> {
                          const auto& types = view.modules[m].types;
                          for (std::size_t i = 0; i < types.size(); ++i) {
                            if (types[i].name == n) return TypeId{m, i};
                          }
                          return std::nullopt;
                        });
}

std::optional<ValueId> find_value_from(const DataView& view, std::size_t module,
                                       std::string_view name) {
  return follow_imports(view, module, name,
                        [&](std::size_t m, std::string_view n) -> std::optional<ValueId> {
                          const auto& values = view.modules[m].values;
                          for (std::size_t i = 0; i < values.size(); ++i) {
                            if (values[i].name == n) return ValueId{m, i};
                          }
                          return std::nullopt;
                        });
}

}  // namespace detail

const Module* DataView::module(std::string_view name) const {
  auto index = detail::module_index(*this, name);
  return index ? &modules[*index] : nullptr;
}

std::optional<TypeId> DataView::find_type(std::string_view name, std::string_view in_module) const {
  if (!in_module.empty()) {
    auto index = detail::module_index(*this, in_module);
    if (!index) return std::nullopt;
    return detail::find_type_from(*this, *index, name);
  }
  for (std::size_t m = 0; m < modules.size(); ++m) {
    for (std::size_t i = 0; i < modules[m].types.size(); ++i) {
      if (modules[m].types[i].name == name) return TypeId{m, i};
    }
  }
  return std::nullopt;
}

const TypeAssignment* DataView::type(TypeId id) const {
  if (id.module >= modules.size() || id.index >= modules[id.module].types.size()) return nullptr;
  return &modules[id.module].types[id.index];
}

const ValueAssignment* DataView::find_value(std::string_view name,
                                            std::string_view in_module) const {
  std::optional<detail::ValueId> id;
  if (!in_module.empty()) {
    if (auto index = detail::module_index(*this, in_module)) {
      id = detail::find_value_from(*this, *index, name);
    }
  } else {
    for (std::size_t m = 0; m < modules.size() && !id; ++m) {
      id = detail::find_value_from(*this, m, name);
    }
  }
  return id ? &modules[id->module].values[id->index] : nullptr;
}

BipData bip_data(const DataView& view, const Type& type) {
  const Type* t = &type;
  // A chain of references is at most as long as the number of assignments (or it loops).
  std::size_t hops = 0;
  for (const Module& m : view.modules) hops += m.types.size();
  for (std::size_t i = 0; i <= hops; ++i) {
    switch (t->kind) {
      case TypeKind::Integer:
      case TypeKind::Enumerated:
        return BipData::Int;
      case TypeKind::Boolean:
        return BipData::Bool;
      case TypeKind::Real:
        return BipData::Float;
      case TypeKind::Reference: {
        const TypeAssignment* target = t->target ? view.type(*t->target) : nullptr;
        if (target == nullptr) return BipData::Unknown;
        t = &target->type;
        break;
      }
      default:
        return BipData::Extern;
    }
  }
  return BipData::Unknown;
}

}  // namespace smcbip::taste2bip::asn1
