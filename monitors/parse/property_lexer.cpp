// The lexer of property files: names, numbers with time units, operators and comments.
#include "monitors/parse/property_lexer.h"

#include <array>
#include <charconv>
#include <utility>

namespace smcbip::monitors::detail {

namespace {

bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }

// Longest first, so that `<=>` wins over `<=`, `<=` over `<` and `=?` over `=`.
constexpr std::array<std::string_view, 14> kSymbols = {"<=>", "<->", "<=", ">=", "==", "!=", "&&",
                                                       "||",  "->",  "=>", "=?", "[]", "<>", "-->"};
constexpr std::string_view kOneCharSymbols = "()[]{},;:.!?#+-*/%=<>&|";

}  // namespace

class TokenStream::Lexer {
 public:
  Lexer(std::string_view text, std::uint32_t file, bipc::Diagnostics& diagnostics)
      : text_(text),
        file_(file),
        diagnostics_(diagnostics),
        errors_at_start_(diagnostics.error_count()) {}

  /// The next token; End at the end of the text, or once the file has too many errors to be
  /// worth reading on (a binary file would give one per byte).
  Token next() {
    for (;;) {
      skip_space_and_comments();
      Token token;
      token.at = here();
      if (diagnostics_.error_count() >= errors_at_start_ + kMaxErrors) {
        diagnostics_.error(here(), "too many errors, the rest of the file is not read");
        pos_ = text_.size();
        return token;
      }
      if (pos_ >= text_.size() || lex(token)) return token;
    }
  }

 private:
  bipc::Location here() const { return {file_, line_, column_}; }
  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }
  void advance(std::size_t n = 1) {
    for (std::size_t i = 0; i < n && pos_ < text_.size(); ++i, ++pos_) {
      if (text_[pos_] == '\n') {
        ++line_;
        column_ = 1;
      } else {
        ++column_;
      }
    }
  }

  void skip_space_and_comments() {
    for (;;) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        advance();
      } else if (c == '/' && peek(1) == '/') {
        while (pos_ < text_.size() && peek() != '\n') advance();
      } else if (c == '/' && peek(1) == '*') {
        const bipc::Location start = here();
        advance(2);
        while (pos_ < text_.size() && !(peek() == '*' && peek(1) == '/')) advance();
        if (pos_ >= text_.size()) {
          diagnostics_.error(start, "unterminated comment: expected '*/' before end of file");
          return;
        }
        advance(2);
      } else {
        return;
      }
    }
  }

  // One token into `token`; false when the text there is an error (reported, skipped).
  bool lex(Token& token) {
    const char c = peek();
    if (is_name_start(c)) {
      const std::size_t start = pos_;
      while (is_name_char(peek())) advance();
      token.kind = TokenKind::Name;
      token.text = std::string(text_.substr(start, pos_ - start));
      return true;
    }
    if (is_digit(c)) return number(token);
    if (c == '"') return label(token);
    for (std::string_view symbol : kSymbols) {
      if (text_.substr(pos_, symbol.size()) == symbol) {
        token.kind = TokenKind::Symbol;
        token.text = std::string(symbol);
        advance(symbol.size());
        return true;
      }
    }
    if (kOneCharSymbols.find(c) != std::string_view::npos) {
      token.kind = TokenKind::Symbol;
      token.text = std::string(1, c);
      advance();
      return true;
    }
    const auto byte = static_cast<unsigned char>(c);
    std::string shown = byte >= 0x20 && byte < 0x7F ? std::string("'") + c + "'" : "a byte";
    if (shown == "a byte") {
      constexpr std::string_view kHex = "0123456789ABCDEF";
      shown = std::string("'\\x") + kHex[byte >> 4] + kHex[byte & 0xF] + "'";
    }
    diagnostics_.error(here(), "unexpected character " + shown + " in a property");
    advance();
    return false;
  }

  // A PRISM label, `"deadlock"`: its name, without the quotes, on one line.
  bool label(Token& token) {
    const bipc::Location at = here();
    advance();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && peek() != '"' && peek() != '\n') advance();
    if (peek() != '"') {
      diagnostics_.error(at, "unterminated label: expected '\"' before the end of the line");
      return false;
    }
    token.kind = TokenKind::Label;
    token.text = std::string(text_.substr(start, pos_ - start));
    advance();
    return true;
  }

  // Digits, an optional fraction and exponent, then an optional unit suffix (s, ms, us, ns).
  bool number(Token& token) {
    const std::size_t start = pos_;
    const bipc::Location at = here();
    while (is_digit(peek())) advance();
    bool integral = true;
    if (peek() == '.' && is_digit(peek(1))) {
      integral = false;
      advance();
      while (is_digit(peek())) advance();
    }
    if ((peek() == 'e' || peek() == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      integral = false;
      advance(2);
      while (is_digit(peek())) advance();
    }
    const std::string_view digits = text_.substr(start, pos_ - start);
    const std::size_t suffix_start = pos_;
    while (is_name_char(peek())) advance();
    const std::string_view suffix = text_.substr(suffix_start, pos_ - suffix_start);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size()) {
      diagnostics_.error(at, "number '" + std::string(digits) + "' is out of range");
      return false;
    }
    static constexpr std::array<std::pair<std::string_view, TimeUnit>, 4> kUnits = {
        {{"s", TimeUnit::Seconds},
         {"ms", TimeUnit::Milliseconds},
         {"us", TimeUnit::Microseconds},
         {"ns", TimeUnit::Nanoseconds}}};
    TimeUnit unit = TimeUnit::None;
    if (!suffix.empty()) {
      bool known = false;
      for (const auto& [name, u] : kUnits) {
        if (suffix == name) {
          unit = u;
          known = true;
        }
      }
      // Reported, and the number kept without a unit: the parser goes on without a cascade.
      if (!known) {
        diagnostics_.error(at, "unknown time unit '" + std::string(suffix) + "' after '" +
                                   std::string(digits) + "': expected s, ms, us or ns");
      }
    }
    token.kind = TokenKind::Number;
    token.text = std::string(digits);
    token.number = value;
    token.integral = integral;
    token.unit = unit;
    return true;
  }

  // Enough to show what is wrong with a file; beyond, the errors are the same again.
  static constexpr std::size_t kMaxErrors = 20;

  std::string_view text_;
  std::uint32_t file_;
  bipc::Diagnostics& diagnostics_;
  std::size_t errors_at_start_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1, column_ = 1;
};

TokenStream::TokenStream(std::string_view text, std::uint32_t file, bipc::Diagnostics& diagnostics)
    : lexer_(std::make_unique<Lexer>(text, file, diagnostics)) {}

TokenStream::~TokenStream() = default;

void TokenStream::push_front(Token token) { ahead_.push_front(std::move(token)); }

const Token& TokenStream::peek(std::size_t ahead) {
  while (ahead_.size() <= ahead && (ahead_.empty() || ahead_.back().kind != TokenKind::End)) {
    ahead_.push_back(lexer_->next());
  }
  return ahead < ahead_.size() ? ahead_[ahead] : ahead_.back();
}

const Token& TokenStream::take() {
  peek();
  previous_ = ahead_.front();
  ++taken_;
  if (ahead_.front().kind != TokenKind::End) ahead_.pop_front();
  return previous_;
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::End:
      return "end of file";
    case TokenKind::Name:
      return "name '" + token.text + "'";
    case TokenKind::Number:
      return "number " + token.text;
    case TokenKind::Symbol:
      return "'" + token.text + "'";
    case TokenKind::Label:
      return "label \"" + token.text + "\"";
  }
  return "?";
}

}  // namespace smcbip::monitors::detail
