// The ASN.1 reader: types, their components and their constraints.
#include <charconv>
#include <cstdlib>
#include <memory>
#include <set>

#include "taste2bip/asn1/parser.h"

namespace smcbip::taste2bip::asn1::detail {

bool Parser::parse_type(Type& t, int depth) {
  t.at = cur().at;
  if (depth >= kMaxDepth) {
    error(cur().at, "types nested deeper than " + std::to_string(kMaxDepth) + " levels");
    stop();
    return false;
  }
  const Token& tok = cur();
  if (tok.kind == TokenKind::Identifier) {
    if (!starts_upper(tok.text)) {
      return error(tok.at, "expected a type, got the value name " + describe(tok) +
                               " (type names start with an uppercase letter)");
    }
    t.kind = TypeKind::Reference;
    t.name = std::string(tok.text);
    advance();
    if (cur().is(".") && next().kind == TokenKind::Identifier) {
      t.module = t.name;
      advance();
      t.name = std::string(cur().text);
      advance();
    }
    if (cur().is("{") && !parse_arguments(t)) return false;
  } else if (tok.kind == TokenKind::Keyword) {
    if (!parse_builtin(t, depth)) return false;
  } else if (tok.is("[")) {
    return error(tok.at, "tagged types ('[n] Type') are not supported");
  } else {
    return error(tok.at, "expected a type, got " + describe(tok));
  }
  while (cur().is("(")) {
    if (!parse_constraint(t)) return false;
  }
  return true;
}

bool Parser::parse_builtin(Type& t, int depth) {
  std::string_view word = cur().text;
  bipc::Location at = cur().at;
  advance();
  if (word == "INTEGER") {
    t.kind = TypeKind::Integer;
    if (cur().is("{")) return error(cur().at, "named numbers in INTEGER are not supported");
  } else if (word == "REAL") {
    t.kind = TypeKind::Real;
  } else if (word == "BOOLEAN") {
    t.kind = TypeKind::Boolean;
  } else if (word == "NULL") {
    t.kind = TypeKind::Null;
  } else if (word == "ENUMERATED") {
    t.kind = TypeKind::Enumerated;
    return parse_enumerants(t);
  } else if (word == "CHOICE") {
    t.kind = TypeKind::Choice;
    return parse_components(t, depth);
  } else if (word == "SEQUENCE") {
    if (cur().is("{")) {
      t.kind = TypeKind::Sequence;
      return parse_components(t, depth);
    }
    t.kind = TypeKind::SequenceOf;
    if (cur().is("(")) {
      if (!parse_constraint(t)) return false;
    } else if (cur().is("SIZE")) {
      if (!parse_size(t)) return false;
    }
    if (!expect("OF", "after 'SEQUENCE'")) return false;
    if (cur().kind == TokenKind::Identifier && !starts_upper(cur().text)) {
      return error(cur().at, "named elements ('SEQUENCE OF name Type') are not supported");
    }
    t.element = std::make_unique<Type>();
    return parse_type(*t.element, depth + 1);
  } else if (word == "OCTET" || word == "BIT") {
    t.kind = word == "OCTET" ? TypeKind::OctetString : TypeKind::BitString;
    if (!expect("STRING", "after '" + std::string(word) + "'")) return false;
    if (cur().is("{")) return error(cur().at, "named bits in BIT STRING are not supported");
  } else if (word == "IA5String" || word == "NumericString" || word == "PrintableString" ||
             word == "VisibleString" || word == "UTF8String") {
    t.kind = TypeKind::CharacterString;
    t.string_kind = std::string(word);
  } else if (word == "SET") {
    return error(at, "SET and SET OF types are not supported (TASTE data views use SEQUENCE)");
  } else if (word == "CLASS" || word == "TYPE-IDENTIFIER" || word == "INSTANCE") {
    return error(at, "information object classes ('" + std::string(word) + "') are not supported");
  } else {
    return error(at, "the type '" + std::string(word) + "' is not supported");
  }
  return true;
}

bool Parser::parse_arguments(Type& t) {
  advance();  // {
  while (true) {
    Value v;
    if (!parse_bound(v, "an argument of '" + t.name + "'")) return false;
    t.arguments.push_back(std::move(v));
    if (accept("}")) return true;
    if (!expect(",", "or '}' after an argument of '" + t.name + "'")) return false;
  }
}

bool Parser::parse_enumerants(Type& t) {
  if (!expect("{", "after 'ENUMERATED'")) return false;
  std::set<std::int64_t> used;
  std::set<std::string> names;
  while (true) {
    if (cur().kind == TokenKind::Ellipsis) {
      t.extensible = true;
      advance();
    } else if (cur().kind == TokenKind::Identifier) {
      Enumerant e;
      e.name = std::string(cur().text);
      e.at = cur().at;
      advance();
      if (accept("(")) {
        Value v;
        if (!parse_bound(v, "as the value of '" + e.name + "'")) return false;
        if (v.kind != Value::Kind::Integer) {
          return error(v.at, "expected an integer value for the enumerant '" + e.name + "'");
        }
        e.value = v.integer;
        e.explicit_value = true;
        if (!used.insert(e.value).second) {
          error(v.at, "the value " + std::to_string(e.value) + " of '" + e.name +
                          "' is already used in this ENUMERATED");
        }
        if (!expect(")", "after the value of '" + e.name + "'")) return false;
      }
      if (!names.insert(e.name).second) {
        error(e.at, "the enumerant '" + e.name + "' is already defined in this ENUMERATED");
      }
      t.enumerants.push_back(std::move(e));
    } else {
      return error(cur().at, "expected an enumerant name or '...', got " + describe(cur()));
    }
    if (accept("}")) break;
    if (!expect(",", "or '}' after an enumerant")) return false;
  }
  // X.680 20.3: unnumbered enumerants take the smallest values not used, in order.
  std::int64_t next_value = 0;
  for (Enumerant& e : t.enumerants) {
    if (e.explicit_value) continue;
    while (used.count(next_value) != 0) ++next_value;
    e.value = next_value;
    used.insert(next_value);
  }
  return true;
}

bool Parser::parse_components(Type& t, int depth) {
  bool choice = t.kind == TypeKind::Choice;
  const char* what = choice ? "alternative" : "component";
  if (!expect("{", choice ? "after 'CHOICE'" : "after 'SEQUENCE'")) return false;
  std::set<std::string> names;
  if (accept("}")) return true;
  while (true) {
    if (cur().kind == TokenKind::Ellipsis) {
      t.extensible = true;
      advance();
    } else if (cur().is("COMPONENTS")) {
      return error(cur().at, "'COMPONENTS OF' is not supported");
    } else if (cur().is("[")) {
      return error(cur().at, "extension addition groups and tags ('[') are not supported");
    } else if (cur().kind == TokenKind::Identifier && !starts_upper(cur().text)) {
      Component c;
      c.name = std::string(cur().text);
      c.at = cur().at;
      advance();
      if (!parse_type(c.type, depth + 1)) return false;
      if (cur().is("OPTIONAL") || cur().is("DEFAULT")) {
        if (choice) {
          return error(cur().at,
                       "'" + std::string(cur().text) + "' is not allowed on a CHOICE alternative");
        }
        if (accept("OPTIONAL")) {
          c.optional = true;
        } else {
          advance();
          if (!parse_value_text(c.default_value)) return false;
        }
      }
      if (!names.insert(c.name).second) {
        error(c.at, std::string("the ") + what + " '" + c.name + "' is already defined");
      }
      t.components.push_back(std::move(c));
    } else {
      return error(cur().at, std::string("expected a ") + what +
                                 " name (starting with a lowercase letter) or '...', got " +
                                 describe(cur()));
    }
    if (accept("}")) return true;
    if (!expect(",", std::string("or '}' after a ") + what)) return false;
  }
}

bool Parser::parse_constraint(Type& t) {
  bipc::Location open = cur().at;
  advance();  // (
  if (cur().is("SIZE")) {
    if (!parse_size(t)) return false;
  } else if (cur().is("WITH")) {
    return error(cur().at, "'WITH COMPONENT(S)' constraints are not supported");
  } else if (cur().is("CONTAINING") || cur().is("PATTERN") || cur().is("FROM") ||
             cur().is("INCLUDES") || cur().is("CONSTRAINED")) {
    return error(cur().at, "'" + std::string(cur().text) + "' constraints are not supported");
  } else if (t.kind == TypeKind::SequenceOf) {
    return error(cur().at,
                 "expected 'SIZE' in the constraint of a SEQUENCE OF, got " + describe(cur()));
  } else {
    if (!t.range.empty()) {
      return error(open, "a second value constraint on one type is not supported");
    }
    if (!parse_ranges(t.range)) return false;
  }
  return expect(")", "to close the constraint");
}

bool Parser::parse_size(Type& t) {
  bipc::Location at = cur().at;
  advance();  // SIZE
  if (!t.size.empty()) return error(at, "a second SIZE constraint on one type is not supported");
  if (!expect("(", "after 'SIZE'")) return false;
  if (!parse_ranges(t.size)) return false;
  t.size.at = at;
  return expect(")", "to close 'SIZE ('");
}

bool Parser::parse_ranges(Constraint& c) {
  c.at = cur().at;
  while (true) {
    if (cur().kind == TokenKind::Ellipsis) {
      c.extensible = true;
      advance();
    } else {
      Range r;
      if (!parse_bound(r.lower, "in the constraint")) return false;
      if (accept("..")) {
        if (!parse_bound(r.upper, "after '..'")) return false;
      } else {
        r.upper = r.lower;
      }
      c.ranges.push_back(std::move(r));
    }
    if (!accept("|") && !accept(",")) return true;
  }
}

bool Parser::parse_bound(Value& v, const std::string& where) {
  v.at = cur().at;
  std::size_t from = cur().offset;
  bool negative = false;
  if (cur().is("-")) {
    negative = true;
    advance();
  }
  const Token& tok = cur();
  if (tok.kind == TokenKind::Number) {
    v.kind = Value::Kind::Integer;
    std::uint64_t magnitude = 0;
    auto [end, ec] = std::from_chars(tok.text.data(), tok.text.data() + tok.text.size(), magnitude);
    std::uint64_t limit = negative ? std::uint64_t{1} << 63 : (std::uint64_t{1} << 63) - 1;
    if (ec != std::errc() || magnitude > limit) {
      return error(v.at, "the integer " +
                             std::string(source_between(from, tok.offset + tok.text.size())) +
                             " is outside the 64-bit range");
    }
    v.integer =
        negative ? static_cast<std::int64_t>(0 - magnitude) : static_cast<std::int64_t>(magnitude);
    v.real = static_cast<double>(v.integer);
  } else if (tok.kind == TokenKind::Real) {
    v.kind = Value::Kind::Real;
    v.real = std::strtod(std::string(tok.text).c_str(), nullptr);
    if (negative) v.real = -v.real;
  } else if (!negative && (tok.is("MIN") || tok.is("MAX"))) {
    v.kind = tok.is("MIN") ? Value::Kind::Min : Value::Kind::Max;
  } else if (!negative && tok.kind == TokenKind::Identifier && !starts_upper(tok.text)) {
    v.kind = Value::Kind::Name;
  } else {
    return error(tok.at,
                 "expected a number, MIN, MAX or a value name " + where + ", got " + describe(tok));
  }
  advance();
  v.text = std::string(source_between(from, end_of_previous()));
  return true;
}

}  // namespace smcbip::taste2bip::asn1::detail
