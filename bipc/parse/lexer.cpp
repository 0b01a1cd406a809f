// The BIP2 lexer: keywords, names, literals, comments and operators of Bip2.g, with positions.
#include "bipc/parse/lexer.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <utility>

#include "bipc/utf8.h"

namespace smcbip::bipc::detail {

namespace {

bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }
bool is_hex(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }
int hex_value(char c) {
  if (is_digit(c)) return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return c - 'A' + 10;
}

void append_utf8(std::string& out, std::uint32_t code_point) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code_point >> 18));
    out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

// The length of the UTF-8 sequence starting at text[pos], or 1 when it is not a valid one.
std::size_t utf8_length(std::string_view text, std::size_t pos) {
  return std::max<std::size_t>(1, well_formed_utf8(text, pos));
}

// A character quoted for a message: printable ASCII and valid UTF-8 as is, others as \xNN.
std::string quote_character(std::string_view sequence) {
  if (sequence.size() == 1) {
    auto byte = static_cast<unsigned char>(sequence[0]);
    if (byte < 0x20 || byte >= 0x7F) {
      constexpr std::string_view kHex = "0123456789ABCDEF";
      return std::string("'\\x") + kHex[byte >> 4] + kHex[byte & 0xF] + "'";
    }
  }
  return concat({"'", sequence, "'"});
}

}  // namespace

Lexer::Lexer(std::string_view text, std::uint32_t file, ErrorBudget& errors)
    : text_(text), file_(file), errors_(errors) {
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
}

void Lexer::advance_char() {
  char c = text_[pos_++];
  if (c == '\n') {
    ++line_;
    column_ = 1;
  } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
    ++column_;  // UTF-8 continuation bytes belong to the previous column
  }
}

void Lexer::skip_blanks_and_comments() {
  while (!at_end()) {
    char c = peek_char();
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      advance_char();
    } else if (c == '/' && peek_char(1) == '/') {
      while (!at_end() && peek_char() != '\n') advance_char();
    } else if (c == '/' && peek_char(1) == '*') {
      Location start = here();
      advance_char();
      advance_char();
      bool closed = false;
      while (!at_end()) {
        if (peek_char() == '*' && peek_char(1) == '/') {
          advance_char();
          advance_char();
          closed = true;
          break;
        }
        advance_char();
      }
      if (!closed) {
        errors_.error(start, "unterminated comment");
        ran_off_end_ = true;
      }
    } else {
      return;
    }
  }
}

Token Lexer::next() {
  skip_blanks_and_comments();
  Token token;
  token.loc = here();
  if (at_end() || errors_.exhausted()) {
    token.kind = TokenKind::EndOfFile;
    return token;
  }
  char c = peek_char();
  if (is_ident_start(c)) return lex_identifier_or_keyword(std::move(token));
  if (is_digit(c) || (c == '.' && is_digit(peek_char(1)))) return lex_number(std::move(token));
  if (c == '"') return lex_string(std::move(token));
  return lex_symbol(std::move(token));
}

Token Lexer::lex_identifier_or_keyword(Token token) {
  std::size_t start = pos_;
  while (!at_end() && is_ident_char(peek_char())) advance_char();
  token.text = text_.substr(start, pos_ - start);
  token.kind = keyword_kind(token.text);
  return token;
}

