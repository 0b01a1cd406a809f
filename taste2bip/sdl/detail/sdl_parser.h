// The recursive-descent parser of SDL-PR, after OpenGEODE's grammar (sdl92.g) and ITU-T Z.100.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "taste2bip/sdl/detail/sdl_lexer.h"
#include "taste2bip/sdl/sdl_ast.h"

namespace smcbip::taste2bip::sdl::detail {

/// How deep declarations, transitions and expressions may nest before reading stops.
inline constexpr std::size_t kMaxNesting = 200;
/// How many errors one file reports before reading stops.
inline constexpr std::size_t kMaxErrors = 20;

class Parser {
 public:
  Parser(std::vector<Token> tokens, ErrorBudget& errors)
      : tokens_(std::move(tokens)), errors_(errors) {}
  SdlFile parse_file();

 private:
  // Which keyword closes a body.
  enum class BodyEnd : std::uint8_t { Process, Procedure, Substructure };

  // Keeps track of nesting; reading stops (with one error) past kMaxNesting.
  class Nesting {
   public:
    explicit Nesting(Parser& parser);
    ~Nesting() { --parser_.depth_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

   private:
    Parser& parser_;
  };

  // Tokens.
  bool stopped() const { return stopped_ || errors_.exhausted(); }
  const Token& peek(std::size_t k = 0) const;
  bool at(TokenKind kind, std::size_t k = 0) const { return peek(k).kind == kind; }
  bool at_word(std::string_view keyword, std::size_t k = 0) const;
  bool at_eof() const { return at(TokenKind::EndOfFile); }
  Token take();
  bool accept(TokenKind kind);
  bool accept_word(std::string_view keyword);
  void error_here(std::string message);
  /// Reports the current token where one of `expected` should be: an SDL construct this reader
  /// does not support is named as such.
  void error_unexpected(const std::string& expected);
  /// Whether the current token opens an SDL construct this reader does not support.
  bool at_unsupported() const;
  /// Consumes `kind` or reports "expected X <context>, got Y"; false when missing.
  bool expect(TokenKind kind, std::string_view context);
  bool expect_word(std::string_view keyword, std::string_view context);
  /// A name (a word that is not a reserved keyword), or an error "expected <what>".
  std::optional<std::string> expect_name(std::string_view what);
  bool at_name(std::size_t k = 0) const;
  /// Skips to just after the next ';' (or to the end of the file).
  void skip_past_semicolon();
  /// `comment 'text'` if present (else empty).
  std::string parse_comment();
  /// Expects ';' closing `what`, reporting "expected ';' after <what>".
  bool end_statement(std::string_view what);
  /// `endxxx [name] ;`.
  void parse_end();

  // Structure (sdl_parser.cpp).
  UseClause parse_use();
  System parse_system();
  Block parse_block();
  std::vector<SignalDeclaration> parse_signals();
  Channel parse_channel(bool is_route);
  ChannelConnection parse_channel_connection();
  Process parse_process();
  Procedure parse_procedure();
  void parse_body(Body& body, BodyEnd end, Procedure* procedure, CompositeState* composite);
  void parse_variables(std::vector<Variable>& variables);
  void parse_formal_parameters(std::vector<FormalParameter>& parameters);
  std::vector<std::string> parse_point_list(std::string_view keyword);

  // States (sdl_parser_state.cpp).
  void parse_state(Body& body);
  void parse_state_parts(State& state);
  Input parse_input();
  ContinuousSignal parse_continuous_signal();
  ExitConnection parse_exit_connection();
  Start parse_start();
  FloatingLabel parse_floating_label();

  // Transitions (sdl_parser_transition.cpp).
  bool at_action_start() const;
  Transition parse_transition();
  Action parse_action();
  void parse_task(Action& action);
  ForLoop parse_for_loop();
  void parse_output(Action& action);
  void parse_call(Action& action);
  void parse_decision(Action& action);
  Answer parse_answer();
  RangeCondition parse_range_condition();
  std::vector<Expr> parse_arguments();

  // Expressions (sdl_parser_expr.cpp).
  Expr parse_expression();
  Expr parse_binary(int level);
  Expr parse_unary();
  Expr parse_postfix(bool allow_choice);
  Expr parse_primary(bool allow_choice);
  Expr parse_sequence_value();
  Expr parse_conditional();

  std::vector<Token> tokens_;
  ErrorBudget& errors_;
  std::size_t pos_ = 0;
  std::size_t depth_ = 0;
  bool stopped_ = false;
  std::size_t for_loops_ = 0;  // how many for loop bodies enclose the current position
};

/// Whether `lower` is a keyword of SDL-PR that cannot name anything.
bool is_reserved(std::string_view lower);

/// The comparison a token spells (`=`, `/=`, `<`, `<=`, `>`, `>=`), or Operator::None.
Operator comparison_operator(TokenKind kind);

}  // namespace smcbip::taste2bip::sdl::detail
