// SDL-PR parser: reading tokens, reporting located errors and recovering from them.
#include <string>

#include "taste2bip/sdl/detail/sdl_parser.h"

namespace smcbip::taste2bip::sdl {

const char* spelling(Operator op) {
  switch (op) {
    case Operator::None:
      return "";
    case Operator::Negate:
      return "-";
    case Operator::Not:
      return "not";
    case Operator::Plus:
      return "+";
    case Operator::Minus:
      return "-";
    case Operator::Times:
      return "*";
    case Operator::Divide:
      return "/";
    case Operator::Mod:
      return "mod";
    case Operator::Rem:
      return "rem";
    case Operator::Concat:
      return "//";
    case Operator::Equal:
      return "=";
    case Operator::NotEqual:
      return "/=";
    case Operator::Less:
      return "<";
    case Operator::LessEqual:
      return "<=";
    case Operator::Greater:
      return ">";
    case Operator::GreaterEqual:
      return ">=";
    case Operator::In:
      return "in";
    case Operator::And:
      return "and";
    case Operator::Or:
      return "or";
    case Operator::Xor:
      return "xor";
    case Operator::Implies:
      return "implies";
    case Operator::AndThen:
      return "and then";
    case Operator::OrElse:
      return "or else";
  }
  return "";
}

}  // namespace smcbip::taste2bip::sdl

namespace smcbip::taste2bip::sdl::detail {

Operator comparison_operator(TokenKind kind) {
  switch (kind) {
    case TokenKind::Equal:
      return Operator::Equal;
    case TokenKind::NotEqual:
      return Operator::NotEqual;
    case TokenKind::Less:
      return Operator::Less;
    case TokenKind::LessEqual:
      return Operator::LessEqual;
    case TokenKind::Greater:
      return Operator::Greater;
    case TokenKind::GreaterEqual:
      return Operator::GreaterEqual;
    default:
      return Operator::None;
  }
}

bool is_reserved(std::string_view lower) {
  // Words that open, close or join constructs; everything else may name something.
  static constexpr std::string_view kReserved =
      " and block call channel comment connect connection dcl decision else endblock endchannel"
      " endconnection enddecision endfor endprocedure endprocess endstate endsubstructure"
      " endsystem external fi for fpar if implies input join mod nextstate not or output"
      " procedure process provided rem return returns save signal signalroute start state stop"
      " substructure system task then timer use xor ";
  return !lower.empty() && kReserved.find(" " + std::string(lower) + " ") != std::string_view::npos;
}

Parser::Nesting::Nesting(Parser& parser) : parser_(parser) {
  if (++parser_.depth_ > kMaxNesting && !parser_.stopped_) {
    parser_.error_here("nesting deeper than " + std::to_string(kMaxNesting) +
                       " levels; reading stopped");
    parser_.stopped_ = true;
  }
}

const Token& Parser::peek(std::size_t k) const {
  if (stopped()) return tokens_.back();
  const std::size_t at = pos_ + k;
  return at < tokens_.size() ? tokens_[at] : tokens_.back();
}

bool Parser::at_word(std::string_view keyword, std::size_t k) const {
  const Token& token = peek(k);
  return token.kind == TokenKind::Word && token.lower == keyword;
}

bool Parser::at_name(std::size_t k) const {
  const Token& token = peek(k);
  return token.kind == TokenKind::Word && !is_reserved(token.lower);
}

Token Parser::take() {
  Token token = peek();
  if (!stopped() && pos_ + 1 < tokens_.size()) ++pos_;
  return token;
}

bool Parser::accept(TokenKind kind) {
  if (!at(kind)) return false;
  take();
  return true;
}

bool Parser::accept_word(std::string_view keyword) {
  if (!at_word(keyword)) return false;
  take();
  return true;
}

void Parser::error_here(std::string message) {
  // Past a nesting too deep, or at an end of file an unterminated comment or string reached,
  // what is missing is a consequence of the error already reported.
  if (stopped_ || (at_eof() && errors_.ran_off_end())) return;
  errors_.error(peek().at, std::move(message));
}

bool Parser::at_unsupported() const {
  // Constructs of SDL (Z.100) that OpenGEODE's inputs do not use and this reader does not read.
  static constexpr std::string_view kUnsupported =
      " alternative channelsubstructure create export exported gate import imported macro"
      " newtype operator package remote service signallist synonym syntype ";
  const Token& token = peek();
  return token.kind == TokenKind::Word &&
         kUnsupported.find(" " + token.lower + " ") != std::string_view::npos;
}

void Parser::error_unexpected(const std::string& expected) {
  if (at_unsupported()) {
    error_here("'" + peek().text + "' is not supported by this reader (expected " + expected + ")");
    return;
  }
  error_here("expected " + expected + ", got " + describe(peek()));
}

namespace {

std::string_view kind_spelling(TokenKind kind) {
  switch (kind) {
    case TokenKind::LParen:
      return "'('";
    case TokenKind::RParen:
      return "')'";
    case TokenKind::LBrace:
      return "'{'";
    case TokenKind::RBrace:
      return "'}'";
    case TokenKind::Comma:
      return "','";
    case TokenKind::Semicolon:
      return "';'";
    case TokenKind::Colon:
      return "':'";
    case TokenKind::Assign:
      return "':='";
    case TokenKind::Integer:
      return "an integer";
    case TokenKind::String:
      return "a string";
    default:
      return "a symbol";
  }
}

}  // namespace

bool Parser::expect(TokenKind kind, std::string_view context) {
  if (accept(kind)) return true;
  if (!stopped()) {
    error_here("expected " + std::string(kind_spelling(kind)) + " " + std::string(context) +
               ", got " + describe(peek()));
  }
  return false;
}

bool Parser::expect_word(std::string_view keyword, std::string_view context) {
  if (accept_word(keyword)) return true;
  if (!stopped()) {
    error_here("expected '" + std::string(keyword) + "' " + std::string(context) + ", got " +
               describe(peek()));
  }
  return false;
}

std::optional<std::string> Parser::expect_name(std::string_view what) {
  if (at_name()) return take().text;
  if (!stopped()) error_here("expected " + std::string(what) + ", got " + describe(peek()));
  return std::nullopt;
}

void Parser::skip_past_semicolon() {
  while (!at_eof()) {
    if (take().kind == TokenKind::Semicolon) return;
  }
}

std::string Parser::parse_comment() {
  if (at_word("comment") && at(TokenKind::String, 1)) {
    take();
    return take().value;
  }
  return {};
}

bool Parser::end_statement(std::string_view what) {
  if (accept(TokenKind::Semicolon)) return true;
  if (!stopped()) {
    error_here("expected ';' after " + std::string(what) + ", got " + describe(peek()));
  }
  // Resume at the next ';' or at a keyword that opens or closes a construct, whichever is first.
  while (!at_eof() && !(at(TokenKind::Word) && is_reserved(peek().lower))) {
    if (take().kind == TokenKind::Semicolon) break;
  }
  return false;
}

void Parser::parse_end() {
  const Token end = take();  // the keyword itself
  if (at_name()) take();
  end_statement("'" + end.text + "'");
}

}  // namespace smcbip::taste2bip::sdl::detail
