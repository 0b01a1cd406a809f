#include "taste2bip/translate/bip_types.h"

#include <algorithm>
#include <cctype>

#include "taste2bip/names.h"

namespace smcbip::taste2bip {

namespace {

/// A field's name inside a leaf's suffix: always after a variable's name, so only its
/// characters need mapping (a keyword such as `data` is fine there).
std::string field_identifier(const std::string& name) {
  std::string out = name;
  for (char& c : out) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  }
  return out;
}

std::string joined(const std::string& prefix, const std::string& name) {
  if (prefix.empty()) return name;
  if (name.empty()) return prefix;
  return prefix + "_" + name;
}

/// Walks a type and appends its leaves; `named` is the name of the nearest assignment (with the
/// path inside it) for an extern piece, `instance` the reference that instantiated a
/// parameterized assignment (for its SIZE bounds).
class LeafCollector {
 public:
  explicit LeafCollector(const asn1::DataView& view) : view_(view) {}

  std::vector<Leaf> take() { return std::move(leaves_); }

  void add(const asn1::Type& type, const std::string& suffix, std::vector<std::string> path,
           const std::string& named, const asn1::Type* instance) {
    const asn1::Type* t = &type;
    std::string name = named;
    // Follow references, remembering the last assignment's name and instantiation.
    for (std::size_t hops = 0; t->kind == asn1::TypeKind::Reference; ++hops) {
      const asn1::TypeAssignment* target = t->target ? view_.type(*t->target) : nullptr;
      if (target == nullptr || hops > kMaxHops) return;
      if (!t->arguments.empty()) instance = t;
      name = target->name;
      t = &target->type;
    }
    switch (t->kind) {
      case asn1::TypeKind::Integer:
      case asn1::TypeKind::Enumerated:
        return scalar("int", *t, suffix, std::move(path));
      case asn1::TypeKind::Boolean:
        return scalar("bool", *t, suffix, std::move(path));
      case asn1::TypeKind::Real:
        return scalar("float", *t, suffix, std::move(path));
      case asn1::TypeKind::CharacterString:
        return scalar("string", *t, suffix, std::move(path));
      case asn1::TypeKind::Null:
        return;
      case asn1::TypeKind::Sequence:
        return sequence(*t, suffix, path, name, instance);
      case asn1::TypeKind::Choice:
        return choice(*t, suffix, path, name, instance);
      case asn1::TypeKind::SequenceOf:
        return sequence_of(*t, suffix, path, name, instance);
      default:
        return scalar(extern_type_name(name), *t, suffix, std::move(path));
    }
  }

 private:
  static constexpr std::size_t kMaxHops = 256;

  void scalar(std::string type, const asn1::Type& t, const std::string& suffix,
              std::vector<std::string> path) {
    leaves_.push_back(Leaf{suffix, std::move(type), &t, std::move(path)});
  }

  void bookkeeping(const std::string& suffix, const char* type, std::vector<std::string> path) {
    leaves_.push_back(Leaf{suffix, type, nullptr, std::move(path)});
  }

  void sequence(const asn1::Type& t, const std::string& suffix,
                const std::vector<std::string>& path, const std::string& name,
                const asn1::Type* instance) {
    for (const asn1::Component& c : t.components) {
      std::vector<std::string> inner = path;
      inner.push_back(c.name);
      const std::string field = joined(suffix, field_identifier(c.name));
      if (c.optional) bookkeeping(field + "_exist", "bool", inner);
      add(c.type, field, inner, name + "_" + field_identifier(c.name), instance);
    }
  }

  void choice(const asn1::Type& t, const std::string& suffix, const std::vector<std::string>& path,
              const std::string& name, const asn1::Type* instance) {
    bookkeeping(joined(suffix, "present"), "int", path);
    sequence(t, suffix, path, name, instance);
  }

