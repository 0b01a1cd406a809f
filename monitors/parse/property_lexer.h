// Tokens of property files (PROPERTIES.md) and the lexer producing them, with positions.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
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

/// The tokens of `text` (file index `file`), lexed as the parser reads them, so that only the
/// few it looks ahead at are held (a file costs memory for its text, not per token). Comments
/// (`//`, `/* */`) and white space separate tokens. A character no token starts with, a
/// malformed number or an unknown unit suffix is reported and skipped. After the last token,
/// End repeats.
class TokenStream {
 public:
  TokenStream(std::string_view text, std::uint32_t file, bipc::Diagnostics& diagnostics);
  ~TokenStream();

  /// Puts `token` before the next one (a keyword the caller supplies).
  void push_front(Token token);
  /// The token `ahead` places after the next one.
  const Token& peek(std::size_t ahead = 0);
  /// Takes the next token; the reference holds until the next call of take().
  const Token& take();
  /// The last token taken, or null before the first.
  const Token* previous() const { return taken_ == 0 ? nullptr : &previous_; }
  /// How many tokens were taken.
  std::size_t taken() const { return taken_; }

 private:
  class Lexer;
  std::unique_ptr<Lexer> lexer_;
  std::deque<Token> ahead_;
  Token previous_;
  std::size_t taken_ = 0;
};

/// A token as error messages quote it: `'['`, `name 'x'`, `number 3`, `end of file`.
std::string describe(const Token& token);

}  // namespace smcbip::monitors::detail
