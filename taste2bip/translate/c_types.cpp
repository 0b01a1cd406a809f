#include "taste2bip/translate/c_types.h"

#include <cctype>
#include <map>
#include <set>
#include <utility>

namespace smcbip::taste2bip {

namespace {

using asn1::Type;
using asn1::TypeKind;

std::string joined_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line;
  return text;
}

/// How many CHOICE types of the view use each alternative name: a name used by two gets its
/// type's name before its `_PRESENT`, as C enumerators share one scope.
struct NameUses {
  std::map<std::string, int> alternatives;

  void count(const Type& t) {
    if (t.kind == TypeKind::Choice) {
      for (const asn1::Component& c : t.components) ++alternatives[c_identifier(c.name)];
    }
    for (const asn1::Component& c : t.components) count(c.type);
    if (t.element) count(*t.element);
  }
};

class HeaderWriter {
 public:
  explicit HeaderWriter(const asn1::DataView& view) : view_(view) {
    for (const asn1::Module& m : view.modules) {
      for (const asn1::TypeAssignment& a : m.types) uses_.count(a.type);
    }
  }

  std::string write() {
    for (std::size_t m = 0; m < view_.modules.size(); ++m) {
      for (std::size_t i = 0; i < view_.modules[m].types.size(); ++i) assignment({m, i});
    }
    return joined_lines(out_);
  }

 private:
  /// Writes the assignment `id` once, what it uses first; its C name, or nullopt when it has
  /// no C form.
  std::optional<std::string> assignment(asn1::TypeId id) {
    const asn1::TypeAssignment& a = *view_.type(id);
    const std::string name = c_type_name(a.name);
    const auto key = std::make_pair(id.module, id.index);
    if (const auto it = written_.find(key); it != written_.end()) return it->second;
    written_[key] = std::nullopt;  // a type defined through itself has no C form
    if (!a.parameters.empty()) {
      out_.push_back("/* " + name + ": a parameterized type, written where it is used */\n");
      return std::nullopt;
    }
    if (!emitted_names_.insert(name).second) return written_[key] = name;
    std::optional<std::string> made = define(name, a.type);
    if (!made) {
      out_.push_back("/* " + name + ": no C form (no SIZE bound, or a type without one) */\n");
    }
    return written_[key] = made;
  }

  /// The C type of a field or element of type `t`; an anonymous structured type is defined
  /// first as `anonymous`.
  std::optional<std::string> field_type(const Type& t, const std::string& anonymous,
                                        const Type* instance = nullptr) {
    switch (t.kind) {
      case TypeKind::Reference:
        if (!t.target) return std::nullopt;
        if (!t.arguments.empty()) return define(anonymous, t);
        return assignment(*t.target);
      case TypeKind::Integer:
        return integer_type(t);
      case TypeKind::Real:
        return std::string("asn1Real");
      case TypeKind::Boolean:
        return std::string("flag");
      case TypeKind::Null:
        return std::string("NullType");
      default:
        return define(anonymous, t, instance);
    }
  }

  std::string integer_type(const Type& t) const {
    if (t.range.ranges.empty()) return "asn1SccSint";
    for (const asn1::Range& r : t.range.ranges) {
      const auto low = asn1::bound_integer(view_, r.lower);
      if (!low || *low < 0) return "asn1SccSint";
    }
    return "asn1SccUint";
  }

  /// The size bound of `t` (SIZE(n) or SIZE(low..high)), following `instance`'s arguments.
  std::optional<std::pair<std::int64_t, std::int64_t>> size(const Type& t,
                                                            const Type* instance) const {
    if (t.size.ranges.size() != 1) return std::nullopt;
    const auto low = asn1::bound_integer(view_, t.size.ranges[0].lower, instance);
    const auto high = asn1::bound_integer(view_, t.size.ranges[0].upper, instance);
    if (!low || !high || *high < *low || *high < 0) return std::nullopt;
    return std::make_pair(*low, *high);
  }

