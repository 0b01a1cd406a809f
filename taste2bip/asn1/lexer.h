// Tokens of ASN.1 source text (X.680 clause 12) and the lexer producing them; internal to the
// data view reader.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"

namespace smcbip::taste2bip::asn1::detail {

enum class TokenKind : std::uint8_t {
  EndOfFile,
  Identifier,  // type or value reference, or a module name (hyphens inside)
  Keyword,     // a reserved word of X.680 12.38
  Number,      // unsigned integer
  Real,        // digits with a fraction and/or exponent
  String,      // "..."
  BString,     // '0101'B
  HString,     // 'AF'H
  Assign,      // ::=
  Range,       // ..
  Ellipsis,    // ...
  Symbol,      // one character: { } ( ) , ; | . : - [ ] < > @ ! ^ & * = +
};

struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  std::string_view text;  // into the source text
  std::size_t offset = 0;
  bipc::Location at;
  bool is(std::string_view t) const {
    return kind != TokenKind::String && kind != TokenKind::EndOfFile && text == t;
  }
};

/// Splits `text` into tokens ending with one EndOfFile, skipping `--` and nested `/* */`
/// comments. Lexical errors go to `diags`; a run of invalid bytes is one error, and the lexer
/// gives up after `max_errors` of them. Columns count bytes.
std::vector<Token> tokenize(std::string_view text, std::uint32_t file, bipc::Diagnostics& diags,
                            std::size_t max_errors);

/// Whether `word` is an X.680 reserved word.
bool is_keyword(std::string_view word);

}  // namespace smcbip::taste2bip::asn1::detail
