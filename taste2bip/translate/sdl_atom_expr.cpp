// SDL expressions as BIP expressions over the leaves of the variables: references, names
// (variables, enumerants, ASN.1 values), operators and structured equality.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "bipc/utf8.h"
#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

std::string real_text(const std::string& text) {
  if (text.find_first_of(".eE") == std::string::npos) return text + ".0";
  return text.front() == '.' ? "0" + text : text;
}

std::string string_literal(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

const char* bip_operator(sdl::Operator op) {
  switch (op) {
    case sdl::Operator::Plus:
      return "+";
    case sdl::Operator::Minus:
      return "-";
    case sdl::Operator::Times:
      return "*";
    case sdl::Operator::Divide:
      return "/";
    case sdl::Operator::Mod:
    case sdl::Operator::Rem:
      return "%";
    case sdl::Operator::Less:
      return "<";
    case sdl::Operator::LessEqual:
      return "<=";
    case sdl::Operator::Greater:
      return ">";
    case sdl::Operator::GreaterEqual:
      return ">=";
    case sdl::Operator::And:
    case sdl::Operator::AndThen:
      return "&&";
    case sdl::Operator::Or:
    case sdl::Operator::OrElse:
      return "||";
    case sdl::Operator::Xor:
    case sdl::Operator::NotEqual:
      return "!=";
    case sdl::Operator::Equal:
      return "==";
    default:
      return nullptr;
  }
}

bool is_arithmetic(sdl::Operator op) {
  return op == sdl::Operator::Plus || op == sdl::Operator::Minus || op == sdl::Operator::Times ||
         op == sdl::Operator::Divide || op == sdl::Operator::Mod || op == sdl::Operator::Rem;
}

/// Whether the digits fit a 64-bit int (what BIP's int literals are).
bool fits_int(const std::string& digits) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  return error == std::errc() && end == digits.data() + digits.size();
}

bool numeric(const std::string& kind) { return kind == "int" || kind == "float"; }

/// What the operands of `op` must be when kinds `a` and `b` do not fit it, else empty. Unknown
/// kinds are left to the front end.
std::string operand_problem(sdl::Operator op, const std::string& a, const std::string& b) {
  using O = sdl::Operator;
  if (a.empty() || b.empty()) return "";
  switch (op) {
    case O::Mod:
    case O::Rem:
      return a == "int" && b == "int" ? "" : "integers";
    case O::Plus:
    case O::Minus:
    case O::Times:
    case O::Divide:
    case O::Less:
    case O::LessEqual:
    case O::Greater:
    case O::GreaterEqual:
      return numeric(a) && numeric(b) ? "" : "numbers";
    case O::Equal:
    case O::NotEqual:
      return a == b || (numeric(a) && numeric(b)) ? "" : "values of one type";
    case O::And:
    case O::Or:
    case O::Xor:
    case O::Implies:
    case O::AndThen:
    case O::OrElse:
      return a == "bool" && b == "bool" ? "" : "booleans";
    default:
      return "";
  }
}

}  // namespace

std::optional<Ref> Translator::reference(const sdl::Expr& e) {
  using K = sdl::Expr::Kind;
  if (e.kind == K::Name) {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      auto found = it->find(folded(e.text));
      if (found == it->end()) continue;
      if (found->second.ref) return found->second.ref;
      break;
    }
    error(e.at, "'" + e.text + "' is not a variable");
    return std::nullopt;
  }
  if (e.kind == K::Field) {
    const sdl::Expr& record = e.operands[0];
    // OpenGEODE's `<function>_ctxt.<parameter>`: a context parameter.
    if (record.kind == K::Name && folded(record.text) == folded(function_.name + "_ctxt")) {
      if (auto c = context_.find(folded(e.text)); c != context_.end()) return c->second;
      error(e.at, "'" + e.text + "' is not a context parameter of " + function_.name);
      return std::nullopt;
    }
    std::optional<Ref> base = reference(e.operands[0]);
    return base ? field(*base, e.text, e.at) : std::nullopt;
  }
  if (e.kind == K::Call && e.operands.size() == 2) {
    std::optional<Ref> base = reference(e.operands[0]);
    if (!base) return std::nullopt;
    const std::optional<std::int64_t> index = constant(e.operands[1]);
    if (!index) {
      error(e.operands[1].at, "indexing with an index that is not a constant is not translated");
      return std::nullopt;
    }
    return element(*base, *index, e.at);
  }
  error(e.at, "this expression is not a variable or a part of one");
  return std::nullopt;
}