  /// Defines `name` as `t` (through a parameterized reference, its instance); its name or
  /// nullopt.
  std::optional<std::string> define(const std::string& name, const Type& t,
                                    const Type* instance = nullptr) {
    if (t.kind == TypeKind::Reference && !t.arguments.empty()) {
      const asn1::TypeAssignment* target = t.target ? view_.type(*t.target) : nullptr;
      if (target == nullptr) return std::nullopt;
      return define(name, target->type, &t);
    }
    std::optional<std::string> body = definition_text(name, t, instance);
    if (!body) return std::nullopt;
    out_.push_back(*body);
    return name;
  }

  std::optional<std::string> definition_text(const std::string& name, const Type& t,
                                             const Type* instance) {
    switch (t.kind) {
      case TypeKind::Enumerated:
        return enumerated(name, t);
      case TypeKind::Sequence:
        return sequence(name, t, instance);
      case TypeKind::Choice:
        return choice(name, t, instance);
      case TypeKind::SequenceOf:
        return sequence_of(name, t, instance);
      case TypeKind::OctetString:
      case TypeKind::BitString:
        return octets(name, t, instance);
      case TypeKind::CharacterString: {
        const auto bounds = size(t, instance);
        if (!bounds) return std::nullopt;
        return "typedef char " + name + "[" + std::to_string(bounds->second + 1) + "];\n\n";
      }
      default: {
        const std::optional<std::string> base = field_type(t, name + "_base");
        if (!base) return std::nullopt;
        return "typedef " + *base + " " + name + ";\n\n";
      }
    }
  }

  std::string enumerated(const std::string& name, const Type& t) {
    std::string text = "typedef enum {\n";
    for (std::size_t i = 0; i < t.enumerants.size(); ++i) {
      const std::string e = c_identifier(t.enumerants[i].name);
      const std::string spelled = name + "_" + e;
      text += "    " + spelled + " = " + std::to_string(t.enumerants[i].value) +
              (i + 1 < t.enumerants.size() ? ",\n" : "\n");
    }
    return text + "} " + name + ";\n\n";
  }

  /// The fields of a SEQUENCE or the alternatives of a CHOICE, each on a line of its own.
  std::optional<std::string> members(const std::string& name, const Type& t, const Type* instance,
                                     const std::string& indent) {
    std::string text;
    for (const asn1::Component& c : t.components) {
      const std::string field = c_identifier(c.name);
      std::optional<std::string> type = field_type(c.type, name + "_" + field, instance);
      if (!type) return std::nullopt;
      text += indent + *type + " " + field + ";\n";
    }
    return text;
  }

  std::optional<std::string> sequence(const std::string& name, const Type& t,
                                      const Type* instance) {
    std::optional<std::string> fields = members(name, t, instance, "    ");
    if (!fields) return std::nullopt;
    std::string exist;
    for (const asn1::Component& c : t.components) {
      if (c.optional) exist += "        unsigned int " + c_identifier(c.name) + ":1;\n";
    }
    if (!exist.empty()) *fields += "    struct {\n" + exist + "    } exist;\n";
    if (fields->empty()) *fields = "    char unused;  /* C has no empty struct */\n";
    return "typedef struct {\n" + *fields + "} " + name + ";\n\n";
  }

  std::optional<std::string> choice(const std::string& name, const Type& t, const Type* instance) {
    std::optional<std::string> alternatives = members(name, t, instance, "        ");
    if (!alternatives) return std::nullopt;
    std::string kinds = "    " + name + "_NONE";
    for (const asn1::Component& c : t.components) {
      const std::string alt = c_identifier(c.name);
      kinds += ",\n    " + (uses_.alternatives[alt] > 1 ? name + "_" + alt : alt) + "_PRESENT";
    }
    std::string text = "typedef enum {\n" + kinds + "\n} " + name + "_selection;\n\n";
    text += "typedef struct {\n    " + name + "_selection kind;\n    union {\n" + *alternatives;
    if (t.components.empty()) text += "        char unused;\n";
    return text + "    } u;\n} " + name + ";\n\n";
  }

  std::optional<std::string> sequence_of(const std::string& name, const Type& t,
                                         const Type* instance) {
    const auto bounds = size(t, instance);
    if (!bounds || t.element == nullptr) return std::nullopt;
    const std::optional<std::string> element = field_type(*t.element, name + "_elm", instance);
    if (!element) return std::nullopt;
    return array_struct(name, *element, *bounds, bounds->second);
  }

