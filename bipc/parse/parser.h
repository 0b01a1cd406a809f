// The BIP2 parser: recursive descent over the tokens of one package, building the AST.
//
// Why hand-written rather than generated (the reference compiler uses an ANTLR grammar with
// backtracking): every error is reported as `expected X, got Y` at the offending token with the
// construct it belongs to; after an error the parser resynchronises on the next type definition,
// so one run reports several independent errors of a file; it runs in linear time with one token
// of lookahead (two at a few places; recovery looks a bounded distance further) on generated
// models of 10,000 atoms; and it costs no template-heavy compile times or generator in the build.
// Recursion is bounded (kMaxNestingDepth), so hostile input yields a diagnostic, not a crash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/ast/ast.h"
#include "bipc/diagnostics.h"
#include "bipc/parse/lexer.h"

namespace smcbip::bipc::detail {

/// Diagnostics reported for one file before the parser gives up on it.
inline constexpr std::size_t kMaxErrorsPerFile = 50;
/// Nesting of parentheses, unary operators, `if` statements and port expressions.
inline constexpr int kMaxNestingDepth = 256;
/// Depth of an expression tree, so later recursive passes cannot overflow the stack either.
inline constexpr int kMaxExpressionDepth = 1024;

/// Parses one text; one Parser per text. Syntax errors go to the Diagnostics given.
class Parser {
 public:
  Parser(std::string_view text, std::uint32_t file, Diagnostics& diags);

  /// The package of the text; never null, filled as far as the text could be read.
  std::unique_ptr<ast::Package> parse_package();
  /// A root instantiation `name.Type(args)` making up the whole text.
  std::optional<ast::ComponentDecl> parse_root();

 private:
  // Thrown after an error was reported, unwinding to the nearest recovery point.
  struct SyntaxError {};
  // Thrown to abandon the file: the error budget is exhausted, or the text is not BIP2 at all.
  struct GiveUp {};

  // An expression with the depth of its tree (parser_expr.cpp).
  struct Parsed {
    ast::ExprPtr expr;
    int depth = 1;
  };

  // Counts recursion depth and reports excessive nesting instead of overflowing the stack.
  class DepthGuard {
   public:
    explicit DepthGuard(Parser& parser);
    ~DepthGuard() { --parser_.depth_; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;

   private:
    Parser& parser_;
  };

  // ---- tokens and errors (parser.cpp)
  const Token& peek(std::size_t ahead = 0);
  TokenKind kind(std::size_t ahead = 0) { return peek(ahead).kind; }
  bool at(TokenKind k) { return kind() == k; }
  Token take();
  bool accept(TokenKind k);
  Token expect(TokenKind k, std::string_view context);
  [[noreturn]] void fail(std::string_view expected);
  [[noreturn]] void fail_at(Location at, std::string message);
  void report(Location at, std::string message);
  bool at_name() { return is_name(kind()); }
  static std::string package_description(const ast::Package& package);
  static bool is_name(TokenKind k);
  static bool is_word(TokenKind k);  // an identifier or any keyword (annotation names and keys)
  ast::Ident expect_name(std::string_view what);
  static ast::Ident ident_of(const Token& token);
  ast::QualifiedName parse_qualified_name(std::string_view what);
  ast::TypeRef parse_data_type(bool allow_const);
  bool at_data_type_start();
  ast::Annotations parse_annotations();
  std::vector<ast::ParamDecl> parse_data_params(std::string_view owner);
  std::vector<ast::Ident> parse_name_list(std::string_view what);
  std::vector<ast::Ident> parse_bound_data(const ast::Ident& port);
  ast::ExprPtr parse_parenthesized_guard(std::string_view after);

  // ---- error recovery (parser.cpp)
  bool at_top_level_start(std::size_t ahead = 0);
  void recover(bool closed_by_end);

  // ---- package level (parser_package.cpp)
  void parse_package_header(ast::Package& package);
  void parse_declaration(ast::Package& package);
  void parse_const_data(ast::Package& package, ast::Annotations annotations);
  void parse_extern(ast::Package& package, ast::Annotations annotations);
  void parse_extern_function(ast::Package& package, ast::Annotations annotations, Location start);
  void parse_extern_operator(ast::Package& package, ast::Annotations annotations, Location start);
  ast::ParamDecl parse_prototype_param();
  ast::PortTypeDecl parse_port_type(ast::Annotations annotations);
  [[noreturn]] void fail_bip1(std::string_view construct, std::string_view advice);

  // ---- atom types (parser_atom.cpp)
  ast::AtomTypeDecl parse_atom_type(ast::Annotations annotations);
  void parse_atom_declaration(ast::AtomTypeDecl& atom);
  std::vector<ast::DataDecl> parse_data_declaration(ast::Annotations annotations, bool exported);
  void parse_port_declaration(ast::AtomTypeDecl& atom, ast::Annotations annotations, bool exported,
                              bool is_extern);
  void parse_clock_declaration(ast::AtomTypeDecl& atom, ast::Annotations annotations);
  void parse_initial(ast::AtomTypeDecl& atom);
  ast::Transition parse_transition(ast::Annotations annotations);
  ast::AtomPriorityDecl parse_atom_priority();
  ast::InvariantDecl parse_invariant();
  std::optional<ast::ResumeClause> parse_optional_resume();

  // ---- connector and compound types (parser_connector_compound.cpp)
  ast::ConnectorTypeDecl parse_connector_type(ast::Annotations annotations);
  std::vector<ast::PortExpr> parse_port_expressions();
  ast::InteractionDecl parse_interaction(ast::Annotations annotations);
  ast::CompoundTypeDecl parse_compound_type(ast::Annotations annotations);
  void parse_component_declaration(ast::CompoundTypeDecl& compound, ast::Annotations annotations);
  void parse_connector_declaration(ast::CompoundTypeDecl& compound, ast::Annotations annotations);
  ast::InteractionPattern parse_interaction_pattern();
  ast::CompoundPriorityDecl parse_compound_priority();
  void parse_compound_export(ast::CompoundTypeDecl& compound, ast::Annotations annotations);
  std::vector<ast::ExprPtr> parse_arguments(std::string_view context);

  // ---- expressions and statements (parser_expr.cpp)
  ast::ExprPtr parse_expression();
  Parsed parse_call_arguments(ast::QualifiedName name);
  Parsed parse_logical_chain(int level);
  Parsed parse_equality();
  Parsed parse_relational();
  Parsed parse_additive();
  Parsed parse_multiplicative();
  Parsed parse_unary();
  Parsed parse_postfix();
  Parsed parse_primary();
  void check_expression_depth(int depth, Location at);
  Parsed make_binary(ast::BinaryOp op, Location at, Parsed left, Parsed right);
  bool at_statement_start();
  ast::Block parse_block(std::string_view context);
  void parse_statement(ast::Block& block, std::string_view expected);
  ast::StatementPtr parse_if();

  ErrorBudget errors_;
  Lexer lexer_;
  std::deque<Token> lookahead_;
  int depth_ = 0;
  std::size_t consumed_ = 0;       // tokens taken so far, to make recovery always progress
  bool in_type_with_end_ = false;  // the declaration being parsed is closed by `end`
};

}  // namespace smcbip::bipc::detail
