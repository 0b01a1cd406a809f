// Parser of atom types: data, ports, clocks, places, transitions, priorities and invariants.
#include <utility>

#include "bipc/parse/parser.h"

namespace smcbip::bipc::detail {

namespace {

std::string atom_owner(const ast::AtomTypeDecl& atom) {
  return "atom type '" + atom.name.text + "'";
}

bool is_atom_declaration_start(TokenKind kind) {
  switch (kind) {
    case TokenKind::AtSign:
    case TokenKind::KwData:
    case TokenKind::KwExport:
    case TokenKind::KwPort:
    case TokenKind::KwExtern:
    case TokenKind::KwClock:
      return true;
    default:
      return false;
  }
}

}  // namespace

ast::AtomTypeDecl Parser::parse_atom_type(ast::Annotations annotations) {
  ast::AtomTypeDecl atom;
  atom.loc = take().loc;  // `atom`
  atom.annotations = std::move(annotations);
  expect(TokenKind::KwType, "after 'atom'");
  atom.name = expect_name("an atom type name");
  const std::string owner = atom_owner(atom);
  atom.params = parse_data_params(owner);

  while (is_atom_declaration_start(kind())) parse_atom_declaration(atom);
  if (!at(TokenKind::KwPlace)) fail("a data, port or clock declaration or 'place' in " + owner);
  take();
  atom.places = parse_name_list("a place name");
  if (!at(TokenKind::KwInitial)) fail("'initial' (the initial transition) in " + owner);
  parse_initial(atom);

  while (at(TokenKind::AtSign) || at(TokenKind::KwOn) || at(TokenKind::KwInternal)) {
    ast::Annotations transition_annotations = parse_annotations();
    if (!at(TokenKind::KwOn) && !at(TokenKind::KwInternal)) {
      fail("'on' or 'internal' (a transition) after annotations");
    }
    atom.transitions.push_back(parse_transition(std::move(transition_annotations)));
  }
  while (at(TokenKind::KwPriority) || at(TokenKind::KwInvariant)) {
    if (at(TokenKind::KwPriority)) {
      atom.priorities.push_back(parse_atom_priority());
    } else {
      atom.invariants.push_back(parse_invariant());
    }
  }
  if (!at(TokenKind::KwEnd)) {
    Location here = peek().loc;
    if (is_atom_declaration_start(kind()) && !at(TokenKind::AtSign)) {
      fail_at(here, "data, port and clock declarations must come before 'place' in " + owner);
    }
    if (at(TokenKind::KwPlace)) fail_at(here, owner + " has a single 'place' declaration");
    if (at(TokenKind::KwInitial)) fail_at(here, owner + " has a single initial transition");
    if (at(TokenKind::KwOn) || at(TokenKind::KwInternal)) {
      fail_at(here, "transitions must come before priorities and invariants in " + owner);
    }
    fail("'end' to close " + owner);
  }
  take();
  return atom;
}

void Parser::parse_atom_declaration(ast::AtomTypeDecl& atom) {
  ast::Annotations annotations = parse_annotations();
  switch (kind()) {
    case TokenKind::KwData: {
      for (ast::DataDecl& data : parse_data_declaration(std::move(annotations), false)) {
        atom.data.push_back(std::move(data));
      }
      return;
    }
    case TokenKind::KwExport:
      take();
      if (at(TokenKind::KwData)) {
        for (ast::DataDecl& data : parse_data_declaration(std::move(annotations), true)) {
          atom.data.push_back(std::move(data));
        }
        return;
      }
      if (at(TokenKind::KwPort)) {
        parse_port_declaration(atom, std::move(annotations), true, false);
        return;
      }
      fail("'data' or 'port' after 'export'");
    case TokenKind::KwPort:
      parse_port_declaration(atom, std::move(annotations), false, false);
      return;
    case TokenKind::KwExtern:
      take();
      if (!at(TokenKind::KwPort)) {
        fail("'port' after 'extern' (an atom type declares extern ports only)");
      }
      parse_port_declaration(atom, std::move(annotations), false, true);
      return;
    case TokenKind::KwClock:
      parse_clock_declaration(atom, std::move(annotations));
      return;
    default:
      fail("a data, port or clock declaration after annotations");
  }
}

std::vector<ast::DataDecl> Parser::parse_data_declaration(ast::Annotations annotations,
                                                          bool exported) {
  take();  // `data`
  if (!at_data_type_start()) fail("a data type after 'data'");
  ast::TypeRef type = parse_data_type(true);
  std::vector<ast::DataDecl> declared;
  do {
    ast::DataDecl data;
    data.type = type;
    data.name = expect_name("a data name");
    data.loc = data.name.loc;
    data.exported = exported;
    data.annotations = annotations;
    if (accept(TokenKind::Assign)) data.initial_value = parse_expression();
    declared.push_back(std::move(data));
  } while (accept(TokenKind::Comma));
  return declared;
}

void Parser::parse_port_declaration(ast::AtomTypeDecl& atom, ast::Annotations annotations,
                                    bool exported, bool is_extern) {
  take();  // `port`
  ast::QualifiedName type = parse_qualified_name("a port type name after 'port'");
  const std::size_t first = atom.ports.size();
  do {
    ast::PortDecl port;
    port.type = type;
    port.name = expect_name("a port name");
    port.loc = port.name.loc;
    port.exported = exported;
    port.is_extern = is_extern;
    port.annotations = annotations;
    port.bound_data = parse_bound_data(port.name);
    atom.ports.push_back(std::move(port));
  } while (accept(TokenKind::Comma));

  std::optional<ast::Ident> merged_as;
  std::optional<std::string> backend_name;
  std::optional<ast::ExternPolicy> policy;
  if (exported && accept(TokenKind::KwAs)) {
    merged_as = expect_name("the name of the merged port after 'as'");
  }
  if (is_extern) {
    if (accept(TokenKind::KwAs)) {
      if (!at(TokenKind::String)) fail("a string naming the back-end port class after 'as'");
      backend_name = take().string_value;
    }
    if (accept(TokenKind::KwRemember))
      policy = ast::ExternPolicy::Remember;
    else if (accept(TokenKind::KwIgnore))
      policy = ast::ExternPolicy::Ignore;
    else if (accept(TokenKind::KwError))
      policy = ast::ExternPolicy::Error;
  }
  for (std::size_t i = first; i < atom.ports.size(); ++i) {
    atom.ports[i].merged_as = merged_as;
    atom.ports[i].backend_name = backend_name;
    atom.ports[i].policy = policy;
  }
}

void Parser::parse_clock_declaration(ast::AtomTypeDecl& atom, ast::Annotations annotations) {
  take();  // `clock`
  std::vector<ast::Ident> names = parse_name_list("a clock name");
  std::optional<ast::TimeUnit> unit;
  if (accept(TokenKind::KwUnit)) {
    switch (kind()) {
      case TokenKind::KwNanosecond:
        unit = ast::TimeUnit::Nanosecond;
        break;
      case TokenKind::KwMicrosecond:
        unit = ast::TimeUnit::Microsecond;
        break;
      case TokenKind::KwMillisecond:
        unit = ast::TimeUnit::Millisecond;
        break;
      case TokenKind::KwSecond:
        unit = ast::TimeUnit::Second;
        break;
      case TokenKind::KwMinute:
        unit = ast::TimeUnit::Minute;
        break;
      case TokenKind::KwHour:
        unit = ast::TimeUnit::Hour;
        break;
      case TokenKind::KwDay:
        unit = ast::TimeUnit::Day;
        break;
      default:
        fail(
            "a time unit (nanosecond, microsecond, millisecond, second, minute, hour or day) "
            "after 'unit'");
    }
    take();
  }
  for (ast::Ident& name : names) {
    ast::ClockDecl clock;
    clock.loc = name.loc;
    clock.name = std::move(name);
    clock.unit = unit;
    clock.annotations = annotations;
    atom.clocks.push_back(std::move(clock));
  }
}

std::optional<ast::ResumeClause> Parser::parse_optional_resume() {
  if (!at(TokenKind::KwResume)) return std::nullopt;
  ast::ResumeClause resume;
  resume.loc = take().loc;
  if (at(TokenKind::LParen)) resume.guard = parse_parenthesized_guard("resume");
  return resume;
}

void Parser::parse_initial(ast::AtomTypeDecl& atom) {
  atom.initial.loc = take().loc;  // `initial`
  expect(TokenKind::KwTo, "after 'initial'");
  atom.initial.to = parse_name_list("a place name");
  if (accept(TokenKind::KwDo)) atom.initial.action = parse_block("after 'do'");
  atom.initial.resume = parse_optional_resume();
}

ast::Transition Parser::parse_transition(ast::Annotations annotations) {
  ast::Transition transition;
  transition.annotations = std::move(annotations);
  const bool internal = at(TokenKind::KwInternal);
  transition.loc = take().loc;
  if (!internal) transition.port = expect_name("a port name after 'on'");
  expect(TokenKind::KwFrom, internal ? "after 'internal'" : "after the port of the transition");
  transition.from = parse_name_list("a place name");
  expect(TokenKind::KwTo, "after the source places of the transition");
  transition.to = parse_name_list("a place name");
  if (accept(TokenKind::KwProvided)) transition.guard = parse_parenthesized_guard("provided");
  std::optional<ast::Urgency> urgency;
  Location urgency_loc = peek().loc;
  if (accept(TokenKind::KwEager))
    urgency = ast::Urgency::Eager;
  else if (accept(TokenKind::KwDelayable))
    urgency = ast::Urgency::Delayable;
  else if (accept(TokenKind::KwLazy))
    urgency = ast::Urgency::Lazy;
  if (urgency && internal) {
    // Bip2.g gives internal transitions no urgency; say so instead of a generic error.
    report(urgency_loc, "an internal transition has no urgency");
  }
  transition.urgency = urgency;
  if (accept(TokenKind::KwDo)) {
    transition.has_action = true;
    transition.action = parse_block("after 'do'");
  }
  Location resume_loc = peek().loc;
  transition.resume = parse_optional_resume();
  if (transition.resume && internal) {
    report(resume_loc, "an internal transition has no 'resume' clause");
  }
  return transition;
}

ast::AtomPriorityDecl Parser::parse_atom_priority() {
  ast::AtomPriorityDecl priority;
  priority.loc = take().loc;  // `priority`
  priority.name = expect_name("a priority name after 'priority'");
  const std::string hint = " (an atom priority is 'priority NAME low < high')";
  priority.low_loc = peek().loc;
  if (!accept(TokenKind::Star)) priority.low = expect_name("a port name or '*'" + hint);
  expect(TokenKind::Lt, "between the ports of priority '" + priority.name.text + "'");
  priority.high_loc = peek().loc;
  if (!accept(TokenKind::Star)) priority.high = expect_name("a port name or '*'" + hint);
  if (accept(TokenKind::KwProvided)) priority.guard = parse_parenthesized_guard("provided");
  return priority;
}

ast::InvariantDecl Parser::parse_invariant() {
  ast::InvariantDecl invariant;
  invariant.loc = take().loc;  // `invariant`
  invariant.name = expect_name("an invariant name after 'invariant'");
  if (accept(TokenKind::KwAt)) {
    invariant.at = true;
    invariant.places = parse_name_list("a place name");
  } else if (accept(TokenKind::KwFrom)) {
    invariant.at = false;
    invariant.places = parse_name_list("a place name");
  }
  if (!at(TokenKind::KwProvided)) {
    fail(std::string(invariant.places.empty() ? "'at', 'from' or " : "") +
         "'provided' in invariant '" + invariant.name.text + "'");
  }
  take();
  invariant.guard = parse_parenthesized_guard("provided");
  return invariant;
}

}  // namespace smcbip::bipc::detail
