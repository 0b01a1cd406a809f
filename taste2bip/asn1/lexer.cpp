// The ASN.1 lexer: X.680 clause 12 items, comments skipped, positions tracked per byte.
#include "taste2bip/asn1/lexer.h"

#include <algorithm>
#include <iterator>

#include "taste2bip/detail/text_cursor.h"

namespace smcbip::taste2bip::asn1::detail {
namespace {

// The reserved words of X.680 (08/2015) 12.38.
constexpr std::string_view kKeywords[] = {
    "ABSENT",
    "ABSTRACT-SYNTAX",
    "ALL",
    "APPLICATION",
    "AUTOMATIC",
    "BEGIN",
    "BIT",
    "BMPString",
    "BOOLEAN",
    "BY",
    "CHARACTER",
    "CHOICE",
    "CLASS",
    "COMPONENT",
    "COMPONENTS",
    "CONSTRAINED",
    "CONTAINING",
    "DATE",
    "DATE-TIME",
    "DEFAULT",
    "DEFINITIONS",
    "DURATION",
    "EMBEDDED",
    "ENCODED",
    "ENCODING-CONTROL",
    "END",
    "ENUMERATED",
    "EXCEPT",
    "EXPLICIT",
    "EXPORTS",
    "EXTENSIBILITY",
    "EXTERNAL",
    "FALSE",
    "FROM",
    "GeneralString",
    "GeneralizedTime",
    "GraphicString",
    "IA5String",
    "IDENTIFIER",
    "IMPLICIT",
    "IMPLIED",
    "IMPORTS",
    "INCLUDES",
    "INSTANCE",
    "INSTRUCTIONS",
    "INTEGER",
    "INTERSECTION",
    "ISO646String",
    "MAX",
    "MIN",
    "MINUS-INFINITY",
    "NOT-A-NUMBER",
    "NULL",
    "NumericString",
    "OBJECT",
    "OCTET",
    "OF",
    "OID-IRI",
    "OPTIONAL",
    "ObjectDescriptor",
    "PATTERN",
    "PDV",
    "PLUS-INFINITY",
    "PRESENT",
    "PRIVATE",
    "PrintableString",
    "REAL",
    "RELATIVE-OID",
    "RELATIVE-OID-IRI",
    "SEQUENCE",
    "SET",
    "SETTINGS",
    "SIZE",
    "STRING",
};
// The rest of the reserved words (kept apart so the array above stays readable).
constexpr std::string_view kMoreKeywords[] = {
    "SYNTAX",          "T61String",       "TAGS",           "TIME",   "TIME-OF-DAY", "TRUE",
    "TYPE-IDENTIFIER", "TeletexString",   "UNION",          "UNIQUE", "UNIVERSAL",   "UTCTime",
    "UTF8String",      "UniversalString", "VideotexString",
};

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alnum(char c) { return is_letter(c) || is_digit(c); }
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool is_symbol(char c) {
  return std::string_view("{}(),;|.:-[]<>@!^&*=+").find(c) != std::string_view::npos;
}

class Lexer : private taste2bip::detail::TextCursor {
 public:
  Lexer(std::string_view text, std::uint32_t file, bipc::Diagnostics& diags, std::size_t max)
      : TextCursor(text, file), diags_(diags), max_errors_(max) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    while (errors_ < max_errors_) {
      skip_blanks_and_comments();
      if (pos_ >= text_.size()) break;
      std::size_t start = pos_;
      bipc::Location at = here();
      TokenKind kind = scan(start);
      if (pos_ == start) {  // an invalid byte run: report once, skip it
        while (pos_ < text_.size() && !valid_start(text_[pos_])) advance();
        error(at, "unexpected character in ASN.1 text");
        continue;
      }
      tokens.push_back(Token{kind, text_.substr(start, pos_ - start), start, at});
    }
    tokens.push_back(Token{TokenKind::EndOfFile, {}, text_.size(), here()});
    return tokens;
  }

 private:
  static bool valid_start(char c) {
    return is_space(c) || is_alnum(c) || is_symbol(c) || c == '"' || c == '\'' || c == '/';
  }

  void error(bipc::Location at, std::string message) {
    diags_.error(at, std::move(message));
    ++errors_;
  }

