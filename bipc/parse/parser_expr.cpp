// Parser of expressions (precedence levels of Bip2.g) and of action statements.
#include <algorithm>
#include <array>
#include <utility>

#include "bipc/parse/parser.h"

namespace smcbip::bipc::detail {

namespace {

// The associative operators from the loosest binding: `||` < `&&` < `|` < `^` < `&`.
struct ChainLevel {
  TokenKind token;
  ast::BinaryOp op;
};
constexpr std::array kChainLevels = {
    ChainLevel{TokenKind::OrOr, ast::BinaryOp::Or},
    ChainLevel{TokenKind::AndAnd, ast::BinaryOp::And},
    ChainLevel{TokenKind::Pipe, ast::BinaryOp::BitOr},
    ChainLevel{TokenKind::Caret, ast::BinaryOp::BitXor},
    ChainLevel{TokenKind::Amp, ast::BinaryOp::BitAnd},
};

ast::ExprPtr make_leaf(ast::Expr::Kind kind, Location loc) {
  auto expr = std::make_unique<ast::Expr>();
  expr->kind = kind;
  expr->loc = loc;
  return expr;
}

}  // namespace

ast::ExprPtr Parser::parse_expression() { return parse_logical_chain(0).expr; }

void Parser::check_expression_depth(int depth, Location at) {
  if (depth > kMaxExpressionDepth) {
    fail_at(at, concat({"expression nested too deeply (more than ",
                        std::to_string(kMaxExpressionDepth), " levels)"}));
  }
}

Parser::Parsed Parser::make_binary(ast::BinaryOp op, Location at, Parsed left, Parsed right) {
  Parsed result;
  result.depth = std::max(left.depth, right.depth) + 1;
  check_expression_depth(result.depth, at);
  result.expr = make_leaf(ast::Expr::Kind::Binary, at);
  result.expr->binary = op;
  result.expr->operands.push_back(std::move(left.expr));
  result.expr->operands.push_back(std::move(right.expr));
  return result;
}

Parser::Parsed Parser::parse_logical_chain(int level) {
  if (level == static_cast<int>(kChainLevels.size())) return parse_equality();
  const ChainLevel& chain = kChainLevels[static_cast<std::size_t>(level)];
  Parsed first = parse_logical_chain(level + 1);
  if (!at(chain.token)) return first;
  std::vector<Parsed> operands;
  std::vector<Location> operators;
  operands.push_back(std::move(first));
  while (at(chain.token)) {
    operators.push_back(take().loc);
    operands.push_back(parse_logical_chain(level + 1));
  }
  // Associative: build a balanced tree, so that long generated disjunctions stay shallow.
  auto build = [&](auto& self, std::size_t low, std::size_t high) -> Parsed {
    if (high - low == 1) return std::move(operands[low]);
    std::size_t middle = low + (high - low) / 2;
    Parsed left = self(self, low, middle);
    Parsed right = self(self, middle, high);
    return make_binary(chain.op, operators[middle - 1], std::move(left), std::move(right));
  };
  return build(build, 0, operands.size());
}

Parser::Parsed Parser::parse_equality() {
  Parsed left = parse_relational();
  if (!at(TokenKind::EqEq) && !at(TokenKind::NotEq)) return left;
  ast::BinaryOp op = at(TokenKind::EqEq) ? ast::BinaryOp::Eq : ast::BinaryOp::Ne;
  Location loc = take().loc;
  Parsed right = parse_relational();
  if (at(TokenKind::EqEq) || at(TokenKind::NotEq)) {
    fail_at(peek().loc, "'==' and '!=' do not chain; add parentheses");
  }
  return make_binary(op, loc, std::move(left), std::move(right));
}

Parser::Parsed Parser::parse_relational() {
  auto relational_op = [this]() -> std::optional<ast::BinaryOp> {
    switch (kind()) {
      case TokenKind::Lt:
        return ast::BinaryOp::Lt;
      case TokenKind::Gt:
        return ast::BinaryOp::Gt;
      case TokenKind::Le:
        return ast::BinaryOp::Le;
      case TokenKind::Ge:
        return ast::BinaryOp::Ge;
      default:
        return std::nullopt;
    }
  };
  Parsed left = parse_additive();
  std::optional<ast::BinaryOp> op = relational_op();
  if (!op) return left;
  Location loc = take().loc;
  Parsed right = parse_additive();
  if (relational_op()) fail_at(peek().loc, "'<', '>', '<=' and '>=' do not chain; add parentheses");
  return make_binary(*op, loc, std::move(left), std::move(right));
}

Parser::Parsed Parser::parse_additive() {
  Parsed left = parse_multiplicative();
  while (at(TokenKind::Plus) || at(TokenKind::Minus)) {
    ast::BinaryOp op = at(TokenKind::Plus) ? ast::BinaryOp::Add : ast::BinaryOp::Sub;
    Location loc = take().loc;
    Parsed right = parse_multiplicative();
    left = make_binary(op, loc, std::move(left), std::move(right));
  }
  return left;
}

Parser::Parsed Parser::parse_multiplicative() {
  Parsed left = parse_unary();
  for (;;) {
    ast::BinaryOp op;
    if (at(TokenKind::Star))
      op = ast::BinaryOp::Mul;
    else if (at(TokenKind::Slash))
      op = ast::BinaryOp::Div;
    else if (at(TokenKind::Percent))
      op = ast::BinaryOp::Mod;
    else
      return left;
    Location loc = take().loc;
    Parsed right = parse_unary();
    left = make_binary(op, loc, std::move(left), std::move(right));
  }
}

Parser::Parsed Parser::parse_unary() {
  ast::UnaryOp op;
  switch (kind()) {
    case TokenKind::Minus:
      op = ast::UnaryOp::Minus;
      break;
    case TokenKind::Plus:
      op = ast::UnaryOp::Plus;
      break;
    case TokenKind::Not:
      op = ast::UnaryOp::Not;
      break;
    case TokenKind::Tilde:
      op = ast::UnaryOp::BitNot;
      break;
    default:
      return parse_postfix();
  }
  DepthGuard guard(*this);
  Location loc = take().loc;
  Parsed operand = parse_unary();
  Parsed result;
  result.depth = operand.depth + 1;
  check_expression_depth(result.depth, loc);
  result.expr = make_leaf(ast::Expr::Kind::Unary, loc);
  result.expr->unary = op;
  result.expr->operands.push_back(std::move(operand.expr));
  return result;
}

Parser::Parsed Parser::parse_postfix() {
  Parsed primary = parse_primary();
  if (!at(TokenKind::Quote)) return primary;
  Location quote = take().loc;
  Parsed result;
  result.depth = primary.depth + 1;
  check_expression_depth(result.depth, quote);
  result.expr = make_leaf(ast::Expr::Kind::Prime, primary.expr->loc);
  result.expr->operands.push_back(std::move(primary.expr));
  return result;
}

Parser::Parsed Parser::parse_call_arguments(ast::QualifiedName name) {
  DepthGuard guard(*this);
  Parsed call;
  call.expr = make_leaf(ast::Expr::Kind::Call, name.loc());
  call.expr->name = std::move(name);
  take();  // `(`
  if (!accept(TokenKind::RParen)) {
    do {
      Parsed argument = parse_logical_chain(0);
      call.depth = std::max(call.depth, argument.depth + 1);
      check_expression_depth(call.depth, call.expr->loc);
      call.expr->operands.push_back(std::move(argument.expr));
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RParen, concat({"to close the arguments of '", call.expr->name.text(), "'"}));
  }
  return call;
}

Parser::Parsed Parser::parse_primary() {
  const Token& token = peek();
  Parsed result;
  switch (token.kind) {
    case TokenKind::Int:
      result.expr = make_leaf(ast::Expr::Kind::Int, token.loc);
      result.expr->int_value = token.int_value;
      take();
      return result;
    case TokenKind::Float:
      result.expr = make_leaf(ast::Expr::Kind::Float, token.loc);
      result.expr->float_value = token.float_value;
      take();
      return result;
    case TokenKind::String:
      result.expr = make_leaf(ast::Expr::Kind::String, token.loc);
      result.expr->string_value = take().string_value;
      return result;
    case TokenKind::KwTrue:
    case TokenKind::KwFalse:
      result.expr = make_leaf(ast::Expr::Kind::Bool, token.loc);
      result.expr->bool_value = token.kind == TokenKind::KwTrue;
      take();
      return result;
    case TokenKind::LParen: {
      DepthGuard guard(*this);
      take();
      result = parse_logical_chain(0);
      expect(TokenKind::RParen, "to close '('");
      return result;
    }
    default:
      break;
  }
  if (!at_name()) fail("an expression");
  ast::QualifiedName name = parse_qualified_name("a name");
  if (at(TokenKind::LParen)) return parse_call_arguments(std::move(name));
  result.expr = make_leaf(ast::Expr::Kind::Name, name.loc());
  result.expr->name = std::move(name);
  return result;
}

// ---------------------------------------------------------------------------------------------
// Statements

bool Parser::at_statement_start() {
  switch (kind()) {
    case TokenKind::KwIf:
    case TokenKind::Int:
    case TokenKind::Float:
    case TokenKind::String:
    case TokenKind::KwTrue:
    case TokenKind::KwFalse:
    case TokenKind::LParen:
      return true;
    default:
      return at_name();
  }
}

ast::Block Parser::parse_block(std::string_view context) {
  ast::Block block;
  expect(TokenKind::LBrace, context);
  while (!accept(TokenKind::RBrace)) parse_statement(block, "a statement or '}'");
  return block;
}

void Parser::parse_statement(ast::Block& block, std::string_view expected) {
  if (!at_statement_start()) fail(expected);
  if (at(TokenKind::KwIf)) {
    block.push_back(parse_if());
    return;
  }
  auto statement = std::make_unique<ast::Statement>();
  statement->loc = peek().loc;
  Parsed target = parse_postfix();
  if (accept(TokenKind::Assign)) {
    statement->kind = ast::Statement::Kind::Assign;
    statement->target = std::move(target.expr);
    statement->value = parse_expression();
  } else if (target.expr->kind == ast::Expr::Kind::Call) {
    statement->kind = ast::Statement::Kind::Call;
    statement->value = std::move(target.expr);
  } else {
    fail("'=' (a statement is an assignment or a function call)");
  }
  expect(TokenKind::Semicolon, "after the statement");
  block.push_back(std::move(statement));
}

ast::StatementPtr Parser::parse_if() {
  DepthGuard guard(*this);
  auto statement = std::make_unique<ast::Statement>();
  statement->kind = ast::Statement::Kind::If;
  statement->loc = take().loc;  // `if`
  expect(TokenKind::LParen, "after 'if'");
  statement->value = parse_expression();
  expect(TokenKind::RParen, "to close the condition of 'if'");
  expect(TokenKind::KwThen, "after the condition of 'if'");
  parse_statement(statement->then_branch, "a statement after 'then'");
  while (!at(TokenKind::KwElse) && !at(TokenKind::KwFi)) {
    parse_statement(statement->then_branch, "a statement, 'else' or 'fi'");
  }
  if (accept(TokenKind::KwElse)) {
    parse_statement(statement->else_branch, "a statement after 'else'");
    while (!at(TokenKind::KwFi)) parse_statement(statement->else_branch, "a statement or 'fi'");
  }
  take();  // `fi`
  return statement;
}

}  // namespace smcbip::bipc::detail
