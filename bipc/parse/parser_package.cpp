// Parser of the package frame: header, `use`, constants, extern declarations, port types.
#include <utility>

#include "bipc/parse/parser.h"

namespace smcbip::bipc::detail {

namespace {

bool is_binary_operator(TokenKind kind) {
  switch (kind) {
    case TokenKind::EqEq:
    case TokenKind::NotEq:
    case TokenKind::Lt:
    case TokenKind::Gt:
    case TokenKind::Le:
    case TokenKind::Ge:
    case TokenKind::Plus:
    case TokenKind::Minus:
    case TokenKind::Star:
    case TokenKind::Slash:
    case TokenKind::Percent:
    case TokenKind::Amp:
    case TokenKind::Pipe:
    case TokenKind::Caret:
    case TokenKind::AndAnd:
    case TokenKind::OrOr:
      return true;
    default:
      return false;
  }
}

bool is_unary_operator(TokenKind kind) {
  return kind == TokenKind::Plus || kind == TokenKind::Minus || kind == TokenKind::Not ||
         kind == TokenKind::Tilde;
}

}  // namespace

void Parser::fail_bip1(std::string_view construct, std::string_view advice) {
  // A BIP1 model would only produce a cascade of errors: one clear message, then stop.
  report(peek().loc,
         concat({"BIP1 syntax is not supported ('", construct, "'); this is BIP2: ", advice}));
  throw GiveUp{};
}

void Parser::parse_package_header(ast::Package& package) {
  package.annotations = parse_annotations();
  if (at(TokenKind::Identifier) && peek().text == "model") {
    fail_bip1("model", "write 'package NAME ... end'");
  }
  package.loc = expect(TokenKind::KwPackage, "at the start of the file").loc;
  package.name = parse_qualified_name("a package name after 'package'");
  while (accept(TokenKind::KwUse)) {
    package.uses.push_back(parse_qualified_name("a package name after 'use'"));
  }
}

void Parser::parse_declaration(ast::Package& package) {
  ast::Annotations annotations = parse_annotations();
  switch (kind()) {
    case TokenKind::KwConst:
    case TokenKind::KwData:
      parse_const_data(package, std::move(annotations));
      return;
    case TokenKind::KwExtern:
      parse_extern(package, std::move(annotations));
      return;
    case TokenKind::KwPort:
      package.port_types.push_back(parse_port_type(std::move(annotations)));
      return;
    case TokenKind::KwAtom:
      in_type_with_end_ = true;
      package.atom_types.push_back(parse_atom_type(std::move(annotations)));
      return;
    case TokenKind::KwConnector:
      in_type_with_end_ = true;
      package.connector_types.push_back(parse_connector_type(std::move(annotations)));
      return;
    case TokenKind::KwCompound:
      in_type_with_end_ = true;
      package.compound_types.push_back(parse_compound_type(std::move(annotations)));
      return;
    case TokenKind::Identifier:
      if (peek().text == "atomic" && kind(1) == TokenKind::KwType) {
        fail_bip1("atomic type", "use 'atom type'");
      }
      if (peek().text == "model") fail_bip1("model", "write 'package NAME ... end'");
      break;
    default:
      break;
  }
  if (!annotations.empty()) {
    fail("a declaration after annotations");
  }
  fail(
      concat({"a declaration (const data, extern, port type, atom type, connector type or "
              "compound type) or 'end' to close ",
              package_description(package)}));
}

void Parser::parse_const_data(ast::Package& package, ast::Annotations annotations) {
  if (accept(TokenKind::KwConst)) {
    expect(TokenKind::KwData,
           "after 'const' (a package constant is 'const data TYPE NAME = VALUE')");
  } else {
    take();  // `data`
    expect(TokenKind::KwConst,
           "after 'data' (package-level data must be constant: 'const data TYPE NAME = VALUE')");
  }
  ast::TypeRef type = parse_data_type(false);
  type.is_const = true;
  do {
    ast::ConstDataDecl constant;
    constant.type = type;
    constant.name = expect_name("a constant name");
    constant.loc = constant.name.loc;
    if (accept(TokenKind::Assign)) constant.value = parse_expression();
    constant.annotations = annotations;
    package.consts.push_back(std::move(constant));
  } while (accept(TokenKind::Comma));
}

void Parser::parse_extern(ast::Package& package, ast::Annotations annotations) {
  Location start = take().loc;  // `extern`
  if (accept(TokenKind::KwFunction)) {
    parse_extern_function(package, std::move(annotations), start);
    return;
  }
  if (accept(TokenKind::KwOperator)) {
    parse_extern_operator(package, std::move(annotations), start);
    return;
  }
  if (!accept(TokenKind::KwData)) {
    fail(at(TokenKind::KwPort)
             ? "'data type', 'function' or 'operator' after 'extern' (extern ports are declared "
               "in atom types)"
             : "'data type', 'function' or 'operator' after 'extern'");
  }
  expect(TokenKind::KwType, "after 'extern data'");
  ast::ExternTypeDecl type;
  type.loc = start;
  type.annotations = std::move(annotations);
  type.name = expect_name("an extern type name");
  if (accept(TokenKind::KwRefine)) {
    do {
      type.refines.push_back(parse_data_type(false));
    } while (accept(TokenKind::Comma));
  }
  if (accept(TokenKind::KwAs)) {
    if (!at(TokenKind::String)) fail("a string naming the back-end type after 'as'");
    type.backend_name = take().string_value;
  }
  package.extern_types.push_back(std::move(type));
}

ast::ParamDecl Parser::parse_prototype_param() {
  if (!at_data_type_start()) fail("a parameter type");
  ast::ParamDecl param;
  param.type = parse_data_type(true);
  param.loc = param.type.loc;
  if (at_name()) param.name = ident_of(take());
  return param;
}

void Parser::parse_extern_function(ast::Package& package, ast::Annotations annotations,
                                   Location start) {
  ast::ExternFunctionDecl function;
  function.loc = start;
  function.annotations = std::move(annotations);
  if (at_name()) {
    // Either the function name (then '(' follows) or a named result type.
    ast::QualifiedName first = parse_qualified_name("a function name");
    if (at(TokenKind::LParen)) {
      if (first.parts.size() != 1) {
        fail_at(first.loc(),
                concat({"a function name is a simple name, got '", first.text(), "'"}));
      }
      function.name = std::move(first.parts.front());
    } else {
      ast::TypeRef result;
      result.loc = first.loc();
      result.name = std::move(first);
      function.result = std::move(result);
      function.name = expect_name("a function name after its result type");
    }
  } else if (at_data_type_start()) {
    function.result = parse_data_type(true);
    function.name = expect_name("a function name after its result type");
  } else {
    fail("a result type or a function name after 'extern function'");
  }
  expect(TokenKind::LParen, "after the name of extern function '" + function.name.text + "'");
  if (!accept(TokenKind::RParen)) {
    do {
      function.params.push_back(parse_prototype_param());
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RParen,
           "to close the parameters of extern function '" + function.name.text + "'");
  }
  package.extern_functions.push_back(std::move(function));
}

void Parser::parse_extern_operator(ast::Package& package, ast::Annotations annotations,
                                   Location start) {
  ast::ExternFunctionDecl op;
  op.is_operator = true;
  op.loc = start;
  op.annotations = std::move(annotations);
  if (!at_data_type_start()) fail("the result type of the operator after 'extern operator'");
  op.result = parse_data_type(true);
  TokenKind symbol = kind();
  if (!is_binary_operator(symbol) && !is_unary_operator(symbol)) {
    fail("an operator symbol (such as '+', '==' or '!') after the result type");
  }
  op.name = ident_of(take());
  const std::string what = "operator '" + op.name.text + "'";
  expect(TokenKind::LParen, "after " + what);
  op.params.push_back(parse_prototype_param());
  if (accept(TokenKind::Comma)) op.params.push_back(parse_prototype_param());
  expect(TokenKind::RParen, "to close the operands of " + what + " (one or two operands)");
  if (op.params.size() == 1 && !is_unary_operator(symbol)) {
    fail_at(op.name.loc, what + " is not a unary operator; declare two operands");
  }
  if (op.params.size() == 2 && !is_binary_operator(symbol)) {
    fail_at(op.name.loc, what + " is not a binary operator; declare one operand");
  }
  package.extern_functions.push_back(std::move(op));
}

ast::PortTypeDecl Parser::parse_port_type(ast::Annotations annotations) {
  ast::PortTypeDecl port_type;
  port_type.loc = take().loc;  // `port`
  port_type.annotations = std::move(annotations);
  expect(TokenKind::KwType, "after 'port' (a port type is 'port type NAME(PARAMS)')");
  port_type.name = expect_name("a port type name");
  port_type.params = parse_data_params("port type '" + port_type.name.text + "'");
  return port_type;
}

}  // namespace smcbip::bipc::detail