  void skip_blanks_and_comments() {
    while (pos_ < text_.size()) {
      char c = text_[pos_];
      if (is_space(c)) {
        advance();
      } else if (c == '-' && peek(1) == '-') {
        advance();
        advance();
        // X.680 12.6.3: a comment ends at the end of the line or at the next "--". But a comment
        // whose text starts with "--" is a commented-out comment line (`--  -- note`, as in
        // TASTE's own DataView template) and runs to the end of the line.
        while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) advance();
        bool to_end_of_line = peek() == '-' && peek(1) == '-';
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') {
          if (!to_end_of_line && text_[pos_] == '-' && peek(1) == '-') {
            advance();
            advance();
            break;
          }
          advance();
        }
      } else if (c == '/' && peek(1) == '*') {
        bipc::Location at = here();
        int depth = 0;
        do {  // comments nest (X.680 12.6.4)
          if (text_[pos_] == '/' && peek(1) == '*') {
            ++depth;
            advance();
          } else if (text_[pos_] == '*' && peek(1) == '/') {
            --depth;
            advance();
          }
          advance();
        } while (depth > 0 && pos_ < text_.size());
        if (depth > 0) error(at, "unterminated comment: expected '*/' before the end of the file");
      } else {
        break;
      }
    }
  }

  TokenKind scan(std::size_t start) {
    char c = text_[pos_];
    if (is_letter(c)) {
      advance();
      // A hyphen joins letters and digits, but never ends a name nor doubles ("--" is a comment).
      while (pos_ < text_.size() &&
             (is_alnum(text_[pos_]) || (text_[pos_] == '-' && is_alnum(peek(1))))) {
        advance();
      }
      return is_keyword(text_.substr(start, pos_ - start)) ? TokenKind::Keyword
                                                           : TokenKind::Identifier;
    }
    if (is_digit(c)) {
      TokenKind kind = TokenKind::Number;
      while (is_digit(peek())) advance();
      if (peek() == '.' && is_digit(peek(1))) {
        kind = TokenKind::Real;
        advance();
        while (is_digit(peek())) advance();
      }
      if ((peek() == 'e' || peek() == 'E') &&
          (is_digit(peek(1)) || ((peek(1) == '-' || peek(1) == '+') && is_digit(peek(2))))) {
        kind = TokenKind::Real;
        advance();
        if (peek() == '-' || peek() == '+') advance();
        while (is_digit(peek())) advance();
      }
      return kind;
    }
    if (c == '"') {
      bipc::Location at = here();
      advance();
      while (pos_ < text_.size()) {
        if (text_[pos_] == '"') {
          if (peek(1) != '"') break;
          advance();  // "" is a quote inside the string
        }
        advance();
      }
      if (pos_ >= text_.size()) {
        error(at, "unterminated string: expected '\"' before the end of the file");
        return TokenKind::String;
      }
      advance();
      return TokenKind::String;
    }
    if (c == '\'') {
      bipc::Location at = here();
      advance();
      while (pos_ < text_.size() && (is_alnum(text_[pos_]) || is_space(text_[pos_]))) advance();
      if (peek() == '\'' && (peek(1) == 'B' || peek(1) == 'H')) {
        char radix = peek(1);
        advance();
        advance();
        return radix == 'B' ? TokenKind::BString : TokenKind::HString;
      }
      error(at, "expected a bit string 'bits'B or a hexadecimal string 'hex'H");
      return TokenKind::BString;
    }
    if (c == ':' && peek(1) == ':' && peek(2) == '=') {
      advance();
      advance();
      advance();
      return TokenKind::Assign;
    }
    if (c == '.' && peek(1) == '.') {
      advance();
      advance();
      if (peek() == '.') {
        advance();
        return TokenKind::Ellipsis;
      }
      return TokenKind::Range;
    }
    if (is_symbol(c)) {
      advance();
      return TokenKind::Symbol;
    }
    return TokenKind::Symbol;  // pos_ unchanged: the caller reports the invalid bytes
  }

  bipc::Diagnostics& diags_;
  std::size_t max_errors_;
  std::size_t errors_ = 0;
};

}  // namespace

bool is_keyword(std::string_view word) {
  return std::find(std::begin(kKeywords), std::end(kKeywords), word) != std::end(kKeywords) ||
         std::find(std::begin(kMoreKeywords), std::end(kMoreKeywords), word) !=
             std::end(kMoreKeywords);
}

std::vector<Token> tokenize(std::string_view text, std::uint32_t file, bipc::Diagnostics& diags,
                            std::size_t max_errors) {
  return Lexer(text, file, diags, max_errors).run();
}

}  // namespace smcbip::taste2bip::asn1::detail