const asn1::Type* Translator::type_of(const sdl::Expr& e) {
  const bool was = quiet_;
  quiet_ = true;
  const asn1::Type* type = nullptr;
  if (e.kind == sdl::Expr::Kind::Call && !e.operands.empty() &&
      e.operands[0].kind == sdl::Expr::Kind::Name && folded(e.operands[0].text) == "present" &&
      e.operands.size() == 2) {
    if (std::optional<Ref> r = reference(e.operands[1])) type = r->type;
  } else if (e.kind == sdl::Expr::Kind::Name || e.kind == sdl::Expr::Kind::Field ||
             e.kind == sdl::Expr::Kind::Call) {
    if (std::optional<Ref> r = reference(e)) type = r->type;
  }
  quiet_ = was;
  return type;
}

std::optional<std::int64_t> Translator::constant(const sdl::Expr& e) {
  using K = sdl::Expr::Kind;
  if (e.kind == K::Integer) {
    try {
      return std::stoll(e.text);
    } catch (...) {
      return std::nullopt;
    }
  }
  if (e.kind == K::Name) {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      auto found = it->find(folded(e.text));
      if (found != it->end()) {
        if (found->second.ref) return std::nullopt;
        return found->second.number;
      }
    }
    for (const asn1::Module& m : data_.modules) {
      for (const asn1::ValueAssignment& v : m.values) {
        if (folded(v.name) != folded(e.text)) continue;
        try {
          std::size_t used = 0;
          const std::int64_t n = std::stoll(v.value, &used);
          if (used == v.value.size()) return n;
        } catch (...) {
        }
      }
    }
    return std::nullopt;
  }
  if (e.kind == K::Call && e.operands.size() == 2 && e.operands[0].kind == K::Name &&
      folded(e.operands[0].text) == "length") {
    const bool was = quiet_;
    quiet_ = true;
    std::optional<Scalar> n = call_value(e, nullptr);
    quiet_ = was;
    if (!n) return std::nullopt;
    return constant(sdl::Expr{K::Integer, sdl::Operator::None, n->text, {}, {}, e.at});
  }
  if (e.kind == K::Unary && e.op == sdl::Operator::Negate) {
    std::optional<std::int64_t> v = constant(e.operands[0]);
    std::int64_t negated = 0;
    if (!v || __builtin_sub_overflow(std::int64_t{0}, *v, &negated)) return std::nullopt;
    return negated;
  }
  if (e.kind == K::Binary && (e.op == sdl::Operator::Plus || e.op == sdl::Operator::Minus ||
                              e.op == sdl::Operator::Times)) {
    std::optional<std::int64_t> a = constant(e.operands[0]), b = constant(e.operands[1]);
    if (!a || !b) return std::nullopt;
    std::int64_t result = 0;  // a constant that overflows is no constant
    const bool overflow = e.op == sdl::Operator::Plus    ? __builtin_add_overflow(*a, *b, &result)
                          : e.op == sdl::Operator::Minus ? __builtin_sub_overflow(*a, *b, &result)
                                                         : __builtin_mul_overflow(*a, *b, &result);
    if (overflow) return std::nullopt;
    return result;
  }
  return std::nullopt;
}

