// The lexer of the AADL subset TASTE writes for interface views, with located errors.
#include <cctype>

#include "taste2bip/detail/text_cursor.h"
#include "taste2bip/interface_view/detail/aadl_syntax.h"

namespace smcbip::taste2bip::detail {

void AadlErrors::error(bipc::Location at, std::string message) {
  if (exhausted()) return;
  ++count_;
  if (exhausted()) {
    diags_.error(at, "too many errors (" + std::to_string(kMaxErrors) +
                         "); the rest of the file "
                         "is not read");
    return;
  }
  diags_.error(at, std::move(message));
}

std::string aadl_key(std::string_view name) {
  std::string key(name);
  for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return key;
}

namespace {

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

class Lexer : private taste2bip::detail::TextCursor {
 public:
  Lexer(std::string_view text, std::uint32_t file, AadlErrors& errors)
      : TextCursor(text, file), errors_(errors) {}

  std::vector<AadlToken> run() {
    std::vector<AadlToken> tokens;
    while (!errors_.exhausted()) {
      skip_blanks();
      if (pos_ >= text_.size()) break;
      const bipc::Location at = here();
      const char c = text_[pos_];
      if (is_letter(c)) {
        tokens.push_back({AadlTokenKind::Identifier, take_while_word(), at});
      } else if (is_digit(c)) {
        tokens.push_back({AadlTokenKind::Number, take_number(), at});
      } else if (c == '"') {
        std::string text;
        take_string(text);  // an unterminated string is reported and kept as it stands
        tokens.push_back({AadlTokenKind::String, std::move(text), at});
      } else if (!take_symbol(tokens, at)) {
        // A run of unexpected bytes (1 MB of NULs) is one error.
        advance();  // always: a lone '=' or '<' must not stall the lexer
        std::size_t count = 1;
        while (pos_ < text_.size() && is_unexpected(text_[pos_])) {
          advance();
          ++count;
        }
        errors_.error(at, "unexpected character " + describe(c) +
                              (count > 1 ? " (and " + std::to_string(count - 1) + " more)" : "") +
                              ": expected an AADL identifier, number, string or symbol");
      }
    }
    tokens.push_back({AadlTokenKind::EndOfFile, "", here()});
    return tokens;
  }

 private:
  static std::string describe(char c) {
    if (std::isprint(static_cast<unsigned char>(c)) != 0) return std::string("'") + c + "'";
    static const char* const kHex = "0123456789abcdef";
    const auto byte = static_cast<unsigned char>(c);
    return std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 15];
  }

  static bool is_unexpected(char c) {
    static constexpr std::string_view kStarts = "\":;=+-<{}()[],.* \t\r\n\f\v";
    return !is_letter(c) && !is_digit(c) && kStarts.find(c) == std::string_view::npos;
  }


  void skip_blanks() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '-' && peek(1) == '-') {
        while (pos_ < text_.size() && text_[pos_] != '\n') advance();
      } else {
        break;
      }
    }
  }

  std::string take_while_word() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (is_letter(text_[pos_]) || is_digit(text_[pos_]) || text_[pos_] == '_'))
      advance();
    return std::string(text_.substr(start, pos_ - start));
  }

  std::string take_number() {
    const std::size_t start = pos_;
    auto digits = [&] {
      while (pos_ < text_.size() && (is_digit(text_[pos_]) || text_[pos_] == '_')) advance();
    };
    digits();
    // `0 .. 10` and `0..10` are ranges: a '.' is a decimal point only before a digit.
    if (peek(0) == '.' && is_digit(peek(1))) {
      advance();
      digits();
    }
    if ((peek(0) == 'e' || peek(0) == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      advance();
      if (!is_digit(peek(0))) advance();
      digits();
    }
    return std::string(text_.substr(start, pos_ - start));
  }

  void take_string(std::string& out) {
    const bipc::Location at = here();
    advance();
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') break;
      advance();
      if (c == '"') {
        if (peek(0) != '"') return;
        advance();  // "" is a quote inside the string
      }
      out += c;
    }
    errors_.error(at, "unterminated string: expected '\"' before the end of the line");
  }

  bool take_symbol(std::vector<AadlToken>& tokens, bipc::Location at) {
    struct Symbol {
      std::string_view text;
      AadlTokenKind kind;
    };
    // Longest first.
    static constexpr Symbol kSymbols[] = {
        {"<->", AadlTokenKind::BiConnect},  {"+=>", AadlTokenKind::AddAssociate},
        {"::", AadlTokenKind::DoubleColon}, {"=>", AadlTokenKind::Associate},
        {"->", AadlTokenKind::Connect},     {"..", AadlTokenKind::DotDot},
        {":", AadlTokenKind::Colon},        {";", AadlTokenKind::Semicolon},
        {"{", AadlTokenKind::LeftBrace},    {"}", AadlTokenKind::RightBrace},
        {"(", AadlTokenKind::LeftParen},    {")", AadlTokenKind::RightParen},
        {"[", AadlTokenKind::LeftBracket},  {"]", AadlTokenKind::RightBracket},
        {",", AadlTokenKind::Comma},        {".", AadlTokenKind::Dot},
        {"+", AadlTokenKind::Plus},         {"-", AadlTokenKind::Minus},
        {"*", AadlTokenKind::Star},
    };
    for (const Symbol& symbol : kSymbols) {
      if (text_.substr(pos_, symbol.text.size()) == symbol.text) {
        for (std::size_t i = 0; i < symbol.text.size(); ++i) advance();
        tokens.push_back({symbol.kind, std::string(symbol.text), at});
        return true;
      }
    }
    return false;
  }

  AadlErrors& errors_;
};

}  // namespace

std::vector<AadlToken> lex_aadl(std::string_view text, std::uint32_t file, AadlErrors& errors) {
  return Lexer(text, file, errors).run();
}

}  // namespace smcbip::taste2bip::detail
