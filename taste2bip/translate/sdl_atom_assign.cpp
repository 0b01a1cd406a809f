// Assignments leaf by leaf: a scalar expression, a whole record copied, an ASN.1 SEQUENCE,
// SEQUENCE OF or CHOICE literal spread over the target's leaves, and elements at a variable
// index as a chain of ifs.
#include <set>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

bool is_scalar(const Ref& r) { return r.leaves.size() == 1 && r.leaves[0].suffix.empty(); }

const Leaf* bookkeeping(const Ref& r, const std::string& suffix) {
  for (const Leaf& l : r.leaves) {
    if (l.suffix == suffix && l.asn1_type == nullptr) return &l;
  }
  return nullptr;
}

bool assignable(const std::string& to, const std::string& from) {
  return to == from || (to == "float" && from == "int");
}

std::size_t element_count(const Ref& r) {
  std::set<std::string> elements;
  for (const Leaf& l : r.leaves) {
    if (!l.path.empty()) elements.insert(l.path[0]);
  }
  return elements.size();
}

}  // namespace

bool Translator::assign(const Ref& target, const sdl::Expr& value, std::vector<std::string>& out) {
  if (value.kind == sdl::Expr::Kind::Conditional) return assign_conditional(target, value, out);
  if (is_scalar(target)) {
    std::optional<Scalar> s = scalar(value, target.leaves[0].asn1_type);
    if (!s) return false;
    if (!s->kind.empty() && !assignable(target.leaves[0].type, s->kind)) {
      error(value.at, "a value of BIP type " + s->kind + " assigned to '" + target.data +
                          "' of BIP type " + target.leaves[0].type);
      return false;
    }
    out.push_back(target.data + " = " + s->text + ";");
    return true;
  }
  if (value.kind == sdl::Expr::Kind::Sequence) return assign_sequence(target, value, out);
  if (value.kind == sdl::Expr::Kind::Choice) return assign_choice(target, value, out);
  std::optional<Ref> source = reference(value);
  return source && assign_ref(target, *source, value.at, out);
}

bool Translator::assign_conditional(const Ref& target, const sdl::Expr& value,
                                    std::vector<std::string>& out) {
  std::optional<Scalar> condition = scalar(value.operands[0]);
  std::vector<std::string> then, otherwise;
  if (!condition || !assign(target, value.operands[1], then) ||
      !assign(target, value.operands[2], otherwise)) {
    return false;
  }
  std::string text = "if (" + condition->text + ") then";
  for (const std::string& s : then) text += " " + s;
  text += " else";
  for (const std::string& s : otherwise) text += " " + s;
  out.push_back(text + " fi");
  return true;
}

bool Translator::assign_ref(const Ref& target, const Ref& source, const bipc::Location& at,
                            std::vector<std::string>& out) {
  std::vector<std::string> statements;
  for (const Leaf& t : target.leaves) {
    const Leaf* match = nullptr;
    for (const Leaf& s : source.leaves) match = s.suffix == t.suffix ? &s : match;
    if (match == nullptr || !assignable(t.type, match->type) ||
        target.leaves.size() != source.leaves.size()) {
      error(at, "'" + source.data + "' does not have the structure of '" + target.data + "'");
      return false;
    }
    statements.push_back(leaf_name(target.data, t) + " = " + leaf_name(source.data, *match) + ";");
  }
  out.insert(out.end(), statements.begin(), statements.end());
  return true;
}

bool Translator::assign_sequence(const Ref& target, const sdl::Expr& value,
                                 std::vector<std::string>& out) {
  if (target.type != nullptr && target.type->kind == asn1::TypeKind::SequenceOf) {
    const std::size_t n = value.operands.size();
    if (const Leaf* length = bookkeeping(target, "length")) {
      out.push_back(leaf_name(target.data, *length) + " = " + std::to_string(n) + ";");
    } else if (n != element_count(target)) {
      error(value.at, "this literal does not have the size of '" + target.data + "'");
      return false;
    }
    bool ok = true;
    for (std::size_t k = 0; k < n; ++k) {
      std::optional<Ref> e = element(target, static_cast<std::int64_t>(k), value.operands[k].at);
      ok = e && assign(*e, value.operands[k], out) && ok;
    }
    return ok;
  }
  if (target.type == nullptr || target.type->kind != asn1::TypeKind::Sequence) {
    error(value.at, "a SEQUENCE value assigned to '" + target.data + "', which is not one");
    return false;
  }
  bool ok = true;
  for (const asn1::Component& c : target.type->components) {
    const sdl::Expr* given = nullptr;
    for (std::size_t k = 0; k < value.operands.size() && k < value.field_names.size(); ++k) {
      if (folded(value.field_names[k]) == folded(c.name)) given = &value.operands[k];
    }
    const std::string exist = bip_identifier(c.name) + "_exist";
    if (c.optional) {
      if (const Leaf* leaf = bookkeeping(target, exist)) {
        out.push_back(leaf_name(target.data, *leaf) + (given ? " = true;" : " = false;"));
      }
    }
    if (given == nullptr) {
      if (!c.optional) error(value.at, "field '" + c.name + "' is missing from this value");
      ok = ok && c.optional;
      continue;
    }
    std::optional<Ref> f = field(target, c.name, given->at);
    ok = f && assign(*f, *given, out) && ok;
  }
  return ok;
}

