// SDL-PR parser: tokens, error recovery and the structure (system, block, process, procedure).
#include "taste2bip/sdl/detail/sdl_parser.h"

#include <array>

#include "taste2bip/sdl/sdl_reader.h"

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

SdlFile read_sdl(const std::string& text, std::uint32_t file, bipc::Diagnostics& diags) {
  detail::ErrorBudget errors(diags, detail::kMaxErrors);
  std::vector<detail::Token> tokens = detail::lex_sdl(text, file, errors);
  return detail::Parser(std::move(tokens), errors).parse_file();
}

}  // namespace smcbip::taste2bip::sdl

namespace smcbip::taste2bip::sdl::detail {

bool is_reserved(std::string_view lower) {
  // Words that open, close or join constructs; everything else may name something.
  static constexpr std::array<std::string_view, 52> kReserved = {"and",
                                                                 "block",
                                                                 "call",
                                                                 "channel",
                                                                 "comment",
                                                                 "connect",
                                                                 "connection",
                                                                 "dcl",
                                                                 "decision",
                                                                 "else",
                                                                 "endblock",
                                                                 "endchannel",
                                                                 "endconnection",
                                                                 "enddecision",
                                                                 "endfor",
                                                                 "endprocedure",
                                                                 "endprocess",
                                                                 "endstate",
                                                                 "endsubstructure",
                                                                 "endsystem",
                                                                 "external",
                                                                 "fi",
                                                                 "for",
                                                                 "fpar",
                                                                 "if",
                                                                 "implies",
                                                                 "input",
                                                                 "join",
                                                                 "mod",
                                                                 "nextstate",
                                                                 "not",
                                                                 "or",
                                                                 "output",
                                                                 "procedure",
                                                                 "process",
                                                                 "provided",
                                                                 "rem",
                                                                 "return",
                                                                 "returns",
                                                                 "save",
                                                                 "signal",
                                                                 "signalroute",
                                                                 "start",
                                                                 "state",
                                                                 "stop",
                                                                 "substructure",
                                                                 "system",
                                                                 "task",
                                                                 "then",
                                                                 "timer",
                                                                 "use",
                                                                 "xor"};
  for (std::string_view word : kReserved) {
    if (word == lower) return true;
  }
  return false;
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
  static constexpr std::array<std::string_view, 17> kUnsupported = {"newtype",
                                                                    "syntype",
                                                                    "synonym",
                                                                    "signallist",
                                                                    "create",
                                                                    "export",
                                                                    "import",
                                                                    "exported",
                                                                    "imported",
                                                                    "alternative",
                                                                    "macro",
                                                                    "service",
                                                                    "remote",
                                                                    "gate",
                                                                    "package",
                                                                    "operator",
                                                                    "channelsubstructure"};
  const Token& token = peek();
  if (token.kind != TokenKind::Word) return false;
  for (std::string_view word : kUnsupported) {
    if (word == token.lower) return true;
  }
  return false;
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

SdlFile Parser::parse_file() {
  SdlFile file;
  while (!at_eof()) {
    if (at_word("use")) {
      file.uses.push_back(parse_use());
    } else if (at_word("system")) {
      file.systems.push_back(parse_system());
    } else if (at_word("process")) {
      file.processes.push_back(parse_process());
    } else if (at_word("procedure")) {
      file.procedures.push_back(parse_procedure());
    } else if (!accept(TokenKind::Semicolon)) {
      error_unexpected("'use', 'system', 'process' or 'procedure'");
      skip_past_semicolon();
    }
  }
  return file;
}

UseClause Parser::parse_use() {
  UseClause use;
  use.at = take().at;
  if (auto name = expect_name("a package name after 'use'")) use.package = *name;
  if (accept(TokenKind::Slash)) {
    do {
      if (auto name = expect_name("a definition name in 'use'")) use.definitions.push_back(*name);
    } while (accept(TokenKind::Comma));
  }
  use.comment = parse_comment();
  end_statement("'use " + use.package + "'");
  return use;
}

System Parser::parse_system() {
  System system;
  system.at = take().at;
  if (auto name = expect_name("a system name after 'system'")) system.name = *name;
  end_statement("'system " + system.name + "'");
  while (!at_eof() && !at_word("endsystem")) {
    Nesting nesting(*this);
    if (at_word("use")) {
      system.uses.push_back(parse_use());
    } else if (at_word("signal")) {
      for (auto& signal : parse_signals()) system.signals.push_back(std::move(signal));
    } else if (at_word("channel")) {
      system.channels.push_back(parse_channel(false));
    } else if (at_word("procedure")) {
      system.procedures.push_back(parse_procedure());
    } else if (at_word("block")) {
      system.blocks.push_back(parse_block());
    } else if (!accept(TokenKind::Semicolon)) {
      error_here(
          "expected 'use', 'signal', 'channel', 'procedure', 'block' or 'endsystem' in system " +
          system.name + ", got " + describe(peek()));
      skip_past_semicolon();
    }
  }
  if (at_word("endsystem")) {
    parse_end();
  } else {
    error_here("expected 'endsystem' closing system " + system.name + ", got end of file");
  }
  return system;
}

std::vector<SignalDeclaration> Parser::parse_signals() {
  std::vector<SignalDeclaration> signals;
  take();
  do {
    SignalDeclaration signal;
    signal.at = peek().at;
    auto name = expect_name("a signal name");
    if (!name) break;
    signal.name = *name;
    if (accept(TokenKind::LParen)) {
      do {
        if (auto type = expect_name("a parameter type of signal " + signal.name)) {
          signal.parameter_types.push_back(*type);
        }
      } while (accept(TokenKind::Comma));
      expect(TokenKind::RParen, "closing the parameters of signal " + signal.name);
    }
    signals.push_back(std::move(signal));
  } while (accept(TokenKind::Comma));
  parse_comment();
  end_statement("'signal'");
  return signals;
}

Channel Parser::parse_channel(bool is_route) {
  Channel channel;
  channel.at = take().at;
  const std::string keyword = is_route ? "signalroute" : "channel";
  if (auto name = expect_name("a " + keyword + " name")) channel.name = *name;
  accept_word("nodelay");
  while (at_word("from")) {
    Path path;
    path.at = take().at;
    if (auto from = expect_name("a block or 'env' after 'from'")) path.from = *from;
    if (expect_word("to", "after 'from " + path.from + "'")) {
      if (auto to = expect_name("a block or 'env' after 'to'")) path.to = *to;
    }
    if (expect_word("with", "after 'to " + path.to + "'")) {
      do {
        if (auto signal = expect_name("a signal name after 'with'")) {
          path.signals.push_back(*signal);
        }
      } while (accept(TokenKind::Comma));
    }
    end_statement("the signals of " + keyword + " " + channel.name);
    channel.paths.push_back(std::move(path));
  }
  if (!is_route) {
    if (at_word("endchannel")) {
      parse_end();
    } else if (!stopped()) {
      error_here("expected 'from' or 'endchannel' in channel " + channel.name + ", got " +
                 describe(peek()));
      skip_past_semicolon();
    }
  }
  return channel;
}

ChannelConnection Parser::parse_channel_connection() {
  ChannelConnection connection;
  connection.at = take().at;
  if (auto name = expect_name("a channel name after 'connect'")) connection.channel = *name;
  if (expect_word("and", "after 'connect " + connection.channel + "'")) {
    do {
      if (auto route = expect_name("a signal route name")) connection.routes.push_back(*route);
    } while (accept(TokenKind::Comma));
  }
  end_statement("'connect " + connection.channel + "'");
  return connection;
}

Block Parser::parse_block() {
  Block block;
  block.at = take().at;
  if (auto name = expect_name("a block name after 'block'")) block.name = *name;
  if (accept_word("referenced")) {
    block.is_referenced = true;
    end_statement("'block " + block.name + " referenced'");
    return block;
  }
  end_statement("'block " + block.name + "'");
  while (!at_eof() && !at_word("endblock")) {
    Nesting nesting(*this);
    if (at_word("signal")) {
      for (auto& signal : parse_signals()) block.signals.push_back(std::move(signal));
    } else if (at_word("signalroute")) {
      block.routes.push_back(parse_channel(true));
    } else if (at_word("connect")) {
      block.connections.push_back(parse_channel_connection());
    } else if (at_word("process")) {
      block.processes.push_back(parse_process());
    } else if (at_word("block")) {
      block.blocks.push_back(parse_block());
    } else if (at_word("procedure")) {
      block.procedures.push_back(parse_procedure());
    } else if (!accept(TokenKind::Semicolon)) {
      error_here(
          "expected 'signal', 'signalroute', 'connect', 'process', 'block' or "
          "'endblock' in block " +
          block.name + ", got " + describe(peek()));
      skip_past_semicolon();
    }
  }
  if (at_word("endblock")) {
    parse_end();
  } else {
    error_here("expected 'endblock' closing block " + block.name + ", got end of file");
  }
  return block;
}

Process Parser::parse_process() {
  Process process;
  process.at = take().at;
  process.is_type = accept_word("type");
  if (auto name = expect_name("a process name after 'process'")) process.name = *name;
  if (accept(TokenKind::LParen)) {  // number of instances: (initial, maximum)
    process.initial_instances = parse_expression();
    if (expect(TokenKind::Comma, "between the initial and maximum numbers of instances")) {
      process.maximum_instances = parse_expression();
    }
    expect(TokenKind::RParen, "closing the numbers of instances");
  }
  if (accept(TokenKind::Colon)) {
    if (auto type = expect_name("a process type name after ':'")) process.instance_of = *type;
  }
  process.is_referenced = accept_word("referenced");
  parse_comment();
  end_statement("'process " + process.name + "'");
  if (process.is_referenced || !process.instance_of.empty()) return process;
  parse_body(process.body, BodyEnd::Process, nullptr, nullptr);
  if (at_word("endprocess")) {
    take();
    accept_word("type");
    if (at_name()) take();
    end_statement("'endprocess'");
  } else if (!stopped()) {
    error_here("expected 'endprocess' closing process " + process.name + ", got " +
               describe(peek()));
  }
  return process;
}

Procedure Parser::parse_procedure() {
  Procedure procedure;
  procedure.at = take().at;
  if (auto name = expect_name("a procedure name after 'procedure'")) procedure.name = *name;
  procedure.comment = parse_comment();
  end_statement("'procedure " + procedure.name + "'");
  parse_body(procedure.body, BodyEnd::Procedure, &procedure, nullptr);
  if (procedure.is_external || procedure.is_referenced) return procedure;
  if (at_word("endprocedure")) {
    parse_end();
  } else if (!stopped()) {
    error_here("expected 'endprocedure' closing procedure " + procedure.name + ", got " +
               describe(peek()));
  }
  return procedure;
}

std::vector<std::string> Parser::parse_point_list(std::string_view keyword) {
  std::vector<std::string> points;
  take();
  if (expect(TokenKind::LParen, "after '" + std::string(keyword) + "'")) {
    do {
      if (auto name = expect_name("a connection point name")) points.push_back(*name);
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RParen, "closing the connection points");
  }
  end_statement("'" + std::string(keyword) + " (...)'");
  return points;
}

void Parser::parse_body(Body& body, BodyEnd end, Procedure* procedure, CompositeState* composite) {
  const std::string_view end_word = end == BodyEnd::Process     ? "endprocess"
                                    : end == BodyEnd::Procedure ? "endprocedure"
                                                                : "endsubstructure";
  while (!at_eof() && !at_word(end_word)) {
    Nesting nesting(*this);
    if (at_word("dcl")) {
      parse_variables(body.variables);
    } else if (at_word("timer")) {
      take();
      do {
        Timer timer;
        timer.at = peek().at;
        auto name = expect_name("a timer name");
        if (!name) break;
        timer.name = *name;
        body.timers.push_back(timer);
      } while (accept(TokenKind::Comma));
      end_statement("'timer'");
    } else if (at_word("procedure")) {
      body.procedures.push_back(parse_procedure());
    } else if (at_word("start")) {
      body.starts.push_back(parse_start());
    } else if (at_word("state")) {
      parse_state(body);
    } else if (at_word("connection")) {
      body.labels.push_back(parse_floating_label());
    } else if (procedure != nullptr && at_word("fpar")) {
      parse_formal_parameters(procedure->parameters);
    } else if (procedure != nullptr && at_word("returns")) {
      take();
      auto first = expect_name("a result type after 'returns'");
      if (first && at_name()) {
        procedure->return_name = *first;
        procedure->return_type = take().text;
      } else if (first) {
        procedure->return_type = *first;
      }
      end_statement("'returns " + procedure->return_type + "'");
    } else if (procedure != nullptr && (at_word("external") || at_word("referenced"))) {
      (at_word("external") ? procedure->is_external : procedure->is_referenced) = true;
      end_statement("'" + take().text + "'");
      return;
    } else if (composite != nullptr && at_word("in") && at(TokenKind::LParen, 1)) {
      for (auto& point : parse_point_list("in")) composite->entry_points.push_back(point);
    } else if (composite != nullptr && at_word("out") && at(TokenKind::LParen, 1)) {
      for (auto& point : parse_point_list("out")) composite->exit_points.push_back(point);
    } else if (!accept(TokenKind::Semicolon)) {
      error_unexpected("'dcl', 'timer', 'procedure', 'start', 'state', 'connection' or '" +
                       std::string(end_word) + "'");
      skip_past_semicolon();
    }
  }
}

void Parser::parse_variables(std::vector<Variable>& variables) {
  take();
  do {
    std::vector<Variable> group;
    do {
      Variable variable;
      variable.at = peek().at;
      auto name = expect_name("a variable name after 'dcl'");
      if (!name) break;
      variable.name = *name;
      group.push_back(std::move(variable));
    } while (accept(TokenKind::Comma));
    if (group.empty()) break;
    auto type = expect_name("a type name after variable " + group.back().name);
    if (!type) break;
    std::optional<Expr> initial;
    if (accept(TokenKind::Assign)) initial = parse_expression();
    for (Variable& variable : group) {
      variable.type = *type;
      variable.initial = initial;
      variables.push_back(std::move(variable));
    }
  } while (accept(TokenKind::Comma));
  parse_comment();
  end_statement("a 'dcl' declaration");
}

void Parser::parse_formal_parameters(std::vector<FormalParameter>& parameters) {
  take();
  do {
    FormalParameter::Direction direction = FormalParameter::Direction::In;
    const Location at = peek().at;
    if (accept_word("in")) {
      if (accept(TokenKind::Slash)) {
        expect_word("out", "after 'in/'");
        direction = FormalParameter::Direction::InOut;
      }
    } else if (accept_word("out")) {
      direction = FormalParameter::Direction::Out;
    }
    std::vector<FormalParameter> group;
    do {
      FormalParameter parameter;
      parameter.at = group.empty() ? at : peek().at;
      parameter.direction = direction;
      auto name = expect_name("a parameter name after 'fpar'");
      if (!name) break;
      parameter.name = *name;
      group.push_back(std::move(parameter));
    } while (accept(TokenKind::Comma));
    if (group.empty()) break;
    auto type = expect_name("a type name after parameter " + group.back().name);
    if (!type) break;
    for (FormalParameter& parameter : group) {
      parameter.type = *type;
      parameters.push_back(std::move(parameter));
    }
  } while (accept(TokenKind::Comma));
  end_statement("'fpar'");
}

}  // namespace smcbip::taste2bip::sdl::detail
