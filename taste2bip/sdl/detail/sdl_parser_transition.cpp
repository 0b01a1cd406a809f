// SDL-PR parser: transitions and their actions (tasks, outputs, calls, decisions, labels and the
// terminators nextstate, join, stop and return).
#include "taste2bip/sdl/detail/sdl_parser.h"

namespace smcbip::taste2bip::sdl::detail {

bool Parser::at_action_start() const {
  const Token& token = peek();
  if (token.kind == TokenKind::String) return true;  // informal text without 'task'
  if (token.kind != TokenKind::Word) return false;
  const std::string& w = token.lower;
  if (w == "task" || w == "output" || w == "call" || w == "decision" || w == "join" ||
      w == "nextstate" || w == "stop" || w == "return") {
    return true;
  }
  if ((w == "set" || w == "reset") && at(TokenKind::LParen, 1)) return true;
  if (w == "for") return true;  // a task body without 'task'
  if (!at_name()) return false;
  // A label, or an assignment without 'task' (`x := 1`, `a(1)!b := 2`).
  const TokenKind next = peek(1).kind;
  return next == TokenKind::Colon || next == TokenKind::Assign || next == TokenKind::LParen ||
         next == TokenKind::Dot || next == TokenKind::Bang;
}

Transition Parser::parse_transition() {
  Nesting nesting(*this);
  Transition transition;
  transition.at = peek().at;
  while (!stopped()) {
    if (accept(TokenKind::Semicolon)) continue;  // an empty action, as OpenGEODE accepts it
    if (at_unsupported()) {
      error_unexpected("an action");
      skip_past_semicolon();
      continue;
    }
    if (!at_action_start()) break;
    transition.actions.push_back(parse_action());
    const Action::Kind kind = transition.actions.back().kind;
    if (kind == Action::Kind::NextState || kind == Action::Kind::Join ||
        kind == Action::Kind::Stop || kind == Action::Kind::Return) {
      break;
    }
  }
  return transition;
}

Action Parser::parse_action() {
  Action action;
  action.at = peek().at;
  const std::string word = peek().lower;
  if (at_name() && at(TokenKind::Colon, 1)) {
    action.kind = Action::Kind::Label;
    action.name = take().text;
    take();
    return action;
  }
  const bool timer_statement = (word == "set" || word == "reset") && at(TokenKind::LParen, 1);
  if (word == "output") {
    parse_output(action);
  } else if (word == "call" || timer_statement) {
    parse_call(action);
  } else if (word == "decision") {
    parse_decision(action);
  } else if (word == "join") {
    take();
    action.kind = Action::Kind::Join;
    if (auto name = expect_name("a label name after 'join'")) action.name = *name;
    action.comment = parse_comment();
    end_statement("'join " + action.name + "'");
  } else if (word == "nextstate") {
    take();
    action.kind = Action::Kind::NextState;
    if (accept(TokenKind::Minus)) {
      action.name = accept(TokenKind::Star) ? "-*" : "-";
    } else if (auto name = expect_name("a state name or '-' after 'nextstate'")) {
      action.name = *name;
    }
    if (accept_word("via")) {
      if (auto entry = expect_name("an entry point after 'via'")) action.via = *entry;
    }
    action.comment = parse_comment();
    end_statement("'nextstate " + action.name + "'");
  } else if (word == "stop") {
    take();
    action.kind = Action::Kind::Stop;
    action.comment = parse_comment();
    end_statement("'stop'");
  } else if (word != "return") {
    parse_task(action);  // with 'task' or without (a bare assignment, informal text or loop)
  } else {
    take();
    action.kind = Action::Kind::Return;
    if (!at(TokenKind::Semicolon) && !at_word("comment")) action.value = parse_expression();
    action.comment = parse_comment();
    end_statement("'return'");
  }
  return action;
}

void Parser::parse_task(Action& action) {
  if (at_word("task")) take();
  action.kind = Action::Kind::Task;
  if (at(TokenKind::Semicolon) || at_word("comment")) {  // an empty task
    action.comment = parse_comment();
    end_statement("'task'");
    return;
  }
  do {
    TaskElement element;
    element.at = peek().at;
    if (at(TokenKind::String)) {
      element.kind = TaskElement::Kind::Informal;
      element.text = take().value;
    } else if (at_word("for")) {
      element.kind = TaskElement::Kind::ForLoop;
      element.loop.push_back(parse_for_loop());
    } else {
      element.kind = TaskElement::Kind::Assignment;
      if (!at_name()) {
        error_here("expected an assignment, informal text or 'for' after 'task', got " +
                   describe(peek()));
        skip_past_semicolon();
        return;
      }
      element.target = parse_postfix(false);
      if (!expect(TokenKind::Assign, "in an assignment")) {
        skip_past_semicolon();
        return;
      }
      element.value = parse_expression();
    }
    action.task.push_back(std::move(element));
  } while (accept(TokenKind::Comma));
  action.comment = parse_comment();
  // In a for loop's body, OpenGEODE's inputs write assignments one a line without ';'.
  if (for_loops_ > 0) {
    accept(TokenKind::Semicolon);
  } else {
    end_statement("'task'");
  }
}

ForLoop Parser::parse_for_loop() {
  Nesting nesting(*this);
  ForLoop loop;
  loop.at = take().at;
  if (auto name = expect_name("a loop variable after 'for'")) loop.variable = *name;
  expect_word("in", "after 'for " + loop.variable + "'");
  loop.iterable = parse_postfix(false);
  expect(TokenKind::Colon, "after the range of 'for " + loop.variable + "'");
  ++for_loops_;
  loop.body = parse_transition();
  --for_loops_;
  expect_word("endfor", "closing 'for " + loop.variable + "'");
  return loop;
}

std::vector<Expr> Parser::parse_arguments() {
  std::vector<Expr> arguments;
  if (!accept(TokenKind::LParen)) return arguments;
  if (accept(TokenKind::RParen)) return arguments;
  do {
    arguments.push_back(parse_expression());
  } while (accept(TokenKind::Comma));
  expect(TokenKind::RParen, "closing the arguments");
  return arguments;
}

void Parser::parse_output(Action& action) {
  take();
  action.kind = Action::Kind::Output;
  do {
    OutputSignal signal;
    signal.at = peek().at;
    auto name = expect_name("a signal name after 'output'");
    if (!name) break;
    signal.name = *name;
    signal.arguments = parse_arguments();
    action.outputs.push_back(std::move(signal));
  } while (accept(TokenKind::Comma));
  if (accept_word("to")) action.to = parse_expression();
  if (accept_word("via")) {
    if (auto route = expect_name("a channel or route after 'via'")) action.via = *route;
  }
  action.comment = parse_comment();
  end_statement(action.outputs.empty() ? std::string("'output'")
                                       : "'output " + action.outputs.front().name + "'");
}

void Parser::parse_call(Action& action) {
  action.kind = Action::Kind::Call;
  const bool timer_statement = !at_word("call");
  if (accept_word("call")) {
    if (auto name = expect_name("a procedure name after 'call'")) action.name = *name;
  } else {
    action.name = take().text;  // set(...) / reset(...)
  }
  action.arguments = parse_arguments();
  if (accept_word("to")) action.to = parse_expression();
  action.comment = parse_comment();
  end_statement(timer_statement ? "'" + action.name + "(...)'" : "'call " + action.name + "'");
}

void Parser::parse_decision(Action& action) {
  take();
  action.kind = Action::Kind::Decision;
  if (at_word("any") && at(TokenKind::Semicolon, 1)) {
    take();
    action.decision.is_any = true;
  } else {
    action.decision.question = parse_expression();
  }
  action.comment = parse_comment();
  end_statement("the question of 'decision'");
  while (!at_eof() && !at_word("enddecision")) {
    Nesting nesting(*this);
    if (!at(TokenKind::LParen) && !at_word("else")) {
      error_here("expected an answer '(...):', 'else:' or 'enddecision', got " + describe(peek()));
      skip_past_semicolon();
      continue;
    }
    action.decision.answers.push_back(parse_answer());
  }
  if (at_word("enddecision")) {
    take();
    end_statement("'enddecision'");
  } else if (!stopped()) {
    error_here("expected 'enddecision', got end of file");
  }
}

Answer Parser::parse_answer() {
  Answer answer;
  answer.at = peek().at;
  if (accept_word("else")) {
    answer.is_else = true;
  } else {
    take();  // (
    do {
      answer.conditions.push_back(parse_range_condition());
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RParen, "closing the answer");
  }
  if (!expect(TokenKind::Colon, "after the answer")) {
    skip_past_semicolon();
    return answer;
  }
  answer.transition = parse_transition();
  return answer;
}

RangeCondition Parser::parse_range_condition() {
  RangeCondition condition;
  condition.at = peek().at;
  const Operator op = comparison_operator(peek().kind);
  if (op != Operator::None) {
    take();
    condition.kind = RangeCondition::Kind::Open;
    condition.op = op;
    condition.low = parse_expression();
    return condition;
  }
  condition.low = parse_expression();
  if (accept(TokenKind::Colon)) {
    condition.kind = RangeCondition::Kind::Closed;
    condition.high = parse_expression();
  }
  return condition;
}

}  // namespace smcbip::taste2bip::sdl::detail
