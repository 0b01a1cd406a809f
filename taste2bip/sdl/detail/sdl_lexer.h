// Tokens of SDL-PR text and the lexer producing them (comments skipped, keywords left as words).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"

namespace smcbip::taste2bip::sdl::detail {

enum class TokenKind : std::uint8_t {
  EndOfFile,
  Word,  // a name or keyword; `lower` holds it in lower case
  Integer,
  Real,
  String,       // `value` holds the contents
  BitString,    // '0101'B: `value` holds the digits
  OctetString,  // '0A'H: `value` holds the hexadecimal digits
  LParen,
  RParen,
  LBrace,
  RBrace,
  Comma,
  Semicolon,
  Colon,
  Assign,  // :=
  Dot,
  Bang,
  Plus,
  Minus,
  Star,
  Slash,
  Concat,  // //
  Equal,
  NotEqual,  // /=
  Less,
  LessEqual,
  Greater,
  GreaterEqual,
  Arrow,  // =>
};

struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  std::string text;   // as written
  std::string lower;  // Word: lower case
  std::string value;  // String: contents
  bipc::Location at;
};

/// Counts the errors of one file and stops reporting past a limit.
class ErrorBudget {
 public:
  ErrorBudget(bipc::Diagnostics& diags, std::size_t max_errors) : diags_(diags), max_(max_errors) {}
  void error(bipc::Location at, std::string message);
  bool exhausted() const { return count_ >= max_; }
  /// Set by the lexer when an unterminated comment or string ran to the end of the text: what
  /// the parser then finds missing at the end is a consequence, not a new error.
  void set_ran_off_end() { ran_off_end_ = true; }
  bool ran_off_end() const { return ran_off_end_; }

 private:
  bipc::Diagnostics& diags_;
  std::size_t max_;
  std::size_t count_ = 0;
  bool ran_off_end_ = false;
};

/// Lexes the whole text; the last token is EndOfFile. Columns count bytes, as in every reader of
/// taste2bip (detail/text_cursor.h); a leading UTF-8 byte order mark is skipped. Stops early once
/// the budget is exhausted.
std::vector<Token> lex_sdl(std::string_view text, std::uint32_t file, ErrorBudget& errors);

/// How a token is named in a message: `';'`, `'state'`, `end of file`.
std::string describe(const Token& token);

}  // namespace smcbip::taste2bip::sdl::detail