Token Lexer::lex_number(Token token) {
  std::size_t start = pos_;
  bool is_float = false;
  while (is_digit(peek_char())) advance_char();
  if (peek_char() == '.') {
    is_float = true;
    advance_char();
    while (is_digit(peek_char())) advance_char();
  }
  char e = peek_char();
  if (e == 'e' || e == 'E') {
    std::size_t digits_at = (peek_char(1) == '+' || peek_char(1) == '-') ? 2 : 1;
    if (is_digit(peek_char(digits_at))) {
      is_float = true;
      for (std::size_t i = 0; i < digits_at; ++i) advance_char();
      while (is_digit(peek_char())) advance_char();
    }
  }
  token.text = text_.substr(start, pos_ - start);
  const char* first = token.text.data();
  const char* last = first + token.text.size();
  if (is_float) {
    token.kind = TokenKind::Float;
    auto [end, status] = std::from_chars(first, last, token.float_value);
    if (status != std::errc() || end != last) {
      errors_.error(token.loc,
                    concat({"floating-point literal '", token.text, "' is out of range"}));
      token.float_value = 0.0;
    }
  } else {
    token.kind = TokenKind::Int;
    auto [end, status] = std::from_chars(first, last, token.int_value);
    if (status != std::errc() || end != last) {
      errors_.error(token.loc,
                    concat({"integer literal '", token.text, "' is too large (the largest int is ",
                            std::to_string(std::numeric_limits<std::int64_t>::max()), ")"}));
      token.int_value = 0;
    }
  }
  return token;
}

void Lexer::lex_escape(std::string& value) {
  Location at = here();
  advance_char();  // the backslash
  char c = peek_char();
  switch (c) {
    case 'b':
      value += '\b';
      advance_char();
      return;
    case 't':
      value += '\t';
      advance_char();
      return;
    case 'n':
      value += '\n';
      advance_char();
      return;
    case 'f':
      value += '\f';
      advance_char();
      return;
    case 'r':
      value += '\r';
      advance_char();
      return;
    case '"':
      value += '"';
      advance_char();
      return;
    case '\'':
      value += '\'';
      advance_char();
      return;
    case '\\':
      value += '\\';
      advance_char();
      return;
    default:
      break;
  }
  if (c >= '0' && c <= '7') {
    // Bip2.g: \[0-3][0-7][0-7], \[0-7][0-7] or \[0-7].
    std::size_t max_digits = c <= '3' ? 3 : 2;
    unsigned code = 0;
    for (std::size_t i = 0; i < max_digits && peek_char() >= '0' && peek_char() <= '7'; ++i) {
      code = code * 8 + static_cast<unsigned>(peek_char() - '0');
      advance_char();
    }
    // A character, as in Java, from which BIP2 takes its escapes: U+0000 to U+00FF.
    append_utf8(value, code);
    return;
  }
  if (c == 'u' && is_hex(peek_char(1)) && is_hex(peek_char(2)) && is_hex(peek_char(3)) &&
      is_hex(peek_char(4))) {
    const std::uint32_t code = lex_hex4();
    if (code >= 0xD800 && code <= 0xDBFF && peek_char() == '\\' && peek_char(1) == 'u' &&
        is_hex(peek_char(2)) && is_hex(peek_char(3)) && is_hex(peek_char(4)) &&
        is_hex(peek_char(5))) {
      const std::size_t mark = pos_;
      const Location after = here();
      advance_char();  // the backslash of the second half
      const std::uint32_t low = lex_hex4();
      if (low >= 0xDC00 && low <= 0xDFFF) {
        append_utf8(value, 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00));
        return;
      }
      pos_ = mark;  // not a low surrogate: lexed again as an escape of its own
      line_ = after.line;
      column_ = after.column;
    }
    if (code >= 0xD800 && code <= 0xDFFF) {
      errors_.error(at, concat({"invalid escape sequence '\\", text_.substr(pos_ - 5, 5),
                                "': half of a UTF-16 surrogate pair without its other half"}));
      return;
    }
    append_utf8(value, code);
    return;
  }
  if (c == 'u') {
    errors_.error(at, "invalid escape sequence: '\\u' needs four hexadecimal digits");
    return;
  }
  if (at_end()) return;  // reported as an unterminated string
  std::size_t length = utf8_length(text_, pos_);
  errors_.error(at, concat({"invalid escape sequence '\\", text_.substr(pos_, length),
                            "' in string literal"}));
  for (std::size_t i = 0; i < length; ++i) advance_char();
}

std::uint32_t Lexer::lex_hex4() {
  advance_char();  // the u
  std::uint32_t code = 0;
  for (int i = 0; i < 4; ++i) {
    code = code * 16 + static_cast<std::uint32_t>(hex_value(peek_char()));
    advance_char();
  }
  return code;
}

