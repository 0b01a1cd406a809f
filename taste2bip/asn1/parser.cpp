// The ASN.1 reader: modules, IMPORTS, assignments and value notation (types in
// parser_type.cpp).
#include "taste2bip/asn1/parser.h"

namespace smcbip::taste2bip::asn1 {
namespace detail {

std::string describe(const Token& t) {
  if (t.kind == TokenKind::EndOfFile) return "the end of the file";
  std::string_view text = t.text.size() > 40 ? t.text.substr(0, 40) : t.text;
  return "'" + std::string(text) + "'";
}

void Parser::skip_to_end() {
  while (cur().kind != TokenKind::EndOfFile && !cur().is("END")) advance();
  advance();
}

void Parser::parse_module() {
  Module m;
  m.at = cur().at;
  if (cur().kind != TokenKind::Identifier || !starts_upper(cur().text)) {
    error(cur().at,
          "expected a module name (`Name DEFINITIONS ::= BEGIN ... END`), got " + describe(cur()));
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

void Parser::parse_exports(Module& m) {
  if (accept("ALL")) {
    expect(";", "after 'EXPORTS ALL'");
    return;
  }
  m.exports_all = false;  // the names are not kept: TASTE exports everything
  while (cur().kind == TokenKind::Identifier || cur().is(",")) advance();
  expect(";", "after the exported names");
}

void Parser::parse_imports(Module& m) {
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

void Parser::skip_imports() {
  while (cur().kind != TokenKind::EndOfFile && !cur().is(";") && !cur().is("END")) advance();
  accept(";");
}

/// Skips `{ ... }`, nested; iterative, so deep nesting costs no stack. False if unclosed.
bool Parser::skip_braces() {
  std::size_t depth = 0;
  do {
    if (cur().is("{")) ++depth;
    if (cur().is("}")) --depth;
    advance();
  } while (depth > 0 && cur().kind != TokenKind::EndOfFile);
  return depth == 0;
}

/// Skips to what looks like the next assignment (or END), always moving on at least a token.
void Parser::recover() {
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

void Parser::parse_assignment(Module& m) {
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

bool Parser::parse_parameters(TypeAssignment& a) {
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
      return error(cur().at,
                   "expected a parameter name after '" + p.governor + ":', got " + describe(cur()));
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

/// A value in value notation, kept as written: `{ ... }` (balanced), or one (signed) item,
/// or `name : value` (a CHOICE value).
bool Parser::parse_value_text(std::string& out) {
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

}  // namespace detail

void read_asn1(const std::string& text, std::uint32_t file, DataView& into,
               bipc::Diagnostics& diags) {
  detail::Parser(text, file, into, diags).run();
}

}  // namespace smcbip::taste2bip::asn1
