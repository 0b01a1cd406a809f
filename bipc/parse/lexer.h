// Tokens of BIP2 source text (after the lexical rules of Bip2.g) and the lexer producing them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"

namespace smcbip::bipc::detail {

/// The kinds of tokens; keywords are those of Bip2.g (see is_soft_keyword for names among them).
enum class TokenKind : std::uint8_t {
  EndOfFile,
  Invalid,  // a lexical error, already reported by the lexer
  Identifier,
  Int,
  Float,
  String,
  // Keywords of Bip2.g, KwInt to KwFi contiguous (Parser::is_word relies on it).
  KwInt,
  KwBool,
  KwFloat,
  KwString,
  KwTrue,
  KwFalse,
  KwPackage,
  KwUse,
  KwEnd,
  KwConst,
  KwData,
  KwExtern,
  KwType,
  KwRefine,
  KwAs,
  KwFunction,
  KwOperator,
  KwPort,
  KwAtom,
  KwCompound,
  KwConnector,
  KwComponent,
  KwExport,
  KwRemember,
  KwIgnore,
  KwError,
  KwClock,
  KwUnit,
  KwNanosecond,
  KwMicrosecond,
  KwMillisecond,
  KwSecond,
  KwMinute,
  KwHour,
  KwDay,
  KwPlace,
  KwInitial,
  KwOn,
  KwInternal,
  KwFrom,
  KwTo,
  KwAt,
  KwProvided,
  KwDo,
  KwResume,
  KwLazy,
  KwDelayable,
  KwEager,
  KwPriority,
  KwInvariant,
  KwDefine,
  KwUp,
  KwDown,
  KwSync,
  KwAsync,
  KwIf,
  KwThen,
  KwElse,
  KwFi,
  // Punctuation and operators.
  LParen,
  RParen,
  LBrace,
  RBrace,
  Comma,
  Quote,
  Dot,
  Semicolon,
  Colon,
  AtSign,
  Assign,
  Lt,
  Gt,
  Le,
  Ge,
  EqEq,
  NotEq,
  AndAnd,
  OrOr,
  Not,
  Tilde,
  Plus,
  Minus,
  Star,
  Slash,
  Percent,
  Amp,
  Pipe,
  Caret,
};

/// One token; `text` views the source text, which must outlive the token.
struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  Location loc;
  std::string_view text;     // as written (a string literal with its quotes)
  std::string string_value;  // String: the unescaped contents
  std::int64_t int_value = 0;
  double float_value = 0.0;
};

/// Counts the errors reported for one file and stops reporting once a limit is reached, so a
/// binary or badly broken file yields a bounded list of diagnostics.
class ErrorBudget {
 public:
  ErrorBudget(Diagnostics& diags, std::size_t max_errors) : diags_(diags), max_(max_errors) {}
  /// Reports an error unless the limit was already reached; the last one adds a note.
  void error(Location at, std::string message);
  bool exhausted() const { return count_ >= max_; }
  std::size_t count() const { return count_; }

 private:
  Diagnostics& diags_;
  std::size_t max_;
  std::size_t count_ = 0;
};

/// A hand-written lexer producing one token at a time. Line and column are 1-based; a tab is one
/// column and a UTF-8 sequence is one column. A leading UTF-8 byte order mark is skipped.
class Lexer {
 public:
  Lexer(std::string_view text, std::uint32_t file, ErrorBudget& errors);
  /// The next token; EndOfFile forever once the text (or the error budget) is exhausted.
  Token next();
  /// Whether an unterminated comment or string ran to the end of the text: what the parser
  /// then finds missing at the end of the file is a consequence, not a new error.
  bool ran_off_end() const { return ran_off_end_; }

 private:
  char peek_char(std::size_t k = 0) const {
    return pos_ + k < text_.size() ? text_[pos_ + k] : '\0';
  }
  bool at_end() const { return pos_ >= text_.size(); }
  void advance_char();
  Location here() const { return {file_, line_, column_}; }
  void skip_blanks_and_comments();
  Token lex_identifier_or_keyword(Token token);
  Token lex_number(Token token);
  Token lex_string(Token token);
  void lex_escape(std::string& value);
  /// The code unit of a `\uXXXX` escape whose backslash is lexed: past the `u` and its four
  /// hexadecimal digits, which the caller has checked.
  std::uint32_t lex_hex4();
  Token lex_symbol(Token token);

  std::string_view text_;
  std::uint32_t file_;
  ErrorBudget& errors_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1;
  std::uint32_t column_ = 1;
  bool ran_off_end_ = false;
};

/// Lexes a whole text (the EndOfFile token included); for tests and tools.
std::vector<Token> lex_all(std::string_view text, std::uint32_t file, Diagnostics& diags);

/// The keyword for `word`, or Identifier.
TokenKind keyword_kind(std::string_view word);

/// Whether a keyword may still serve as a name where the grammar expects one (`up`, `error`,
/// `second`, ...): these keywords only have a meaning at positions where no name can follow.
bool is_soft_keyword(TokenKind kind);

/// The fixed spelling of a keyword or symbol ("end", "<="); empty for other kinds.
std::string_view spelling(TokenKind kind);

/// Joins the parts of a message. (Writing `"text" + std::string(...)` trips a false -Wrestrict of
/// GCC 12 in optimised builds.)
std::string concat(std::initializer_list<std::string_view> parts);

/// How a token is named in a diagnostic: `'end'`, `','`, `'x'`, `end of file`.
std::string describe(const Token& token);

}  // namespace smcbip::bipc::detail