bool Translator::assign_choice(const Ref& target, const sdl::Expr& value,
                               std::vector<std::string>& out) {
  if (target.type == nullptr || target.type->kind != asn1::TypeKind::Choice) {
    error(value.at, "a CHOICE value assigned to '" + target.data + "', which is not one");
    return false;
  }
  for (std::size_t k = 0; k < target.type->components.size(); ++k) {
    if (folded(target.type->components[k].name) != folded(value.text)) continue;
    if (const Leaf* present = bookkeeping(target, "present")) {
      out.push_back(leaf_name(target.data, *present) + " = " + std::to_string(k + 1) + ";");
    }
    std::optional<Ref> f = field(target, value.text, value.at);
    return f && assign(*f, value.operands[0], out);
  }
  error(value.at, "'" + value.text + "' is not an alternative of '" + target.data + "'");
  return false;
}

std::optional<std::string> Translator::literal_equals(const Ref& r, const sdl::Expr& literal) {
  const asn1::TypeKind kind = r.type ? r.type->kind : asn1::TypeKind::Integer;
  std::vector<std::string> parts;
  if (literal.kind == sdl::Expr::Kind::Choice && kind == asn1::TypeKind::Choice) {
    const Leaf* present = bookkeeping(r, "present");
    for (std::size_t k = 0; present && k < r.type->components.size(); ++k) {
      if (folded(r.type->components[k].name) != folded(literal.text)) continue;
      parts.push_back(leaf_name(r.data, *present) + " == " + std::to_string(k + 1));
      std::optional<Ref> f = field(r, literal.text, literal.at);
      std::optional<std::string> inner = f ? literal_equals(*f, literal.operands[0]) : std::nullopt;
      if (!inner) return std::nullopt;
      parts.push_back(*inner);
    }
  } else if (literal.kind == sdl::Expr::Kind::Sequence && kind == asn1::TypeKind::SequenceOf) {
    if (const Leaf* length = bookkeeping(r, "length")) {
      parts.push_back(leaf_name(r.data, *length) +
                      " == " + std::to_string(literal.operands.size()));
    }
    for (std::size_t k = 0; k < literal.operands.size(); ++k) {
      std::optional<Ref> e = element(r, static_cast<std::int64_t>(k), literal.operands[k].at);
      std::optional<std::string> inner = e ? literal_equals(*e, literal.operands[k]) : std::nullopt;
      if (!inner) return std::nullopt;
      parts.push_back(*inner);
    }
  } else if (literal.kind == sdl::Expr::Kind::Sequence && kind == asn1::TypeKind::Sequence) {
    for (std::size_t k = 0; k < literal.operands.size() && k < literal.field_names.size(); ++k) {
      std::optional<Ref> f = field(r, literal.field_names[k], literal.operands[k].at);
      std::optional<std::string> inner = f ? literal_equals(*f, literal.operands[k]) : std::nullopt;
      if (!inner) return std::nullopt;
      parts.push_back(*inner);
    }
  } else if (is_scalar(r)) {
    std::optional<Scalar> s = scalar(literal, r.leaves[0].asn1_type);
    if (!s) return std::nullopt;
    parts.push_back(r.data + " == " + s->text);
  } else {
    error(literal.at, "this value cannot be compared with '" + r.data + "'");
    return std::nullopt;
  }
  if (parts.empty()) {
    error(literal.at, "this value does not match the type of '" + r.data + "'");
    return std::nullopt;
  }
  std::string text;
  for (const std::string& p : parts) text += (text.empty() ? "" : " && ") + p;
  return "(" + text + ")";
}

bool Translator::assign_statement(const sdl::Expr& target, const sdl::Expr& value,
                                  std::vector<std::string>& out) {
  const bool variable_index = target.kind == sdl::Expr::Kind::Call && target.operands.size() == 2 &&
                              !constant(target.operands[1]);
  if (!variable_index) {
    std::optional<Ref> t = reference(target);
    return t && assign(*t, value, out);
  }
  std::optional<Ref> base = reference(target.operands[0]);
  std::optional<Scalar> index = scalar(target.operands[1]);
  if (!base || !index) return false;
  const std::size_t n = element_count(*base);
  if (base->type == nullptr || base->type->kind != asn1::TypeKind::SequenceOf || n == 0) {
    error(target.at, "'" + base->data + "' is not a SEQUENCE OF spread over data");
    return false;
  }
  for (std::size_t k = 0; k < n; ++k) {
    std::optional<Ref> e = element(*base, static_cast<std::int64_t>(k), target.at);
    std::vector<std::string> inner;
    if (!e || !assign(*e, value, inner)) return false;
    std::string text = "if (" + index->text + " == " + std::to_string(k) + ") then";
    for (const std::string& s : inner) text += " " + s;
    out.push_back(text + " fi");
  }
  return true;
}

}  // namespace smcbip::taste2bip::detail
