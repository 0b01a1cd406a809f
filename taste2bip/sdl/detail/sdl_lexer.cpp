// The SDL-PR lexer: words, numbers, quoted strings and symbols; `/* */` and `--` comments skipped.
#include "taste2bip/sdl/detail/sdl_lexer.h"

#include <cctype>

#include "taste2bip/detail/text_cursor.h"

namespace smcbip::taste2bip::sdl::detail {

void ErrorBudget::error(bipc::Location at, std::string message) {
  if (exhausted()) return;
  ++count_;
  diags_.error(at, std::move(message));
  if (exhausted()) diags_.note(at, "too many errors in this file; reading stopped");
}

namespace {

bool is_word_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Scanner : public taste2bip::detail::TextCursor {
 public:
  Scanner(std::string_view text, std::uint32_t file, ErrorBudget& errors)
      : TextCursor(text, file), errors_(errors) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
  }

  std::vector<Token> run() {
    std::vector<Token> tokens;
    for (;;) {
      skip_blanks_and_comments();
      if (at_end() || errors_.exhausted()) break;
      Token token;
      token.at = here();
      const std::size_t start = pos_;
      if (!lex_one(token)) continue;
      token.text = std::string(text_.substr(start, pos_ - start));
      tokens.push_back(std::move(token));
    }
    Token eof;
    eof.at = here();
    tokens.push_back(eof);
    return tokens;
  }

 private:
  bool at_end() const { return pos_ >= text_.size(); }