std::optional<Scalar> Translator::scalar(const sdl::Expr& e, const asn1::Type* hint) {
  using K = sdl::Expr::Kind;
  switch (e.kind) {
    case K::Integer:
      if (!fits_int(e.text)) {
        error(e.at, "the integer " + e.text + " is beyond BIP's 64-bit int");
        return std::nullopt;
      }
      return Scalar{e.text, "int"};
    case K::Real:
      if (e.text.find("infinity") != std::string::npos) break;
      if (!std::isfinite(std::strtod(e.text.c_str(), nullptr))) {
        error(e.at, "the real " + e.text + " is beyond a double");
        return std::nullopt;
      }
      return Scalar{real_text(e.text), "float"};
    case K::Boolean:
      return Scalar{e.text, "bool"};
    case K::String:
      if (!bipc::is_utf8(e.text)) {
        error(e.at, "a string holding bytes that are not UTF-8 (BIP text is UTF-8)");
        return std::nullopt;
      }
      return Scalar{string_literal(e.text), "string"};
    case K::Name:
      return name_value(e, hint);
    case K::Call:
      return call_value(e, hint);
    case K::Field:
      return scalar_reference(e);
    case K::Unary: {
      std::optional<Scalar> v = scalar(e.operands[0], hint);
      if (!v) return std::nullopt;
      const bool is_not = e.op == sdl::Operator::Not;
      if (!v->kind.empty() && (is_not ? v->kind != "bool" : !numeric(v->kind))) {
        error(e.at, std::string(is_not ? "'not' takes a boolean" : "'-' takes a number") +
                        ", not a " + v->kind);
        return std::nullopt;
      }
      if (is_not) return Scalar{"!(" + v->text + ")", "bool"};
      return Scalar{"-(" + v->text + ")", v->kind};
    }
    case K::Binary:
      return binary(e);
    default:
      break;
  }
  error(e.at, "this expression is not translated (no BIP form for it)");
  return std::nullopt;
}

std::optional<Scalar> Translator::name_value(const sdl::Expr& e, const asn1::Type* hint) {
  const std::string name = folded(e.text);
  // Compared with present(x), a name is an alternative of x's CHOICE before anything else.
  if (hint != nullptr && hint->kind == asn1::TypeKind::Choice) {
    for (std::size_t k = 0; k < hint->components.size(); ++k) {
      if (folded(hint->components[k].name) == name) return Scalar{std::to_string(k + 1), "int"};
    }
  }
  for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
    auto found = it->find(name);
    if (found == it->end()) continue;
    if (!found->second.ref) return Scalar{std::to_string(found->second.number), "int"};
    const Ref& r = *found->second.ref;
    if (r.leaves.size() == 1 && r.leaves[0].suffix.empty()) return Scalar{r.data, r.leaves[0].type};
    error(e.at, "'" + e.text + "' is a structured value, used where a single value is needed");
    return std::nullopt;
  }
  if (hint != nullptr) {
    for (const asn1::Enumerant& en : hint->enumerants) {
      if (folded(en.name) == name) return Scalar{std::to_string(en.value), "int"};
    }
  }
  std::optional<std::int64_t> value;
  bool ambiguous = false;
  for (const asn1::Module& m : data_.modules) {
    for (const asn1::TypeAssignment& t : m.types) {
      for (const asn1::Enumerant& en : t.type.enumerants) {
        if (folded(en.name) != name) continue;
        ambiguous = ambiguous || (value && *value != en.value);
        value = en.value;
      }
    }
  }
  if (value && !ambiguous) return Scalar{std::to_string(*value), "int"};
  if (ambiguous) {
    error(e.at, "enumerant '" + e.text + "' has different values in different types");
    return std::nullopt;
  }
  for (const asn1::Module& m : data_.modules) {
    for (const asn1::ValueAssignment& v : m.values) {
      if (folded(v.name) != name) continue;
      const std::string t = folded(v.value);
      if (t == "true" || t == "false") return Scalar{t, "bool"};
      if (std::optional<std::int64_t> n = constant(e)) return Scalar{std::to_string(*n), "int"};
      if (!v.value.empty() && v.value.find_first_not_of("+-.0123456789eE") == std::string::npos) {
        return Scalar{real_text(v.value), "float"};
      }
      error(e.at, "the ASN.1 value '" + v.name + "' is not a single number or boolean");
      return std::nullopt;
    }
  }
  error(e.at, "unknown name '" + e.text + "'");
  return std::nullopt;
}

