// Tests of expression precedence and action statements as the BIP2 parser builds them.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "bipc/bipc.h"

namespace smcbip::bipc {
namespace {

const char* binary_name(ast::BinaryOp op) {
  switch (op) {
    case ast::BinaryOp::Or:
      return "||";
    case ast::BinaryOp::And:
      return "&&";
    case ast::BinaryOp::BitOr:
      return "|";
    case ast::BinaryOp::BitXor:
      return "^";
    case ast::BinaryOp::BitAnd:
      return "&";
    case ast::BinaryOp::Eq:
      return "==";
    case ast::BinaryOp::Ne:
      return "!=";
    case ast::BinaryOp::Lt:
      return "<";
    case ast::BinaryOp::Gt:
      return ">";
    case ast::BinaryOp::Le:
      return "<=";
    case ast::BinaryOp::Ge:
      return ">=";
    case ast::BinaryOp::Add:
      return "+";
    case ast::BinaryOp::Sub:
      return "-";
    case ast::BinaryOp::Mul:
      return "*";
    case ast::BinaryOp::Div:
      return "/";
    case ast::BinaryOp::Mod:
      return "%";
  }
  return "?";
}

const char* unary_name(ast::UnaryOp op) {
  switch (op) {
    case ast::UnaryOp::Minus:
      return "-";
    case ast::UnaryOp::Plus:
      return "+";
    case ast::UnaryOp::Not:
      return "!";
    case ast::UnaryOp::BitNot:
      return "~";
  }
  return "?";
}

// A fully parenthesised prefix form, e.g. `(+ a (* b c))`.
std::string dump(const ast::Expr& e) {
  std::ostringstream out;
  switch (e.kind) {
    case ast::Expr::Kind::Int:
      out << e.int_value;
      break;
    case ast::Expr::Kind::Float:
      out << e.float_value;
      break;
    case ast::Expr::Kind::String:
      out << '"' << e.string_value << '"';
      break;
    case ast::Expr::Kind::Bool:
      out << (e.bool_value ? "true" : "false");
      break;
    case ast::Expr::Kind::Name:
      out << e.name.text();
      break;
    case ast::Expr::Kind::Call:
      out << "(call " << e.name.text();
      for (const ast::ExprPtr& arg : e.operands) out << ' ' << dump(*arg);
      out << ')';
      break;
    case ast::Expr::Kind::Unary:
      out << '(' << unary_name(e.unary) << ' ' << dump(*e.operands[0]) << ')';
      break;
    case ast::Expr::Kind::Binary:
      out << '(' << binary_name(e.binary) << ' ' << dump(*e.operands[0]) << ' '
          << dump(*e.operands[1]) << ')';
      break;
    case ast::Expr::Kind::Prime:
      out << "(' " << dump(*e.operands[0]) << ')';
      break;
  }
  return out.str();
}

std::string parse_expr(const std::string& text) {
  Diagnostics diags;
  auto package = parse_package("package p const data int K = " + text + " end", 0, diags);
  if (diags.has_errors()) return "error: " + diags.all()[0].message;
  return dump(*package->consts.at(0).value);
}

TEST(ParseExpr, Literals) {
  EXPECT_EQ(parse_expr("42"), "42");
  EXPECT_EQ(parse_expr("2.5"), "2.5");
  EXPECT_EQ(parse_expr("\"s\\n\""), "\"s\n\"");
  EXPECT_EQ(parse_expr("true"), "true");
  EXPECT_EQ(parse_expr("false"), "false");
  EXPECT_EQ(parse_expr("a.b.c"), "a.b.c");
  EXPECT_EQ(parse_expr("pkg.f(1, x.y, g())"), "(call pkg.f 1 x.y (call g))");
}

TEST(ParseExpr, Precedence) {
  EXPECT_EQ(parse_expr("a || b && c"), "(|| a (&& b c))");
  EXPECT_EQ(parse_expr("a && b || c"), "(|| (&& a b) c)");
  EXPECT_EQ(parse_expr("a | b ^ c & d == e < f + g * h"),
            "(| a (^ b (& c (== d (< e (+ f (* g h)))))))");
  EXPECT_EQ(parse_expr("a * b + c"), "(+ (* a b) c)");
  EXPECT_EQ(parse_expr("a < b == c > d"), "(== (< a b) (> c d))");
  EXPECT_EQ(parse_expr("-a * b"), "(* (- a) b)");
  EXPECT_EQ(parse_expr("!a && ~b"), "(&& (! a) (~ b))");
  EXPECT_EQ(parse_expr("+a - -b"), "(- (+ a) (- b))");
  EXPECT_EQ(parse_expr("(a + b) * c"), "(* (+ a b) c)");
  EXPECT_EQ(parse_expr("-x'"), "(- (' x))");
  EXPECT_EQ(parse_expr("a != b"), "(!= a b)");
  EXPECT_EQ(parse_expr("a >= b"), "(>= a b)");
  EXPECT_EQ(parse_expr("a <= b % c"), "(<= a (% b c))");
}

TEST(ParseExpr, ArithmeticIsLeftAssociative) {
  EXPECT_EQ(parse_expr("a - b - c"), "(- (- a b) c)");
  EXPECT_EQ(parse_expr("a / b * c % d"), "(% (* (/ a b) c) d)");
  EXPECT_EQ(parse_expr("a + b - c + d"), "(+ (- (+ a b) c) d)");
}

TEST(ParseExpr, AssociativeChainsKeepOperandOrder) {
  // Any tree is fine for associative operators; the operands stay in order.
  EXPECT_EQ(parse_expr("a || b || c || d"), "(|| (|| a b) (|| c d))");
  EXPECT_EQ(parse_expr("a & b & c"), "(& a (& b c))");
}

TEST(ParseExpr, ComparisonsDoNotChain) {
  EXPECT_EQ(parse_expr("a == b == c"), "error: '==' and '!=' do not chain; add parentheses");
  EXPECT_EQ(parse_expr("a < b < c"),
            "error: '<', '>', '<=' and '>=' do not chain; add parentheses");
  EXPECT_EQ(parse_expr("(a == b) == c"), "(== (== a b) c)");
}

TEST(ParseExpr, LocationsPointAtOperatorsAndNames) {
  Diagnostics diags;
  auto package = parse_package("package p const data int K = a +\n  f(b) end", 0, diags);
  const ast::Expr& sum = *package->consts.at(0).value;
  EXPECT_EQ(sum.loc.line, 1u);
  EXPECT_EQ(sum.loc.column, 32u);
  EXPECT_EQ(sum.operands[0]->loc.column, 30u);
  EXPECT_EQ(sum.operands[1]->loc.line, 2u);
  EXPECT_EQ(sum.operands[1]->loc.column, 3u);
}

ast::Block parse_action(const std::string& body, Diagnostics& diags) {
  auto package = parse_package(
      "package p atom type A() place s initial to s do {" + body + "} end end", 0, diags);
  if (package->atom_types.empty()) return {};
  return std::move(package->atom_types[0].initial.action);
}

TEST(ParseExpr, Statements) {
  Diagnostics diags;
  ast::Block block = parse_action(
      "x = 1 + y; f(a, b); x' = 2.0; p.q = r;"
      "if (x > 0) then y = 1; if (z) then g(); fi else y = 2; z = 3; fi "
      "if (c) then h(); fi",
      diags);
  ASSERT_FALSE(diags.has_errors()) << diags.format(SourceFiles{});
  ASSERT_EQ(block.size(), 6u);
  EXPECT_EQ(block[0]->kind, ast::Statement::Kind::Assign);
  EXPECT_EQ(dump(*block[0]->target), "x");
  EXPECT_EQ(dump(*block[0]->value), "(+ 1 y)");
  EXPECT_EQ(block[1]->kind, ast::Statement::Kind::Call);
  EXPECT_EQ(dump(*block[1]->value), "(call f a b)");
  EXPECT_EQ(block[2]->kind, ast::Statement::Kind::Assign);
  EXPECT_EQ(block[2]->target->kind, ast::Expr::Kind::Prime);
  EXPECT_EQ(dump(*block[2]->target), "(' x)");
  EXPECT_EQ(dump(*block[3]->target), "p.q");
  const ast::Statement& branch = *block[4];
  EXPECT_EQ(branch.kind, ast::Statement::Kind::If);
  EXPECT_EQ(dump(*branch.value), "(> x 0)");
  ASSERT_EQ(branch.then_branch.size(), 2u);
  EXPECT_EQ(branch.then_branch[1]->kind, ast::Statement::Kind::If);
  EXPECT_EQ(branch.else_branch.size(), 2u);
  EXPECT_TRUE(block[5]->else_branch.empty());
}

TEST(ParseExpr, StatementErrors) {
  {
    Diagnostics diags;
    parse_action("x + 1;", diags);
    ASSERT_TRUE(diags.has_errors());
    EXPECT_EQ(diags.all()[0].message,
              "expected '=' (a statement is an assignment or a function call), got '+'");
  }
  {
    Diagnostics diags;
    parse_action("x = 1 y = 2;", diags);
    EXPECT_EQ(diags.all().at(0).message, "expected ';' after the statement, got 'y'");
  }
  {
    Diagnostics diags;
    parse_action("if (x) then fi", diags);
    EXPECT_EQ(diags.all().at(0).message, "expected a statement after 'then', got 'fi'");
  }
  {
    Diagnostics diags;
    parse_action("if (x) then y = 1; fi;", diags);
    EXPECT_EQ(diags.all().at(0).message, "expected a statement or '}', got ';'");
  }
}

}  // namespace
}  // namespace smcbip::bipc