  void skip_blanks_and_comments() {
    while (!at_end()) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '/' && peek(1) == '*') {
        const bipc::Location start = here();
        advance();
        advance();
        while (!at_end() && !(peek() == '*' && peek(1) == '/')) advance();
        if (at_end()) {
          errors_.error(start, "unterminated comment: expected '*/' before end of file");
          errors_.set_ran_off_end();
          return;
        }
        advance();
        advance();
      } else if (c == '-' && peek(1) == '-') {
        // As in OpenGEODE's grammar, a `--` comment ends at the next `--` or at the line's end.
        advance();
        advance();
        while (!at_end() && peek() != '\n' && !(peek() == '-' && peek(1) == '-')) advance();
        if (!at_end() && peek() == '-') {
          advance();
          advance();
        }
      } else {
        return;
      }
    }
  }

  // Lexes one token into `token`; false when nothing was produced (an error was reported).
  bool lex_one(Token& token) {
    const char c = peek();
    if (is_word_start(c)) {
      const std::size_t start = pos_;
      while (is_word_char(peek())) advance();
      token.kind = TokenKind::Word;
      // ASN.1's REAL values plus-infinity and minus-infinity are one word.
      std::string word(text_.substr(start, pos_ - start));
      for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if ((word == "plus" || word == "minus") && peek() == '-' &&
          text_.substr(pos_ + 1, 8).size() == 8 && !is_word_char(peek(9))) {
        std::string rest(text_.substr(pos_ + 1, 8));
        for (char& ch : rest) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        if (rest == "infinity") {
          for (int i = 0; i < 9; ++i) advance();
        }
      }
      return true;
    }
    if (is_digit(c)) return lex_number(token);
    if (c == '\'') return lex_string(token);
    if (c == '"') return lex_quoted_bits(token);
    return lex_symbol(token);
  }

  bool lex_number(Token& token) {
    token.kind = TokenKind::Integer;
    while (is_digit(peek())) advance();
    if (peek() == '.' && is_digit(peek(1))) {
      token.kind = TokenKind::Real;
      advance();
      while (is_digit(peek())) advance();
    }
    if ((peek() == 'e' || peek() == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      token.kind = TokenKind::Real;
      advance();
      if (peek() == '+' || peek() == '-') advance();
      while (is_digit(peek())) advance();
    }
    return true;
  }

  bool lex_string(Token& token) {
    const bipc::Location start = here();
    advance();
    for (;;) {
      if (at_end()) {
        errors_.error(start, "unterminated string: expected a closing quote before end of file");
        errors_.set_ran_off_end();
        return false;
      }
      if (peek() == '\'') {
        advance();
        if (peek() != '\'') break;
      }
      token.value.push_back(peek());
      advance();
    }
    token.kind = TokenKind::String;
    // ASN.1 bit and octet string values: '0101'B, '0A'H.
    const char suffix = static_cast<char>(std::toupper(static_cast<unsigned char>(peek())));
    if ((suffix == 'B' || suffix == 'H') && !is_word_char(peek(1))) {
      const std::string_view digits = suffix == 'B' ? "01" : "0123456789abcdefABCDEF";
      if (token.value.find_first_not_of(digits) == std::string::npos) {
        token.kind = suffix == 'B' ? TokenKind::BitString : TokenKind::OctetString;
        advance();
      }
    }
    return true;
  }

  // OpenGEODE's bit and octet strings in double quotes: "0101"B, "0A"H (blanks allowed).
  bool lex_quoted_bits(Token& token) {
    const bipc::Location start = here();
    advance();
    while (!at_end() && peek() != '"') {
      const char c = peek();
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n') token.value.push_back(c);
      advance();
    }
    if (at_end()) {
      errors_.error(start, "unterminated string: expected a closing '\"' before end of file");
      errors_.set_ran_off_end();
      return false;
    }
    advance();
    const char suffix = static_cast<char>(std::toupper(static_cast<unsigned char>(peek())));
    const std::string_view digits = suffix == 'B' ? "01" : "0123456789abcdefABCDEF";
    if ((suffix != 'B' && suffix != 'H') || is_word_char(peek(1)) ||
        token.value.find_first_not_of(digits) != std::string::npos) {
      errors_.error(start, "expected a bit string \"0101\"B or an octet string \"0A\"H");
      return false;
    }
    advance();
    token.kind = suffix == 'B' ? TokenKind::BitString : TokenKind::OctetString;
    return true;
  }

  bool lex_symbol(Token& token) {
    const char c = peek();
    const char d = peek(1);
    auto take = [&](TokenKind kind, int length) {
      for (int i = 0; i < length; ++i) advance();
      token.kind = kind;
      return true;
    };
    switch (c) {
      case '(':
        return take(TokenKind::LParen, 1);
      case ')':
        return take(TokenKind::RParen, 1);
      case '{':
        return take(TokenKind::LBrace, 1);
      case '}':
        return take(TokenKind::RBrace, 1);
      case ',':
        return take(TokenKind::Comma, 1);
      case ';':
        return take(TokenKind::Semicolon, 1);
      case ':':
        return d == '=' ? take(TokenKind::Assign, 2) : take(TokenKind::Colon, 1);
      case '.':
        return take(TokenKind::Dot, 1);
      case '!':
        return take(TokenKind::Bang, 1);
      case '+':
        return take(TokenKind::Plus, 1);
      case '-':
        return take(TokenKind::Minus, 1);
      case '*':
        return take(TokenKind::Star, 1);
      case '/':
        if (d == '/') return take(TokenKind::Concat, 2);
        if (d == '=') return take(TokenKind::NotEqual, 2);
        return take(TokenKind::Slash, 1);
      case '=':
        return d == '>' ? take(TokenKind::Arrow, 2) : take(TokenKind::Equal, 1);
      case '<':
        return d == '=' ? take(TokenKind::LessEqual, 2) : take(TokenKind::Less, 1);
      case '>':
        return d == '=' ? take(TokenKind::GreaterEqual, 2) : take(TokenKind::Greater, 1);
      default:
        break;
    }
    const bipc::Location at = here();
    const unsigned char byte = static_cast<unsigned char>(c);
    std::string shown;
    if (byte >= 0x20 && byte < 0x7F) {
      shown = std::string("'") + c + "'";
    } else {
      static const char* const kHex = "0123456789ABCDEF";
      shown = std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 15];
    }
    // A run of unexpected characters is one error.
    while (!at_end() && !is_expected_start(peek())) advance();
    errors_.error(at, "unexpected character " + shown + " (not part of SDL-PR)");
    return false;
  }

  static bool is_expected_start(char c) {
    return is_word_start(c) || is_digit(c) || c == '\'' || c == '"' || c == ' ' || c == '\n' ||
           c == '\t' || c == '\r' ||
           std::string_view("(){},;:.!+-*/=<>").find(c) != std::string_view::npos;
  }

  ErrorBudget& errors_;
};

}  // namespace

std::vector<Token> lex_sdl(std::string_view text, std::uint32_t file, ErrorBudget& errors) {
  std::vector<Token> tokens = Scanner(text, file, errors).run();
  for (Token& token : tokens) {
    if (token.kind != TokenKind::Word) continue;
    token.lower = token.text;
    for (char& c : token.lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return tokens;
}

std::string describe(const Token& token) {
  if (token.kind == TokenKind::EndOfFile) return "end of file";
  if (token.kind == TokenKind::String) {
    // Informal text may run over many lines: a message shows its start.
    constexpr std::size_t kShown = 30;
    if (token.value.size() <= kShown) return "string '" + token.value + "'";
    return "string '" + token.value.substr(0, kShown) + "...'";
  }
  return "'" + token.text + "'";
}

}  // namespace smcbip::taste2bip::sdl::detail