Token Lexer::lex_string(Token token) {
  std::size_t start = pos_;
  advance_char();  // the opening quote
  while (!at_end() && peek_char() != '"') {
    if (peek_char() == '\\') {
      lex_escape(token.string_value);
    } else if (const std::size_t length = well_formed_utf8(text_, pos_); length != 0) {
      for (std::size_t i = 0; i < length; ++i) {
        token.string_value += peek_char();
        advance_char();
      }
    } else {
      errors_.error(
          here(), concat({"string literal holds the byte ", quote_character(text_.substr(pos_, 1)),
                          ", which is not UTF-8 (sources are UTF-8 text)"}));
      advance_char();
    }
  }
  if (at_end()) {
    errors_.error(token.loc, "unterminated string literal");
    ran_off_end_ = true;
    token.kind = TokenKind::Invalid;
    token.text = text_.substr(start, 1);
    return token;
  }
  advance_char();  // the closing quote
  token.kind = TokenKind::String;
  token.text = text_.substr(start, pos_ - start);
  return token;
}

Token Lexer::lex_symbol(Token token) {
  std::size_t start = pos_;
  char c = peek_char();
  char d = peek_char(1);
  auto two = [&](TokenKind kind) {
    advance_char();
    advance_char();
    token.kind = kind;
  };
  auto one = [&](TokenKind kind) {
    advance_char();
    token.kind = kind;
  };
  switch (c) {
    case '(':
      one(TokenKind::LParen);
      break;
    case ')':
      one(TokenKind::RParen);
      break;
    case '{':
      one(TokenKind::LBrace);
      break;
    case '}':
      one(TokenKind::RBrace);
      break;
    case ',':
      one(TokenKind::Comma);
      break;
    case '\'':
      one(TokenKind::Quote);
      break;
    case '.':
      one(TokenKind::Dot);
      break;
    case ';':
      one(TokenKind::Semicolon);
      break;
    case ':':
      one(TokenKind::Colon);
      break;
    case '@':
      one(TokenKind::AtSign);
      break;
    case '~':
      one(TokenKind::Tilde);
      break;
    case '+':
      one(TokenKind::Plus);
      break;
    case '-':
      one(TokenKind::Minus);
      break;
    case '*':
      one(TokenKind::Star);
      break;
    case '/':
      one(TokenKind::Slash);
      break;
    case '%':
      one(TokenKind::Percent);
      break;
    case '^':
      one(TokenKind::Caret);
      break;
    case '<':
      d == '=' ? two(TokenKind::Le) : one(TokenKind::Lt);
      break;
    case '>':
      d == '=' ? two(TokenKind::Ge) : one(TokenKind::Gt);
      break;
    case '=':
      d == '=' ? two(TokenKind::EqEq) : one(TokenKind::Assign);
      break;
    case '!':
      d == '=' ? two(TokenKind::NotEq) : one(TokenKind::Not);
      break;
    case '&':
      d == '&' ? two(TokenKind::AndAnd) : one(TokenKind::Amp);
      break;
    case '|':
      d == '|' ? two(TokenKind::OrOr) : one(TokenKind::Pipe);
      break;
    default: {
      std::size_t length = utf8_length(text_, pos_);
      std::string_view sequence = text_.substr(pos_, length);
      errors_.error(token.loc, concat({"unexpected character ", quote_character(sequence)}));
      for (std::size_t i = 0; i < length; ++i) advance_char();
      token.kind = TokenKind::Invalid;
      break;
    }
  }
  token.text = text_.substr(start, pos_ - start);
  return token;
}

std::vector<Token> lex_all(std::string_view text, std::uint32_t file, Diagnostics& diags) {
  ErrorBudget errors(diags, std::numeric_limits<std::size_t>::max());
  Lexer lexer(text, file, errors);
  std::vector<Token> tokens;
  do {
    tokens.push_back(lexer.next());
  } while (tokens.back().kind != TokenKind::EndOfFile);
  return tokens;
}

}  // namespace smcbip::bipc::detail
