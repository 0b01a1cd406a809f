// SDL-PR parser: the structure of a file (use clauses, systems, blocks, channels, processes,
// procedures and their declarations).
#include "taste2bip/sdl/detail/sdl_parser.h"

#include "taste2bip/sdl/sdl_reader.h"

namespace smcbip::taste2bip::sdl {

SdlFile read_sdl(const std::string& text, std::uint32_t file, bipc::Diagnostics& diags) {
  detail::ErrorBudget errors(diags, detail::kMaxErrors);
  std::vector<detail::Token> tokens = detail::lex_sdl(text, file, errors);
  return detail::Parser(std::move(tokens), errors).parse_file();
}

}  // namespace smcbip::taste2bip::sdl

namespace smcbip::taste2bip::sdl::detail {

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
  channel.no_delay = accept_word("nodelay");
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
