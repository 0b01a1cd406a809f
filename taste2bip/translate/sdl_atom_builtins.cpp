// OpenGEODE's builtin operators (abs, length, present, exist, num, float, power) over the
// leaves of a value, and indexing; other calls inside expressions are refused.
#include <set>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

/// The data of `ref`'s leaf with relative suffix `suffix`, or empty.
std::string leaf_data(const Ref& ref, const std::string& suffix) {
  for (const Leaf& l : ref.leaves) {
    if (l.suffix == suffix && l.asn1_type == nullptr) return leaf_name(ref.data, l);
  }
  return {};
}

}  // namespace

std::optional<Scalar> Translator::bookkeeping_value(const std::string& f, const sdl::Expr& e) {
  const sdl::Expr& arg = e.operands[1];
  if (f == "exist") {
    std::optional<Ref> r =
        arg.kind == sdl::Expr::Kind::Field ? reference(arg.operands[0]) : std::nullopt;
    const std::string suffix = bip_identifier(arg.text) + "_exist";
    for (const Leaf& l : r ? r->leaves : std::vector<Leaf>{}) {
      if (folded(l.suffix) == folded(suffix)) return Scalar{leaf_name(r->data, l), "bool"};
    }
    error(e.at, "exist of something that is not an optional field");
    return std::nullopt;
  }
  std::optional<Ref> r = reference(arg);
  if (!r) return std::nullopt;
  if (std::string d = leaf_data(*r, f); !d.empty()) return Scalar{d, "int"};
  if (f == "length" && r->type != nullptr && r->type->kind == asn1::TypeKind::SequenceOf) {
    std::set<std::string> elements;
    for (const Leaf& l : r->leaves) {
      if (!l.path.empty()) elements.insert(l.path[0]);
    }
    return Scalar{std::to_string(elements.size()), "int"};
  }
  error(e.at, "'" + f + "' of a value that has no " + f + " in its data is not translated");
  return std::nullopt;
}

std::optional<Scalar> Translator::call_value(const sdl::Expr& e, const asn1::Type* hint) {
  const sdl::Expr& callee = e.operands[0];
  const std::size_t args = e.operands.size() - 1;
  const std::string f = callee.kind == sdl::Expr::Kind::Name ? folded(callee.text) : "";
  if ((f == "abs" || f == "num" || f == "float") && args == 1) {
    std::optional<Scalar> x = scalar(e.operands[1], hint);
    if (!x) return std::nullopt;
    if (f == "num") return x;
    if (f == "float") return Scalar{"(" + x->text + " * 1.0)", "float"};
    if (x->kind == "float") {
      need_function("float max(float, float)");
      return Scalar{"max(" + x->text + ", -(" + x->text + "))", "float"};
    }
    need_function("int abs(int)");
    return Scalar{"abs(" + x->text + ")", "int"};
  }
  if (f == "power" && args == 2) {
    std::optional<Scalar> x = scalar(e.operands[1]);
    std::optional<std::int64_t> n = constant(e.operands[2]);
    if (!x) return std::nullopt;
    if (!n || *n < 0 || *n > 16) {
      error(e.operands[2].at,
            "power with an exponent that is not a constant from 0 to 16 is "
            "not translated");
      return std::nullopt;
    }
    std::string text = x->kind == "float" ? "1.0" : "1";
    for (std::int64_t k = 0; k < *n; ++k) text += " * " + x->text;
    return Scalar{"(" + text + ")", x->kind};
  }
  if ((f == "length" || f == "present" || f == "exist") && args == 1) {
    return bookkeeping_value(f, e);
  }
  if (!f.empty() && procedures_.count(f) > 0) {
    error(e.at, "a call of procedure '" + callee.text + "' inside an expression is not translated");
    return std::nullopt;
  }
  return scalar_reference(e);
}

std::optional<Scalar> Translator::scalar_reference(const sdl::Expr& e) {
  std::optional<Ref> r = reference(e);
  if (!r) return std::nullopt;
  if (r->leaves.size() == 1 && r->leaves[0].suffix.empty()) {
    return Scalar{r->data, r->leaves[0].type};
  }
  error(e.at, "a structured value is used where a single value is needed");
  return std::nullopt;
}

}  // namespace smcbip::taste2bip::detail