  std::optional<std::string> octets(const std::string& name, const Type& t, const Type* instance) {
    const auto bounds = size(t, instance);
    if (!bounds) return std::nullopt;
    const std::int64_t bytes =
        t.kind == TypeKind::BitString ? (bounds->second + 7) / 8 : bounds->second;
    return array_struct(name, "byte", *bounds, bytes);
  }

  static std::string array_struct(const std::string& name, const std::string& element,
                                  std::pair<std::int64_t, std::int64_t> bounds,
                                  std::int64_t capacity) {
    std::string text = "typedef struct {\n";
    if (bounds.first != bounds.second) text += "    int nCount;\n";
    text +=
        "    " + element + " arr[" + std::to_string(std::max<std::int64_t>(capacity, 1)) + "];\n";
    return text + "} " + name + ";\n\n";
  }

  const asn1::DataView& view_;
  NameUses uses_;
  std::map<std::pair<std::size_t, std::size_t>, std::optional<std::string>> written_;
  std::set<std::string> emitted_names_;
  std::vector<std::string> out_;
};

const std::string kHeaderTop =
    "/* The data view's types in C, as TASTE's C bodies use them. Written by taste2bip. */\n"
    "#ifndef TASTE2BIP_DATAVIEW_UNIQ_H\n#define TASTE2BIP_DATAVIEW_UNIQ_H\n\n"
    "#include <stdbool.h>\n#include <stddef.h>\n#include <stdint.h>\n#include <inttypes.h>\n\n"
    "#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n"
    "typedef int64_t asn1SccSint;\ntypedef uint64_t asn1SccUint;\ntypedef double asn1Real;\n"
    "typedef bool flag;\ntypedef unsigned char byte;\ntypedef char NullType;\n\n";

const std::string kHeaderBottom = "#ifdef __cplusplus\n}\n#endif\n\n#endif\n";

}  // namespace

std::string c_identifier(std::string_view name) {
  std::string out(name);
  for (char& c : out) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  }
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out.insert(0, "_");
  return out;
}

std::string c_type_name(std::string_view assignment_name) {
  return "asn1Scc" + c_identifier(assignment_name);
}

std::string c_dataview_header(const asn1::DataView& view) {
  return kHeaderTop + HeaderWriter(view).write() + kHeaderBottom;
}

std::optional<std::string> c_access(const asn1::DataView& view, const Type& type,
                                    const Leaf& leaf) {
  const bool bookkeeping = leaf.asn1_type == nullptr;
  const auto ends_with = [&](std::string_view tail) {
    return leaf.suffix.size() >= tail.size() &&
           leaf.suffix.compare(leaf.suffix.size() - tail.size(), tail.size(), tail) == 0;
  };
  std::string expr;
  const Type* t = definition(view, type);
  for (std::size_t i = 0; t != nullptr && i < leaf.path.size(); ++i) {
    const std::string& step = leaf.path[i];
    const bool last = i + 1 == leaf.path.size();
    if (t->kind == TypeKind::SequenceOf) {
      expr += ".arr[" + step + "]";
      t = t->element ? definition(view, *t->element) : nullptr;
      continue;
    }
    if (t->kind != TypeKind::Sequence && t->kind != TypeKind::Choice) return std::nullopt;
    const asn1::Component* field = nullptr;
    for (const asn1::Component& c : t->components) {
      if (c.name == step) field = &c;
    }
    if (field == nullptr) return std::nullopt;
    const Type* inner = definition(view, field->type);
    const bool exist_bit = bookkeeping && last && field->optional && ends_with("_exist") &&
                           !(inner && inner->kind == TypeKind::Choice && ends_with("present")) &&
                           !(inner && inner->kind == TypeKind::SequenceOf && ends_with("length"));
    if (exist_bit) return expr + ".exist." + c_identifier(step);
    expr += (t->kind == TypeKind::Choice ? ".u." : ".") + c_identifier(step);
    t = inner;
  }
  if (t == nullptr) return std::nullopt;
  if (!bookkeeping) return expr;
  if (t->kind == TypeKind::Choice && ends_with("present")) return expr + ".kind";
  if (t->kind == TypeKind::SequenceOf && ends_with("length")) return expr + ".nCount";
  return std::nullopt;
}

}  // namespace smcbip::taste2bip
