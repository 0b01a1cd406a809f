// The ASN.1 reader: recursive descent over the X.680 subset of TASTE data views.
#include <charconv>
#include <cstdlib>
#include <set>

#include "taste2bip/asn1/data_view.h"
#include "taste2bip/asn1/lexer.h"

namespace smcbip::taste2bip::asn1 {
namespace {

using detail::Token;
using detail::TokenKind;

constexpr std::size_t kMaxErrors = 20;
constexpr int kMaxDepth = 200;

bool starts_upper(std::string_view s) { return !s.empty() && s[0] >= 'A' && s[0] <= 'Z'; }

/// How a token is named in messages.
std::string describe(const Token& t) {
  if (t.kind == TokenKind::EndOfFile) return "the end of the file";
  std::string_view text = t.text.size() > 40 ? t.text.substr(0, 40) : t.text;
  return "'" + std::string(text) + "'";
}

class Parser {
 public:
  Parser(const std::string& text, std::uint32_t file, DataView& into, bipc::Diagnostics& diags)
      : text_(text), into_(into), diags_(diags), first_error_(diags.error_count()) {
    tokens_ = detail::tokenize(text, file, diags, kMaxErrors);
    eof_ = tokens_.back();
    if (errors() >= kMaxErrors) stop();
  }

  void run() {
    while (cur().kind != TokenKind::EndOfFile) parse_module();
  }

 private:
  // --- tokens and errors -------------------------------------------------------------------
  std::size_t errors() const { return diags_.error_count() - first_error_; }
  const Token& cur() const { return stopped_ ? eof_ : tokens_[pos_]; }
  const Token& next(std::size_t ahead = 1) const {
    if (stopped_) return eof_;
    return pos_ + ahead < tokens_.size() ? tokens_[pos_ + ahead] : tokens_.back();
  }
  void advance() {
    if (!stopped_ && pos_ + 1 < tokens_.size()) ++pos_;
  }
  bool accept(std::string_view text) {
    if (!cur().is(text)) return false;
    advance();
    return true;
  }
  void stop() {
    if (!stopped_) diags_.note(cur().at, "too many errors: the rest of the file is not read");
    stopped_ = true;
  }
  /// Reports an error; always returns false so that parse functions can `return error(...)`.
  bool error(bipc::Location at, std::string message) {
    if (stopped_) return false;
    diags_.error(at, std::move(message));
    if (errors() >= kMaxErrors) stop();
    return false;
  }
  bool expect(std::string_view text, const std::string& what) {
    if (accept(text)) return true;
    return error(cur().at,
                 "expected '" + std::string(text) + "' " + what + ", got " + describe(cur()));
  }
  std::string_view source_between(std::size_t from, std::size_t to) const {
    return std::string_view(text_).substr(from, to - from);
  }
  std::size_t end_of_previous() const {
    const Token& t = tokens_[pos_ == 0 ? 0 : pos_ - 1];
    return t.offset + t.text.size();
  }

  // --- modules --------------------------------------------------------------------------------
  void skip_to_end() {
    while (cur().kind != TokenKind::EndOfFile && !cur().is("END")) advance();
    advance();
  }

  void parse_module() {
    Module m;
    m.at = cur().at;
    if (cur().kind != TokenKind::Identifier || !starts_upper(cur().text)) {
      error(cur().at, "expected a module name (`Name DEFINITIONS ::= BEGIN ... END`), got " +
                          describe(cur()));
      return skip_to_end();
    }
    m.name = std::string(cur().text);
    advance();
    if (cur().is("{")) skip_braces();  // the module's object identifier
    if (!expect("DEFINITIONS", "after the module name '" + m.name + "'")) return skip_to_end();
    if (cur().is("EXPLICIT") || cur().is("IMPLICIT") || cur().is("AUTOMATIC")) {
      m.tag_default = std::string(cur().text);
      advance();
      if (!expect("TAGS", "after '" + m.tag_default + "'")) return skip_to_end();
    }
    if (accept("EXTENSIBILITY") && !expect("IMPLIED", "after 'EXTENSIBILITY'")) {
      return skip_to_end();
    }
    if (!expect("::=", "after 'DEFINITIONS'") || !expect("BEGIN", "after 'DEFINITIONS ::='")) {
      return skip_to_end();
    }
    if (accept("EXPORTS")) parse_exports(m);
    if (accept("IMPORTS")) parse_imports(m);
    while (cur().kind != TokenKind::EndOfFile && !cur().is("END")) parse_assignment(m);
    expect("END", "at the end of module '" + m.name + "'");
    into_.modules.push_back(std::move(m));
  }