std::optional<Scalar> Translator::binary(const sdl::Expr& e) {
  const sdl::Operator op = e.op;
  if (op == sdl::Operator::Equal || op == sdl::Operator::NotEqual) {
    return equality(e.operands[0], e.operands[1], op == sdl::Operator::Equal, e.at);
  }
  const char* bip = bip_operator(op);
  if (bip == nullptr) {
    error(e.at, std::string("operator '") + sdl::spelling(op) + "' is not translated");
    return std::nullopt;
  }
  std::optional<Scalar> a = scalar(e.operands[0], type_of(e.operands[1]));
  std::optional<Scalar> b = scalar(e.operands[1], type_of(e.operands[0]));
  if (!a || !b) return std::nullopt;
  if (const std::string want = operand_problem(op, a->kind, b->kind); !want.empty()) {
    error(e.at, std::string("'") + sdl::spelling(op) + "' takes " + want + ", not " + a->kind +
                    " and " + b->kind);
    return std::nullopt;
  }
  if (op == sdl::Operator::Implies)
    return Scalar{"(!(" + a->text + ") || " + b->text + ")", "bool"};
  std::string kind = "bool";
  if (is_arithmetic(op)) kind = (a->kind == "float" || b->kind == "float") ? "float" : "int";
  return Scalar{"(" + a->text + " " + bip + " " + b->text + ")", kind};
}

std::optional<Scalar> Translator::equality(const sdl::Expr& a, const sdl::Expr& b, bool equal,
                                           const bipc::Location& at) {
  const asn1::Type* ta = type_of(a);
  const asn1::Type* tb = type_of(b);
  auto is_present = [](const sdl::Expr& x) {
    return x.kind == sdl::Expr::Kind::Call && x.operands[0].kind == sdl::Expr::Kind::Name &&
           folded(x.operands[0].text) == "present";
  };
  const bool structured = !is_present(a) && !is_present(b) && [&] {
    const auto kind = ta ? ta->kind : (tb ? tb->kind : asn1::TypeKind::Integer);
    return kind == asn1::TypeKind::Sequence || kind == asn1::TypeKind::Choice ||
           kind == asn1::TypeKind::SequenceOf;
  }();
  const std::string op = equal ? " == " : " != ";
  if (!structured) {
    std::optional<Scalar> x = scalar(a, tb), y = scalar(b, ta);
    if (!x || !y) return std::nullopt;
    if (!operand_problem(sdl::Operator::Equal, x->kind, y->kind).empty()) {
      error(at, "a " + x->kind + " compared with a " + y->kind);
      return std::nullopt;
    }
    return Scalar{"(" + x->text + op + y->text + ")", "bool"};
  }
  auto literal = [](const sdl::Expr& x) {
    return x.kind == sdl::Expr::Kind::Sequence || x.kind == sdl::Expr::Kind::Choice;
  };
  if (literal(a) || literal(b)) {
    std::optional<Ref> r = reference(literal(a) ? b : a);
    std::optional<std::string> text = r ? literal_equals(*r, literal(a) ? a : b) : std::nullopt;
    if (!text) return std::nullopt;
    return Scalar{equal ? "(" + *text + ")" : "!(" + *text + ")", "bool"};
  }
  std::optional<Ref> x = reference(a), y = reference(b);
  if (!x || !y) return std::nullopt;
  std::string text;
  for (const Leaf& l : x->leaves) {
    const Leaf* match = nullptr;
    for (const Leaf& m : y->leaves) match = m.suffix == l.suffix ? &m : match;
    if (match == nullptr || l.type != match->type) {
      error(at, "the values compared do not have the same structure");
      return std::nullopt;
    }
    text +=
        (text.empty() ? "" : " && ") + leaf_name(x->data, l) + " == " + leaf_name(y->data, *match);
  }
  if (text.empty()) text = "true";
  return Scalar{equal ? "(" + text + ")" : "!(" + text + ")", "bool"};
}

std::optional<Scalar> Translator::condition(const sdl::Expr& e, const char* what) {
  std::optional<Scalar> value = scalar(e);
  if (value && value->kind != "bool") {
    error(e.at, std::string(what) + " must be a boolean, not " +
                    (value->kind.empty() ? "a value of unknown type" : "a " + value->kind));
    return std::nullopt;
  }
  return value;
}

}  // namespace smcbip::taste2bip::detail
