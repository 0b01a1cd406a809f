// Parser core: token access, `expected X, got Y` errors, recovery, names, types, annotations.
#include "bipc/parse/parser.h"

#include <utility>

#include "bipc/bipc.h"

namespace smcbip::bipc {

namespace detail {

Parser::DepthGuard::DepthGuard(Parser& parser) : parser_(parser) {
  if (++parser_.depth_ > kMaxNestingDepth) {
    --parser_.depth_;
    parser_.fail_at(parser_.peek().loc, concat({"nesting too deep (more than ",
                                                std::to_string(kMaxNestingDepth), " levels)"}));
  }
}

Parser::Parser(std::string_view text, std::uint32_t file, Diagnostics& diags)
    : errors_(diags, kMaxErrorsPerFile), lexer_(text, file, errors_) {}

const Token& Parser::peek(std::size_t ahead) {
  while (lookahead_.size() <= ahead) lookahead_.push_back(lexer_.next());
  return lookahead_[ahead];
}

Token Parser::take() {
  peek();
  Token token = std::move(lookahead_.front());
  lookahead_.pop_front();
  ++consumed_;
  return token;
}

bool Parser::accept(TokenKind k) {
  if (!at(k)) return false;
  take();
  return true;
}

Token Parser::expect(TokenKind k, std::string_view context) {
  if (at(k)) return take();
  fail(concat({"'", spelling(k), "'", context.empty() ? "" : " ", context}));
}

void Parser::report(Location at, std::string message) {
  if (errors_.exhausted()) throw GiveUp{};
  errors_.error(at, std::move(message));
}

void Parser::fail(std::string_view expected) {
  const Token& token = peek();
  // An invalid token was already reported by the lexer, and so was the unterminated comment or
  // string that swallowed the rest of the file: do not add a second message for them.
  bool consequence = token.kind == TokenKind::Invalid ||
                     (token.kind == TokenKind::EndOfFile && lexer_.ran_off_end());
  if (!consequence) {
    report(token.loc, concat({"expected ", expected, ", got ", describe(token)}));
  }
  throw SyntaxError{};
}

void Parser::fail_at(Location at, std::string message) {
  report(at, std::move(message));
  throw SyntaxError{};
}

std::string Parser::package_description(const ast::Package& package) {
  return package.name.parts.empty() ? std::string("the package")
                                    : concat({"package '", package.name.text(), "'"});
}

bool Parser::is_name(TokenKind k) { return k == TokenKind::Identifier || is_soft_keyword(k); }

bool Parser::is_word(TokenKind k) {
  return k == TokenKind::Identifier || (k >= TokenKind::KwInt && k <= TokenKind::KwFi);
}

ast::Ident Parser::ident_of(const Token& token) { return {std::string(token.text), token.loc}; }

ast::Ident Parser::expect_name(std::string_view what) {
  if (at_name()) return ident_of(take());
  fail(what);
}

ast::QualifiedName Parser::parse_qualified_name(std::string_view what) {
  ast::QualifiedName name;
  name.parts.push_back(expect_name(what));
  while (accept(TokenKind::Dot)) name.parts.push_back(expect_name("a name after '.'"));
  return name;
}

bool Parser::at_data_type_start() {
  switch (kind()) {
    case TokenKind::KwConst:
    case TokenKind::KwInt:
    case TokenKind::KwBool:
    case TokenKind::KwFloat:
    case TokenKind::KwString:
      return true;
    default:
      return at_name();
  }
}

ast::TypeRef Parser::parse_data_type(bool allow_const) {
  ast::TypeRef type;
  type.loc = peek().loc;
  if (allow_const && accept(TokenKind::KwConst)) type.is_const = true;
  switch (kind()) {
    case TokenKind::KwInt:
    case TokenKind::KwBool:
    case TokenKind::KwFloat:
    case TokenKind::KwString:
      type.name.parts.push_back(ident_of(take()));
      break;
    default:
      type.name = parse_qualified_name("a type name");
      break;
  }
  return type;
}

ast::Annotations Parser::parse_annotations() {
  ast::Annotations annotations;
  while (at(TokenKind::AtSign)) {
    ast::Annotation annotation;
    annotation.loc = take().loc;
    if (!is_word(kind())) fail("an annotation name after '@'");
    annotation.name = ident_of(take());
    if (accept(TokenKind::LParen)) {
      do {
        ast::AnnotationParam param;
        if (!is_word(kind())) fail("an annotation parameter name");
        param.key = ident_of(take());
        if (accept(TokenKind::Assign)) {
          param.value_loc = peek().loc;
          if (at(TokenKind::String)) {
            param.value = take().string_value;
          } else if (at_name() || at(TokenKind::KwTrue) || at(TokenKind::KwFalse)) {
            param.value = std::string(take().text);
          } else {
            fail("an annotation value (a name, true, false or a string)");
          }
        }
        annotation.params.push_back(std::move(param));
      } while (accept(TokenKind::Comma));
      expect(TokenKind::RParen,
             "to close the parameters of annotation '@" + annotation.name.text + "'");
    }
    annotations.push_back(std::move(annotation));
  }
  return annotations;
}

std::vector<ast::ParamDecl> Parser::parse_data_params(std::string_view owner) {
  std::vector<ast::ParamDecl> params;
  expect(TokenKind::LParen, concat({"after the name of ", owner}));
  if (accept(TokenKind::RParen)) return params;
  do {
    if (!at_data_type_start()) fail("a parameter type");
    ast::ParamDecl param;
    param.type = parse_data_type(true);
    param.loc = param.type.loc;
    param.name = expect_name("a parameter name");
    params.push_back(std::move(param));
  } while (accept(TokenKind::Comma));
  expect(TokenKind::RParen, concat({"to close the parameters of ", owner}));
  return params;
}

std::vector<ast::Ident> Parser::parse_name_list(std::string_view what) {
  std::vector<ast::Ident> names;
  names.push_back(expect_name(what));
  while (accept(TokenKind::Comma)) names.push_back(expect_name(what));
  return names;
}

/// `(x, y)` after the name of a port (of an atom, or exported by a connector): the data it binds.
std::vector<ast::Ident> Parser::parse_bound_data(const ast::Ident& port) {
  expect(TokenKind::LParen, "after port name '" + port.text + "'");
  if (accept(TokenKind::RParen)) return {};
  std::vector<ast::Ident> bound = parse_name_list("a data name");
  expect(TokenKind::RParen, "to close the data bound to port '" + port.text + "'");
  return bound;
}

ast::ExprPtr Parser::parse_parenthesized_guard(std::string_view after) {
  expect(TokenKind::LParen, concat({"after '", after, "'"}));
  ast::ExprPtr guard = parse_expression();
  expect(TokenKind::RParen, concat({"to close the condition of '", after, "'"}));
  return guard;
}

// ---------------------------------------------------------------------------------------------
// Recovery

bool Parser::at_top_level_start(std::size_t ahead) {
  // Annotations may precede a declaration; skip them with a bounded look, so that adversarial
  // input cannot make the recovery quadratic.
  constexpr std::size_t kMaxAnnotationLook = 64;
  std::size_t limit = ahead + kMaxAnnotationLook;
  while (kind(ahead) == TokenKind::AtSign && ahead < limit) {
    ++ahead;
    if (!is_word(kind(ahead))) return false;
    ++ahead;
    if (kind(ahead) == TokenKind::LParen) {
      while (kind(ahead) != TokenKind::RParen && kind(ahead) != TokenKind::EndOfFile &&
             ahead < limit) {
        ++ahead;
      }
      if (kind(ahead) != TokenKind::RParen) return false;
      ++ahead;
    }
  }
  TokenKind next = kind(ahead + 1);
  switch (kind(ahead)) {
    case TokenKind::KwAtom:
    case TokenKind::KwCompound:
    case TokenKind::KwConnector:
    case TokenKind::KwPort:
      return next == TokenKind::KwType;
    case TokenKind::KwExtern:
      return next == TokenKind::KwData || next == TokenKind::KwFunction ||
             next == TokenKind::KwOperator;
    case TokenKind::KwConst:
      return next == TokenKind::KwData;
    default:
      return false;
  }
}

void Parser::recover(bool closed_by_end) {
  for (;;) {
    if (errors_.exhausted()) throw GiveUp{};
    TokenKind k = kind();
    if (k == TokenKind::EndOfFile || at_top_level_start()) return;
    if (k == TokenKind::KwEnd) {
      // The `end` closing the broken type; unless it is the last one, which closes the package.
      if (closed_by_end && kind(1) != TokenKind::EndOfFile) take();
      return;
    }
    take();
  }
}

// ---------------------------------------------------------------------------------------------
// Entry points

std::unique_ptr<ast::Package> Parser::parse_package() {
  auto package = std::make_unique<ast::Package>();
  try {
    in_type_with_end_ = false;
    bool header_read = true;
    try {
      parse_package_header(*package);
    } catch (const SyntaxError&) {
      recover(false);
      header_read = false;
    }
    const std::string name = package_description(*package);
    while (!at(TokenKind::KwEnd) && !at(TokenKind::EndOfFile)) {
      std::size_t before = consumed_;
      in_type_with_end_ = false;
      try {
        parse_declaration(*package);
      } catch (const SyntaxError&) {
        recover(in_type_with_end_);
        if (consumed_ == before && !at(TokenKind::EndOfFile)) take();
      }
    }
    // Without a header, a missing or extra `end` is a consequence of the first error.
    if (!header_read) return package;
    if (at(TokenKind::EndOfFile)) fail("'end' to close " + name);
    take();
    if (!at(TokenKind::EndOfFile)) {
      fail("end of file after the 'end' of " + name);
    }
  } catch (const SyntaxError&) {
  } catch (const GiveUp&) {
  }
  return package;
}

std::optional<ast::ComponentDecl> Parser::parse_root() {
  try {
    ast::ComponentDecl root;
    root.loc = peek().loc;
    root.type = parse_qualified_name("a component type name");
    root.args = parse_arguments("after the component type name");
    if (!at(TokenKind::EndOfFile)) fail("end of the root instantiation");
    return root;
  } catch (const SyntaxError&) {
  } catch (const GiveUp&) {
  }
  return std::nullopt;
}

}  // namespace detail

std::unique_ptr<ast::Package> parse_package(const std::string& text, std::uint32_t file,
                                            Diagnostics& diags) {
  detail::Parser parser(text, file, diags);
  return parser.parse_package();
}

std::optional<ast::ComponentDecl> parse_root(const std::string& text, std::uint32_t file,
                                             Diagnostics& diags) {
  detail::Parser parser(text, file, diags);
  return parser.parse_root();
}

}  // namespace smcbip::bipc