  void parse_exports(Module& m) {
    if (accept("ALL")) {
      expect(";", "after 'EXPORTS ALL'");
      return;
    }
    m.exports_all = false;  // the names are not kept: TASTE exports everything
    while (cur().kind == TokenKind::Identifier || cur().is(",")) advance();
    expect(";", "after the exported names");
  }

  void parse_imports(Module& m) {
    while (!cur().is(";")) {
      Import import;
      while (true) {
        if (cur().kind != TokenKind::Identifier) {
          error(cur().at, "expected an imported name or ';', got " + describe(cur()));
          return skip_imports();
        }
        import.names.emplace_back(cur().text);
        import.name_at.push_back(cur().at);
        advance();
        if (cur().is("{")) {
          error(cur().at, "importing parameterized references ('Name{}') is not supported");
          return skip_imports();
        }
        if (!accept(",")) break;
      }
      if (!expect("FROM", "after the imported names")) return skip_imports();
      if (cur().kind != TokenKind::Identifier || !starts_upper(cur().text)) {
        error(cur().at, "expected a module name after 'FROM', got " + describe(cur()));
        return skip_imports();
      }
      import.module = std::string(cur().text);
      import.at = cur().at;
      advance();
      if (cur().is("{")) skip_braces();
      m.imports.push_back(std::move(import));
    }
    advance();
  }

  void skip_imports() {
    while (cur().kind != TokenKind::EndOfFile && !cur().is(";") && !cur().is("END")) advance();
    accept(";");
  }

  /// Skips `{ ... }`, nested; iterative, so deep nesting costs no stack. False if unclosed.
  bool skip_braces() {
    std::size_t depth = 0;
    do {
      if (cur().is("{")) ++depth;
      if (cur().is("}")) --depth;
      advance();
    } while (depth > 0 && cur().kind != TokenKind::EndOfFile);
    return depth == 0;
  }

  // --- assignments ----------------------------------------------------------------------------
  /// Skips to what looks like the next assignment (or END), always moving on at least a token.
  void recover() {
    if (!cur().is("END")) advance();
    while (cur().kind != TokenKind::EndOfFile && !cur().is("END")) {
      if (cur().kind == TokenKind::Identifier &&
          (next().kind == TokenKind::Assign ||
           (!starts_upper(cur().text) && next(2).kind == TokenKind::Assign &&
            (next().kind == TokenKind::Identifier || next().kind == TokenKind::Keyword)))) {
        return;
      }
      advance();
    }
  }

  void parse_assignment(Module& m) {
    const Token& first = cur();
    if (first.kind != TokenKind::Identifier) {
      error(first.at, "expected a type or value assignment, got " + describe(first));
      return recover();
    }
    std::string name(first.text);
    bipc::Location at = first.at;
    advance();
    if (starts_upper(name)) {
      TypeAssignment assignment;
      assignment.name = name;
      assignment.at = at;
      if (cur().is("{") && !parse_parameters(assignment)) return recover();
      if (cur().kind != TokenKind::Assign) {
        if ((cur().kind == TokenKind::Identifier || cur().kind == TokenKind::Keyword) &&
            next().kind == TokenKind::Assign) {
          error(at, "value set and information object assignments ('" + name + " " +
                        std::string(cur().text) + " ::= ...') are not supported");
        } else {
          error(cur().at,
                "expected '::=' after the type name '" + name + "', got " + describe(cur()));
        }
        return recover();
      }
      advance();
      if (!parse_type(assignment.type, 0)) return recover();
      m.types.push_back(std::move(assignment));
      return;
    }
    ValueAssignment value;
    value.name = name;
    value.at = at;
    if (!parse_type(value.type, 0)) return recover();
    if (!expect("::=", "after the type of the value '" + name + "'")) return recover();
    if (!parse_value_text(value.value)) return recover();
    m.values.push_back(std::move(value));
  }

  bool parse_parameters(TypeAssignment& a) {
    advance();  // {
    while (true) {
      Parameter p;
      p.at = cur().at;
      if ((cur().kind != TokenKind::Identifier && cur().kind != TokenKind::Keyword) ||
          !next().is(":")) {
        return error(cur().at,
                     "expected a value parameter 'Type: name' (type parameters are not "
                     "supported), got " +
                         describe(cur()));
      }
      p.governor = std::string(cur().text);
      advance();
      advance();  // :
      if (cur().kind != TokenKind::Identifier) {
        return error(cur().at, "expected a parameter name after '" + p.governor + ":', got " +
                                   describe(cur()));
      }
      p.name = std::string(cur().text);
      advance();
      a.parameters.push_back(std::move(p));
      if (accept("}")) return true;
      if (!expect(",", "or '}' after the parameter '" + a.parameters.back().name + "'")) {
        return false;
      }
    }
  }

