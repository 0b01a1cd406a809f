// Tokens of property files (PROPERTIES.md) and the lexer producing them, with positions.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"
#include "monitors/property/ast.h"

namespace smcbip::monitors::detail {

enum class TokenKind : std::uint8_t {
  End,
  Name,    // identifiers and keywords alike: the parser tells keywords by their text
  Number,  // with its unit, if a suffix follows
  Symbol,  // punctuation and operators, by text: ( ) [ ] { } , ; : . ! ? # + - * / % = < <= >
           // >= == != && || & | -> => <-> <=> =? [] <> -->
  Label,   // a PRISM label, `"deadlock"`: its text without the quotes
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;
  bipc::Location at;
  // Number: its value, whether written as an integer, and its unit.
  double number = 0.0;
  bool integral = false;
  TimeUnit unit = TimeUnit::None;
};

/// The tokens of `text` (file index `file`), ending with End. Comments (`//`, `/* */`) and
/// white space separate tokens. A character no token starts with, a malformed number or an
/// unknown unit suffix is reported and skipped.
std::vector<Token> lex_properties(std::string_view text, std::uint32_t file,
                                  bipc::Diagnostics& diagnostics);

/// A token as error messages quote it: `'['`, `name 'x'`, `number 3`, `end of file`.
std::string describe(const Token& token);

}  // namespace smcbip::monitors::detail