  void sequence_of(const asn1::Type& t, const std::string& suffix,
                   const std::vector<std::string>& path, const std::string& name,
                   const asn1::Type* instance) {
    std::optional<std::int64_t> low, high;
    if (t.size.ranges.size() == 1) {
      low = asn1::bound_integer(view_, t.size.ranges[0].lower, instance);
      high = asn1::bound_integer(view_, t.size.ranges[0].upper, instance);
    }
    if (!low || !high || *high > kMaxElements || *high < 0 || t.element == nullptr) {
      return scalar(extern_type_name(name), t, suffix, path);
    }
    if (*low != *high) bookkeeping(joined(suffix, "length"), "int", path);
    for (std::int64_t i = 0; i < *high; ++i) {
      std::vector<std::string> inner = path;
      inner.push_back(std::to_string(i));
      add(*t.element, joined(suffix, std::to_string(i)), inner, name + "_elem", instance);
    }
  }

  const asn1::DataView& view_;
  std::vector<Leaf> leaves_;
};

}  // namespace

std::string leaf_name(std::string_view name, const Leaf& leaf) {
  return joined(std::string(name), leaf.suffix);
}

std::optional<asn1::TypeId> find_type_spelled(const asn1::DataView& view, std::string_view name) {
  const std::string wanted = folded_name(name);
  std::optional<asn1::TypeId> found;
  for (std::size_t m = 0; m < view.modules.size(); ++m) {
    const auto& types = view.modules[m].types;
    for (std::size_t i = 0; i < types.size(); ++i) {
      if (folded_name(types[i].name) != wanted) continue;
      if (found) return std::nullopt;
      found = asn1::TypeId{m, i};
    }
  }
  return found;
}

const asn1::Type* definition(const asn1::DataView& view, const asn1::Type& type) {
  const asn1::Type* t = &type;
  std::size_t hops = 0;
  for (const asn1::Module& m : view.modules) hops += m.types.size();
  for (std::size_t i = 0; i <= hops && t->kind == asn1::TypeKind::Reference; ++i) {
    const asn1::TypeAssignment* target = t->target ? view.type(*t->target) : nullptr;
    if (target == nullptr) return nullptr;
    t = &target->type;
  }
  return t->kind == asn1::TypeKind::Reference ? nullptr : t;
}

std::vector<Leaf> leaves_of(const asn1::DataView& view, const asn1::Type& type) {
  LeafCollector collector(view);
  collector.add(type, "", {}, "", nullptr);
  return collector.take();
}

std::optional<std::vector<Leaf>> leaves_of(const asn1::DataView& view, std::string_view name,
                                           const bipc::Location& at, bipc::Diagnostics& diags) {
  const auto id = find_type_spelled(view, name);
  const asn1::TypeAssignment* assignment = id ? view.type(*id) : nullptr;
  if (assignment == nullptr) {
    diags.error(at, "type '" + std::string(name) +
                        "' is not in the data view (or names more than one type there)");
    return std::nullopt;
  }
  LeafCollector collector(view);
  collector.add(assignment->type, "", {}, assignment->name, nullptr);
  return collector.take();
}

std::string extern_type_name(std::string_view assignment_name) {
  return "asn1Scc" + bip_identifier(assignment_name);
}

std::vector<std::string> extern_types_in(const std::vector<Leaf>& leaves) {
  std::vector<std::string> out;
  for (const Leaf& leaf : leaves) {
    const bool scalar =
        leaf.type == "int" || leaf.type == "bool" || leaf.type == "float" || leaf.type == "string";
    if (!scalar && std::find(out.begin(), out.end(), leaf.type) == out.end()) {
      out.push_back(leaf.type);
    }
  }
  return out;
}

std::string port_type_name(const std::vector<std::string>& types) {
  if (types.empty()) return "Port";
  std::string out = "Port_";
  for (const std::string& t : types) {
    if (t == "int" || t == "bool" || t == "float" || t == "string") {
      out += t[0];
    } else {
      out += "x" + t + "_";
    }
  }
  return out;
}

}  // namespace smcbip::taste2bip