  // --- types ----------------------------------------------------------------------------------
  bool parse_type(Type& t, int depth) {
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

  bool parse_builtin(Type& t, int depth) {
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
      return error(at,
                   "information object classes ('" + std::string(word) + "') are not supported");
    } else {
      return error(at, "the type '" + std::string(word) + "' is not supported");
    }
    return true;
  }

  bool parse_arguments(Type& t) {
    advance();  // {
    while (true) {
      Value v;
      if (!parse_bound(v, "an argument of '" + t.name + "'")) return false;
      t.arguments.push_back(std::move(v));
      if (accept("}")) return true;
      if (!expect(",", "or '}' after an argument of '" + t.name + "'")) return false;
    }
  }

  bool parse_enumerants(Type& t) {
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

  bool parse_components(Type& t, int depth) {
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
            return error(cur().at, "'" + std::string(cur().text) +
                                       "' is not allowed on a CHOICE alternative");
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

  // --- constraints ----------------------------------------------------------------------------
  bool parse_constraint(Type& t) {
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

  bool parse_size(Type& t) {
    bipc::Location at = cur().at;
    advance();  // SIZE
    if (!t.size.empty()) return error(at, "a second SIZE constraint on one type is not supported");
    if (!expect("(", "after 'SIZE'")) return false;
    if (!parse_ranges(t.size)) return false;
    t.size.at = at;
    return expect(")", "to close 'SIZE ('");
  }

  bool parse_ranges(Constraint& c) {
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

  bool parse_bound(Value& v, const std::string& where) {
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
      auto [end, ec] =
          std::from_chars(tok.text.data(), tok.text.data() + tok.text.size(), magnitude);
      std::uint64_t limit = negative ? std::uint64_t{1} << 63 : (std::uint64_t{1} << 63) - 1;
      if (ec != std::errc() || magnitude > limit) {
        return error(v.at, "the integer " +
                               std::string(source_between(from, tok.offset + tok.text.size())) +
                               " is outside the 64-bit range");
      }
      v.integer = negative ? static_cast<std::int64_t>(0 - magnitude)
                           : static_cast<std::int64_t>(magnitude);
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
      return error(tok.at, "expected a number, MIN, MAX or a value name " + where + ", got " +
                               describe(tok));
    }
    advance();
    v.text = std::string(source_between(from, end_of_previous()));
    return true;
  }

  // --- values ---------------------------------------------------------------------------------
  /// A value in value notation, kept as written: `{ ... }` (balanced), or one (signed) item,
  /// or `name : value` (a CHOICE value).
  bool parse_value_text(std::string& out) {
    std::size_t from = cur().offset;
    for (int items = 0; items < kMaxDepth; ++items) {
      if (cur().is("{")) {
        if (!skip_braces()) {
          return error(cur().at, "expected '}' to close the value, got " + describe(cur()));
        }
      } else {
        accept("-");
        const Token& tok = cur();
        bool ok = tok.kind == TokenKind::Number || tok.kind == TokenKind::Real ||
                  tok.kind == TokenKind::String || tok.kind == TokenKind::BString ||
                  tok.kind == TokenKind::HString || tok.kind == TokenKind::Identifier ||
                  tok.is("TRUE") || tok.is("FALSE") || tok.is("NULL") || tok.is("PLUS-INFINITY") ||
                  tok.is("MINUS-INFINITY");
        if (!ok) return error(tok.at, "expected a value, got " + describe(tok));
        advance();
        if (tok.kind == TokenKind::Identifier && cur().is(".") &&
            next().kind == TokenKind::Identifier) {
          advance();
          advance();
        }
        if (tok.kind == TokenKind::Identifier && accept(":")) continue;
      }
      out = std::string(source_between(from, end_of_previous()));
      return true;
    }
    return error(cur().at, "value nested deeper than " + std::to_string(kMaxDepth) + " levels");
  }

  const std::string& text_;
  DataView& into_;
  bipc::Diagnostics& diags_;
  std::size_t first_error_;
  std::vector<Token> tokens_;
  Token eof_;
  std::size_t pos_ = 0;
  bool stopped_ = false;
};

}  // namespace

void read_asn1(const std::string& text, std::uint32_t file, DataView& into,
               bipc::Diagnostics& diags) {
  Parser(text, file, into, diags).run();
}

}  // namespace smcbip::taste2bip::asn1
