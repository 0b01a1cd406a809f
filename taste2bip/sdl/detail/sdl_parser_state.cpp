// SDL-PR parser: states with their inputs, continuous signals, saves and exit connections,
// state substructures (nested states), start transitions and floating labels.
#include "taste2bip/sdl/detail/sdl_parser.h"

namespace smcbip::taste2bip::sdl::detail {

void Parser::parse_state(Body& body) {
  State state;
  state.at = take().at;
  const bool is_aggregation = at_word("aggregation") && at_name(1);
  if (is_aggregation) take();
  if (accept(TokenKind::Star)) {
    state.is_any = true;
    if (accept(TokenKind::LParen)) {
      do {
        if (auto name = expect_name("a state name in 'state *(...)'")) {
          state.except.push_back(*name);
        }
      } while (accept(TokenKind::Comma));
      expect(TokenKind::RParen, "closing the states of 'state *('");
    }
  } else {
    do {
      auto name = expect_name("a state name or '*' after 'state'");
      if (!name) break;
      state.names.push_back(*name);
    } while (accept(TokenKind::Comma));
  }
  if (accept_word("via")) {
    if (auto entry = expect_name("an entry point after 'via'")) state.via = *entry;
  }
  state.comment = parse_comment();
  const std::string shown = state.is_any ? "*" : state.names.empty() ? "" : state.names.front();
  end_statement("'state " + shown + "'");
  if (at_word("substructure") || is_aggregation) {
    CompositeState composite;
    composite.at = state.at;
    composite.name = shown;
    composite.is_aggregation = is_aggregation;
    if (state.names.size() != 1 || !state.via.empty()) {
      error_here("a substructure belongs to one state named without 'via'");
    }
    expect_word("substructure", "after 'state aggregation " + shown + "'");
    parse_body(composite.body, BodyEnd::Substructure, nullptr, &composite);
    if (at_word("endsubstructure")) {
      parse_end();
    } else if (!stopped()) {
      error_here("expected 'endsubstructure' closing the substructure of state " + shown +
                 ", got " + describe(peek()));
    }
    body.composite_states.push_back(std::move(composite));
    return;
  }
  parse_state_parts(state);
  body.states.push_back(std::move(state));
}

void Parser::parse_state_parts(State& state) {
  while (!at_eof() && !at_word("endstate")) {
    Nesting nesting(*this);
    if (at_word("input")) {
      state.inputs.push_back(parse_input());
    } else if (at_word("provided")) {
      state.continuous.push_back(parse_continuous_signal());
    } else if (at_word("connect")) {
      state.connections.push_back(parse_exit_connection());
    } else if (at_word("save")) {
      take();
      if (accept(TokenKind::Star)) {
        state.saves.push_back("*");
      } else {
        do {
          auto name = expect_name("a signal name after 'save'");
          if (!name) break;
          state.saves.push_back(*name);
        } while (accept(TokenKind::Comma));
      }
      end_statement("'save'");
    } else {
      error_unexpected("'input', 'provided', 'save', 'connect' or 'endstate'");
      skip_past_semicolon();
    }
  }
  if (at_word("endstate")) {
    parse_end();
  } else if (!stopped()) {
    error_here("expected 'endstate', got end of file");
  }
}

Input Parser::parse_input() {
  Input input;
  input.at = take().at;
  if (accept(TokenKind::Star)) {
    input.is_any = true;
  } else {
    do {
      InputSignal signal;
      signal.at = peek().at;
      auto name = expect_name("a signal name or '*' after 'input'");
      if (!name) break;
      signal.name = *name;
      if (accept(TokenKind::LParen)) {
        do {
          if (auto parameter = expect_name("a variable for a parameter of " + signal.name)) {
            signal.parameters.push_back(*parameter);
          }
        } while (accept(TokenKind::Comma));
        expect(TokenKind::RParen, "closing the parameters of input " + signal.name);
      }
      input.signals.push_back(std::move(signal));
    } while (accept(TokenKind::Comma));
  }
  parse_comment();
  end_statement(input.is_any            ? std::string("'input *'")
                : input.signals.empty() ? std::string("'input'")
                                        : "'input " + input.signals.front().name + "'");
  // As in OpenGEODE's grammar, a 'provided' right after an input is its enabling condition.
  if (accept_word("provided")) {
    input.enabling = parse_expression();
    parse_comment();
    end_statement("the enabling condition of 'input'");
  }
  input.transition = parse_transition();
  return input;
}

ContinuousSignal Parser::parse_continuous_signal() {
  ContinuousSignal signal;
  signal.at = take().at;
  signal.condition = parse_expression();
  parse_comment();
  end_statement("the condition of 'provided'");
  if (accept_word("priority")) {
    signal.priority = parse_expression();
    end_statement("'priority'");
  }
  signal.transition = parse_transition();
  return signal;
}

ExitConnection Parser::parse_exit_connection() {
  ExitConnection connection;
  connection.at = take().at;
  if (accept(TokenKind::Star)) {
    connection.exit_points.push_back("*");
  } else if (at_name()) {
    do {
      if (auto name = expect_name("an exit point name after 'connect'")) {
        connection.exit_points.push_back(*name);
      }
    } while (accept(TokenKind::Comma));
  }
  parse_comment();
  end_statement("'connect'");
  connection.transition = parse_transition();
  return connection;
}

Start Parser::parse_start() {
  Start start;
  start.at = take().at;
  if (at_name()) start.entry_point = take().text;
  parse_comment();
  end_statement("'start'");
  start.transition = parse_transition();
  return start;
}

FloatingLabel Parser::parse_floating_label() {
  FloatingLabel label;
  label.at = take().at;
  if (auto name = expect_name("a label name after 'connection'")) label.name = *name;
  expect(TokenKind::Colon, "after 'connection " + label.name + "'");
  label.transition = parse_transition();
  if (at_word("endconnection")) {
    parse_end();
  } else if (!stopped()) {
    error_here("expected 'endconnection' closing connection " + label.name + ", got " +
               describe(peek()));
    skip_past_semicolon();
  }
  return label;
}

}  // namespace smcbip::taste2bip::sdl::detail
