// SDL variables as BIP data: one data per leaf of the variable's ASN.1 type, and the parts of a
// value (fields, elements) as the leaves under them.
#include <algorithm>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

/// SDL's own scalar types, used where the data view has no type of that name.
std::optional<std::string> builtin_scalar(const std::string& type) {
  const std::string f = folded(type);
  if (f == "integer" || f == "natural") return "int";
  if (f == "boolean") return "bool";
  if (f == "real") return "float";
  if (f == "charstring") return "string";
  return std::nullopt;
}

/// `suffix` with the leading `part` (and its '_') removed; nullopt when it does not start so.
std::optional<std::string> strip(const std::string& suffix, const std::string& part) {
  if (suffix == part) return std::string();
  if (suffix.size() > part.size() && suffix.compare(0, part.size(), part) == 0 &&
      suffix[part.size()] == '_') {
    return suffix.substr(part.size() + 1);
  }
  return std::nullopt;
}

/// The leaves of `ref` under path element `part` (BIP spelling `bip`), relative to it.
std::vector<Leaf> leaves_under(const Ref& ref, const std::string& part, const std::string& bip,
                               bool optional) {
  std::vector<Leaf> out;
  for (const Leaf& leaf : ref.leaves) {
    if (leaf.path.empty() || leaf.path[0] != part) continue;
    std::optional<std::string> rest = strip(leaf.suffix, bip);
    if (!rest) continue;
    // The `_exist` leaf of an OPTIONAL field belongs to the record, not to the field.
    if (optional && leaf.asn1_type == nullptr && leaf.path.size() == 1 && *rest == "exist") {
      continue;
    }
    Leaf inner = leaf;
    inner.suffix = *rest;
    inner.path.erase(inner.path.begin());
    out.push_back(std::move(inner));
  }
  return out;
}

}  // namespace

std::optional<std::vector<Leaf>> Translator::leaves_of_type(const std::string& type,
                                                            const bipc::Location& at,
                                                            const asn1::Type** definition_out) {
  *definition_out = nullptr;
  if (const auto id = find_type_spelled(data_, type)) {
    const asn1::TypeAssignment* assignment = data_.type(*id);
    *definition_out = definition(data_, assignment->type);
    return taste2bip::leaves_of(data_, type, at, diags_);
  }
  if (auto scalar = builtin_scalar(type)) return std::vector<Leaf>{Leaf{"", *scalar, nullptr, {}}};
  return taste2bip::leaves_of(data_, type, at, diags_);
}

std::string Translator::default_value(const Leaf& leaf) {
  if (leaf.type == "int") {
    if (leaf.asn1_type != nullptr && !leaf.asn1_type->enumerants.empty()) {
      return std::to_string(leaf.asn1_type->enumerants.front().value);
    }
    const bool present = leaf.asn1_type == nullptr && leaf.suffix.size() >= 7 &&
                         leaf.suffix.compare(leaf.suffix.size() - 7, 7, "present") == 0;
    return present ? "1" : "0";
  }
  if (leaf.type == "bool") return "false";
  if (leaf.type == "float") return "0.0";
  if (leaf.type == "string") return "\"\"";
  return {};
}

void Translator::declare_variable(const std::string& data, const std::vector<Leaf>& leaves) {
  for (const Leaf& leaf : leaves) {
    const std::string name = leaf_name(data, leaf);
    reserve(name);
    const std::string init = default_value(leaf);
    data_text_ += "    data " + leaf.type + " " + name + (init.empty() ? "" : " = " + init) + "\n";
  }
  for (const std::string& t : extern_types_in(leaves)) {
    if (std::find(extern_types_.begin(), extern_types_.end(), t) == extern_types_.end()) {
      extern_types_.push_back(t);
    }
  }
}

std::optional<Ref> Translator::declare_sdl_variable(const sdl::Variable& v,
                                                    const std::string& prefix) {
  const asn1::Type* type = nullptr;
  std::optional<std::vector<Leaf>> leaves = leaves_of_type(v.type, v.at, &type);
  if (!leaves) return std::nullopt;
  Ref ref{bip_identifier(prefix + v.name), std::move(*leaves), type};
  for (const Leaf& leaf : ref.leaves) {
    if (used_.count(leaf_name(ref.data, leaf)) > 0) {
      error(v.at, "variable '" + v.name + "' becomes the BIP data '" + leaf_name(ref.data, leaf) +
                      "', a name already used in the atom");
      return std::nullopt;
    }
  }
  declare_variable(ref.data, ref.leaves);
  return ref;
}

std::optional<Ref> Translator::field(const Ref& ref, const std::string& name,
                                     const bipc::Location& at) {
  const bool record = ref.type != nullptr && (ref.type->kind == asn1::TypeKind::Sequence ||
                                              ref.type->kind == asn1::TypeKind::Choice);
  if (record) {
    for (const asn1::Component& c : ref.type->components) {
      if (folded(c.name) != folded(name)) continue;
      const std::string bip = bip_identifier(c.name);
      return Ref{leaf_name(ref.data, Leaf{bip, "", nullptr, {}}),
                 leaves_under(ref, c.name, bip, c.optional), definition(data_, c.type)};
    }
  }
  error(at, "'" + name + "' is not a field of '" + ref.data + "'");
  return std::nullopt;
}

std::optional<Ref> Translator::element(const Ref& ref, std::int64_t index,
                                       const bipc::Location& at) {
  const std::string part = std::to_string(index);
  std::vector<Leaf> leaves = leaves_under(ref, part, part, false);
  if (ref.type == nullptr || ref.type->kind != asn1::TypeKind::SequenceOf || leaves.empty()) {
    error(at, "element " + part + " of '" + ref.data +
                  "' is not translated (not a SEQUENCE OF spread over data, or out of "
                  "its bounds)");
    return std::nullopt;
  }
  const asn1::Type* type = ref.type->element ? definition(data_, *ref.type->element) : nullptr;
  return Ref{leaf_name(ref.data, Leaf{part, "", nullptr, {}}), std::move(leaves), type};
}

Ref Translator::interface_ref(const SignalInterface& i, const SignalParameter& p) const {
  const asn1::Type* type = nullptr;
  if (const auto id = find_type_spelled(data_, p.asn1_type)) {
    type = definition(data_, data_.type(*id)->type);
  }
  return Ref{i.name + "_" + p.name, p.leaves, type};
}

}  // namespace smcbip::taste2bip::detail
