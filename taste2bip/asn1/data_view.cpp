// Lookups in a data view: modules, and type and value names as a module sees them (IMPORTS).
#include "taste2bip/asn1/data_view.h"

#include "taste2bip/asn1/lookup.h"

namespace smcbip::taste2bip::asn1 {
namespace detail {

// Chains of IMPORTS longer than this are taken to loop (M imports x from N, N from M).
constexpr int kMaxImportHops = 32;

Lookup::Lookup(const DataView& view) {
  for (std::size_t m = 0; m < view.modules.size(); ++m) {
    const Module& module = view.modules[m];
    modules_.emplace(module.name, m);
    Names& types = types_.emplace_back();
    for (std::size_t i = 0; i < module.types.size(); ++i) types.emplace(module.types[i].name, i);
    Names& values = values_.emplace_back();
    for (std::size_t i = 0; i < module.values.size(); ++i) {
      values.emplace(module.values[i].name, i);
    }
    imports_.emplace_back();
  }
  for (std::size_t m = 0; m < view.modules.size(); ++m) {
    for (const Import& import : view.modules[m].imports) {
      auto from = module(import.module);
      if (!from) continue;
      for (const std::string& name : import.names) imports_[m].emplace(name, *from);
    }
  }
}

std::optional<std::size_t> Lookup::module(std::string_view name) const {
  auto it = modules_.find(name);
  if (it == modules_.end()) return std::nullopt;
  return it->second;
}

std::optional<std::size_t> Lookup::imported_from(std::size_t module, std::string_view name) const {
  auto it = imports_[module].find(name);
  if (it == imports_[module].end()) return std::nullopt;
  return it->second;
}

std::optional<TypeId> Lookup::type(std::size_t module, std::string_view name) const {
  for (int hops = 0; hops < kMaxImportHops; ++hops) {
    auto it = types_[module].find(name);
    if (it != types_[module].end()) return TypeId{module, it->second};
    auto from = imported_from(module, name);
    if (!from) return std::nullopt;
    module = *from;
  }
  return std::nullopt;
}

std::optional<ValueId> Lookup::value(std::size_t module, std::string_view name) const {
  for (int hops = 0; hops < kMaxImportHops; ++hops) {
    auto it = values_[module].find(name);
    if (it != values_[module].end()) return ValueId{module, it->second};
    auto from = imported_from(module, name);
    if (!from) return std::nullopt;
    module = *from;
  }
  return std::nullopt;
}

BipData bip_of_kind(TypeKind kind) {
  switch (kind) {
    case TypeKind::Integer:
    case TypeKind::Enumerated:
      return BipData::Int;
    case TypeKind::Boolean:
      return BipData::Bool;
    case TypeKind::Real:
      return BipData::Float;
    case TypeKind::Reference:
      return BipData::Unknown;
    default:
      return BipData::Extern;
  }
}

}  // namespace detail

const Module* DataView::module(std::string_view name) const {
  for (const Module& m : modules) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

std::optional<TypeId> DataView::find_type(std::string_view name, std::string_view in_module) const {
  if (!in_module.empty()) {
    detail::Lookup lookup(*this);
    auto index = lookup.module(in_module);
    if (!index) return std::nullopt;
    return lookup.type(*index, name);
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
  detail::Lookup lookup(*this);
  std::optional<detail::ValueId> id;
  if (!in_module.empty()) {
    if (auto index = lookup.module(in_module)) id = lookup.value(*index, name);
  } else {
    for (std::size_t m = 0; m < modules.size() && !id; ++m) id = lookup.value(m, name);
  }
  return id ? &modules[id->module].values[id->index] : nullptr;
}

BipData bip_data(const DataView& view, const Type& type) {
  const Type* t = &type;
  // A chain of references is at most as long as the number of assignments (or it loops).
  std::size_t hops = 0;
  for (const Module& m : view.modules) hops += m.types.size();
  for (std::size_t i = 0; i <= hops && t->kind == TypeKind::Reference; ++i) {
    const TypeAssignment* target = t->target ? view.type(*t->target) : nullptr;
    if (target == nullptr) return BipData::Unknown;
    t = &target->type;
  }
  return detail::bip_of_kind(t->kind);
}

std::optional<std::int64_t> bound_integer(const DataView& view, const Value& bound,
                                          const Type* instance) {
  switch (bound.kind) {
    case Value::Kind::Integer:
      return bound.integer;
    case Value::Kind::Name:
      break;
    default:
      return std::nullopt;
  }
  if (bound.resolved && !bound.is_parameter) {
    return bound.is_integer ? std::optional<std::int64_t>(bound.integer) : std::nullopt;
  }
  if (!bound.is_parameter || instance == nullptr || !instance->target) return std::nullopt;
  const TypeAssignment* generic = view.type(*instance->target);
  if (generic == nullptr) return std::nullopt;
  for (std::size_t i = 0; i < generic->parameters.size() && i < instance->arguments.size(); ++i) {
    if (generic->parameters[i].name == bound.text) {
      const Value& argument = instance->arguments[i];
      if (argument.is_parameter) return std::nullopt;  // an argument of an enclosing instance
      return bound_integer(view, argument);
    }
  }
  return std::nullopt;
}

}  // namespace smcbip::taste2bip::asn1
