// SDL-PR parser: expressions, with the precedence of OpenGEODE's grammar (sdl92.g): implies,
// then or/or else/xor, and/and then, comparisons and in, + - //, * / mod rem, unary not and -.
#include "taste2bip/sdl/detail/sdl_parser.h"

namespace smcbip::taste2bip::sdl::detail {

namespace {

Expr make(Expr::Kind kind, Location at, std::string text = {}) {
  Expr expr;
  expr.kind = kind;
  expr.at = at;
  expr.text = std::move(text);
  return expr;
}

}  // namespace

Expr Parser::parse_expression() {
  Nesting nesting(*this);
  return parse_binary(0);
}

// Levels: 0 implies, 1 or/or else/xor, 2 and/and then, 3 comparisons and in, 4 + - //,
// 5 * / mod rem.
Expr Parser::parse_binary(int level) {
  if (level > 5) return parse_unary();
  Expr left = parse_binary(level + 1);
  for (;;) {
    const Token& token = peek();
    Operator op = Operator::None;
    std::size_t length = 1;
    const std::string& w = token.lower;
    const bool word = token.kind == TokenKind::Word;
    switch (level) {
      case 0:
        if ((word && w == "implies") || token.kind == TokenKind::Arrow) op = Operator::Implies;
        break;
      case 1:
        if (word && w == "or") {
          op = at_word("else", 1) ? Operator::OrElse : Operator::Or;
          length = op == Operator::OrElse ? 2 : 1;
        } else if (word && w == "xor") {
          op = Operator::Xor;
        }
        break;
      case 2:
        if (word && w == "and") {
          op = at_word("then", 1) ? Operator::AndThen : Operator::And;
          length = op == Operator::AndThen ? 2 : 1;
        }
        break;
      case 3:
        op = comparison_operator(token.kind);
        if (op == Operator::None && word && w == "in") op = Operator::In;
        break;
      case 4:
        if (token.kind == TokenKind::Plus) op = Operator::Plus;
        if (token.kind == TokenKind::Minus) op = Operator::Minus;
        if (token.kind == TokenKind::Concat) op = Operator::Concat;
        break;
      default:
        if (token.kind == TokenKind::Star) op = Operator::Times;
        if (token.kind == TokenKind::Slash) op = Operator::Divide;
        if (word && w == "mod") op = Operator::Mod;
        if (word && w == "rem") op = Operator::Rem;
        break;
    }
    if (op == Operator::None || stopped()) return left;
    Expr binary = make(Expr::Kind::Binary, token.at);
    binary.op = op;
    for (std::size_t i = 0; i < length; ++i) take();
    binary.operands.push_back(std::move(left));
    binary.operands.push_back(parse_binary(level + 1));
    left = std::move(binary);
  }
}

Expr Parser::parse_unary() {
  if (at_word("not") || at(TokenKind::Minus)) {
    Nesting nesting(*this);
    Expr unary = make(Expr::Kind::Unary, peek().at);
    unary.op = at(TokenKind::Minus) ? Operator::Negate : Operator::Not;
    take();
    unary.operands.push_back(parse_unary());
    return unary;
  }
  return parse_postfix(true);
}

Expr Parser::parse_postfix(bool allow_choice) {
  Expr expr = parse_primary(allow_choice);
  for (;;) {
    if (at(TokenKind::LParen)) {
      Expr call = make(Expr::Kind::Call, expr.at);
      call.operands.push_back(std::move(expr));
      for (Expr& argument : parse_arguments()) call.operands.push_back(std::move(argument));
      expr = std::move(call);
    } else if (at(TokenKind::Dot) || at(TokenKind::Bang)) {
      take();
      Expr field = make(Expr::Kind::Field, expr.at);
      if (auto name = expect_name("a field name after '.' or '!'")) field.text = *name;
      field.operands.push_back(std::move(expr));
      expr = std::move(field);
    } else {
      return expr;
    }
  }
}

Expr Parser::parse_primary(bool allow_choice) {
  const Token& token = peek();
  const Location where = token.at;
  switch (token.kind) {
    case TokenKind::Integer:
      return make(Expr::Kind::Integer, where, take().text);
    case TokenKind::Real:
      return make(Expr::Kind::Real, where, take().text);
    case TokenKind::String:
      return make(Expr::Kind::String, where, take().value);
    case TokenKind::BitString:
      return make(Expr::Kind::BitString, where, take().value);
    case TokenKind::OctetString:
      return make(Expr::Kind::OctetString, where, take().value);
    case TokenKind::LParen: {
      Nesting nesting(*this);
      take();
      Expr inner = parse_expression();
      expect(TokenKind::RParen, "closing '('");
      return inner;
    }
    case TokenKind::LBrace:
      return parse_sequence_value();
    case TokenKind::Word:
      if (token.lower == "true" || token.lower == "false") {
        return make(Expr::Kind::Boolean, where, take().lower);
      }
      if (token.lower == "plus-infinity" || token.lower == "minus-infinity") {
        return make(Expr::Kind::Real, where, take().lower);
      }
      if (token.lower == "if") return parse_conditional();
      if (token.lower == "call" && at_name(1)) {
        take();
        Expr call = make(Expr::Kind::ProcedureCall, where);
        call.operands.push_back(make(Expr::Kind::Name, peek().at, take().text));
        for (Expr& argument : parse_arguments()) call.operands.push_back(std::move(argument));
        return call;
      }
      if (at_name()) {
        std::string name = take().text;
        if (allow_choice && at(TokenKind::Colon)) {
          take();
          Nesting nesting(*this);
          Expr choice = make(Expr::Kind::Choice, where, std::move(name));
          choice.operands.push_back(parse_expression());
          return choice;
        }
        return make(Expr::Kind::Name, where, std::move(name));
      }
      break;
    default:
      break;
  }
  if (!stopped()) error_here("expected an expression, got " + describe(token));
  return make(Expr::Kind::Name, where);
}

Expr Parser::parse_sequence_value() {
  Nesting nesting(*this);
  Expr sequence = make(Expr::Kind::Sequence, take().at);
  if (accept(TokenKind::RBrace)) return sequence;
  do {
    // `{a 1, b 2}` names its components; `{1, 2}` and `{hello, world}` do not.
    std::string field;
    if (at_name()) {
      const Token& next = peek(1);
      const bool value_follows =
          next.kind == TokenKind::Integer || next.kind == TokenKind::Real ||
          next.kind == TokenKind::String || next.kind == TokenKind::LBrace ||
          next.kind == TokenKind::Minus ||
          (next.kind == TokenKind::Word && (!is_reserved(next.lower) || next.lower == "if" ||
                                            next.lower == "not" || next.lower == "call"));
      if (value_follows) field = take().text;
    }
    sequence.field_names.push_back(std::move(field));
    sequence.operands.push_back(parse_expression());
  } while (accept(TokenKind::Comma));
  expect(TokenKind::RBrace, "closing '{'");
  return sequence;
}

Expr Parser::parse_conditional() {
  Nesting nesting(*this);
  Expr conditional = make(Expr::Kind::Conditional, take().at);
  conditional.operands.push_back(parse_expression());
  expect_word("then", "after the condition of 'if'");
  conditional.operands.push_back(parse_expression());
  expect_word("else", "after 'if ... then ...'");
  conditional.operands.push_back(parse_expression());
  expect_word("fi", "closing 'if ... then ... else ...'");
  return conditional;
}

}  // namespace smcbip::taste2bip::sdl::detail
