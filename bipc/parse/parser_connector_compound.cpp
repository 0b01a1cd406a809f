// Parser of connector types (define, interactions) and compound types (instances, priorities,
// exports).
#include <utility>

#include "bipc/parse/parser.h"

namespace smcbip::bipc::detail {

// ---------------------------------------------------------------------------------------------
// Connector types

ast::ConnectorTypeDecl Parser::parse_connector_type(ast::Annotations annotations) {
  ast::ConnectorTypeDecl connector;
  connector.loc = take().loc;  // `connector`
  connector.annotations = std::move(annotations);
  expect(TokenKind::KwType, "after 'connector'");
  connector.name = expect_name("a connector type name");
  const std::string owner = "connector type '" + connector.name.text + "'";
  expect(TokenKind::LParen, "after the name of " + owner);
  do {
    ast::ConnectorTypeDecl::PortParam port;
    port.loc = peek().loc;
    port.type = parse_qualified_name("a port type name");
    port.name = expect_name("a port parameter name");
    connector.ports.push_back(std::move(port));
  } while (accept(TokenKind::Comma));
  expect(TokenKind::RParen, "to close the port parameters of " + owner);

  for (;;) {
    ast::Annotations declaration_annotations = parse_annotations();
    if (at(TokenKind::KwData)) {
      if (connector.export_port) {
        fail_at(peek().loc, "data declarations must come before 'export port' in " + owner);
      }
      for (ast::DataDecl& data :
           parse_data_declaration(std::move(declaration_annotations), false)) {
        connector.data.push_back(std::move(data));
      }
    } else if (at(TokenKind::KwExport)) {
      if (connector.export_port) fail_at(peek().loc, owner + " exports at most one port");
      ast::ConnectorExportPort port;
      port.annotations = std::move(declaration_annotations);
      port.loc = take().loc;
      expect(TokenKind::KwPort, "after 'export' (a connector type exports one port)");
      port.type = parse_qualified_name("a port type name");
      port.name = expect_name("the name of the exported port");
      port.bound_data = parse_bound_data(port.name);
      connector.export_port = std::move(port);
    } else if (at(TokenKind::KwDefine) && declaration_annotations.empty()) {
      break;
    } else {
      fail(declaration_annotations.empty()
               ? "a data declaration, 'export port' or 'define' in " + owner
               : std::string("'data' or 'export' after annotations"));
    }
  }
  connector.define_loc = take().loc;  // `define`
  connector.define = parse_port_expressions();
  if (connector.define.empty()) fail("a port name or '(' after 'define'");
  if (accept(TokenKind::KwResume)) {
    if (accept(TokenKind::KwSync))
      connector.resume = ast::ConnectorResume::Sync;
    else if (accept(TokenKind::KwAsync))
      connector.resume = ast::ConnectorResume::Async;
    else
      fail("'sync' or 'async' after 'resume'");
  }
  while (at(TokenKind::AtSign) || at(TokenKind::KwOn)) {
    ast::Annotations interaction_annotations = parse_annotations();
    if (!at(TokenKind::KwOn)) fail("'on' (an interaction) after annotations");
    connector.interactions.push_back(parse_interaction(std::move(interaction_annotations)));
  }
  if (!at(TokenKind::KwEnd)) {
    if (at(TokenKind::KwData) || at(TokenKind::KwExport)) {
      fail_at(peek().loc, "data and exported port must come before 'define' in " + owner);
    }
    if (at(TokenKind::KwDefine)) fail_at(peek().loc, owner + " has a single 'define'");
    fail("'end' to close " + owner);
  }
  take();
  return connector;
}

std::vector<ast::PortExpr> Parser::parse_port_expressions() {
  std::vector<ast::PortExpr> sequence;
  while (at_name() || at(TokenKind::LParen)) {
    ast::PortExpr element;
    element.loc = peek().loc;
    if (at(TokenKind::LParen)) {
      DepthGuard guard(*this);
      take();
      element.children = parse_port_expressions();
      if (element.children.empty()) fail("a port name or '(' in a port expression");
      expect(TokenKind::RParen, "to close the nested port expression");
    } else {
      element.port = ident_of(take());
    }
    element.trigger = accept(TokenKind::Quote);
    sequence.push_back(std::move(element));
  }
  return sequence;
}

ast::InteractionDecl Parser::parse_interaction(ast::Annotations annotations) {
  ast::InteractionDecl interaction;
  interaction.annotations = std::move(annotations);
  interaction.loc = take().loc;  // `on`
  auto at_action = [this] {
    return (at(TokenKind::KwUp) || at(TokenKind::KwDown)) && kind(1) == TokenKind::LBrace;
  };
  while (at_name() && !at_action()) interaction.ports.push_back(ident_of(take()));
  if (interaction.ports.empty()) fail("a port name after 'on'");
  if (accept(TokenKind::KwProvided)) interaction.guard = parse_parenthesized_guard("provided");
  if (at(TokenKind::KwUp)) {
    interaction.up_loc = take().loc;
    interaction.has_up = true;
    interaction.up = parse_block("after 'up'");
  }
  if (at(TokenKind::KwDown)) {
    interaction.down_loc = take().loc;
    interaction.has_down = true;
    interaction.down = parse_block("after 'down'");
  }
  return interaction;
}

// ---------------------------------------------------------------------------------------------
// Compound types

ast::CompoundTypeDecl Parser::parse_compound_type(ast::Annotations annotations) {
  ast::CompoundTypeDecl compound;
  compound.loc = take().loc;  // `compound`
  compound.annotations = std::move(annotations);
  expect(TokenKind::KwType, "after 'compound'");
  compound.name = expect_name("a compound type name");
  const std::string owner = "compound type '" + compound.name.text + "'";
  compound.params = parse_data_params(owner);

  // Annotations read before the first export belong to it.
  std::optional<ast::Annotations> pending;
  for (;;) {
    ast::Annotations instance_annotations = parse_annotations();
    if (at(TokenKind::KwComponent)) {
      parse_component_declaration(compound, std::move(instance_annotations));
    } else if (at(TokenKind::KwConnector)) {
      parse_connector_declaration(compound, std::move(instance_annotations));
    } else {
      if (!instance_annotations.empty()) {
        if (!at(TokenKind::KwExport))
          fail("'component', 'connector' or 'export' after annotations");
        pending = std::move(instance_annotations);
      }
      break;
    }
  }
  if (compound.components.empty() && compound.connectors.empty()) {
    fail("a component or connector declaration in " + owner);
  }
  while (!pending && at(TokenKind::KwPriority)) {
    compound.priorities.push_back(parse_compound_priority());
  }
  for (;;) {
    ast::Annotations export_annotations;
    if (pending) {
      export_annotations = std::move(*pending);
      pending.reset();
    } else {
      export_annotations = parse_annotations();
    }
    if (at(TokenKind::KwExport)) {
      parse_compound_export(compound, std::move(export_annotations));
    } else {
      if (!export_annotations.empty()) fail("'export' after annotations");
      break;
    }
  }
  if (!at(TokenKind::KwEnd)) {
    if (at(TokenKind::KwComponent) || at(TokenKind::KwConnector)) {
      fail_at(peek().loc,
              "component and connector declarations must come before priorities and "
              "exports in " +
                  owner);
    }
    if (at(TokenKind::KwPriority)) {
      fail_at(peek().loc, "priorities must come before exports in " + owner);
    }
    fail("'end' to close " + owner);
  }
  take();
  return compound;
}

std::vector<ast::ExprPtr> Parser::parse_arguments(std::string_view context) {
  std::vector<ast::ExprPtr> args;
  expect(TokenKind::LParen, context);
  if (accept(TokenKind::RParen)) return args;
  do {
    args.push_back(parse_expression());
  } while (accept(TokenKind::Comma));
  expect(TokenKind::RParen, "to close the argument list");
  return args;
}

void Parser::parse_component_declaration(ast::CompoundTypeDecl& compound,
                                         ast::Annotations annotations) {
  take();  // `component`
  ast::QualifiedName type = parse_qualified_name("a component type name after 'component'");
  do {
    ast::ComponentDecl component;
    component.type = type;
    component.name = expect_name("a component name");
    component.loc = component.name.loc;
    component.annotations = annotations;
    component.args = parse_arguments("after component name '" + component.name.text + "'");
    compound.components.push_back(std::move(component));
  } while (accept(TokenKind::Comma));
}

void Parser::parse_connector_declaration(ast::CompoundTypeDecl& compound,
                                         ast::Annotations annotations) {
  take();  // `connector`
  ast::QualifiedName type = parse_qualified_name("a connector type name after 'connector'");
  do {
    ast::ConnectorDecl connector;
    connector.type = type;
    connector.name = expect_name("a connector name");
    connector.loc = connector.name.loc;
    connector.annotations = annotations;
    expect(TokenKind::LParen, "after connector name '" + connector.name.text + "'");
    do {
      connector.ports.push_back(parse_qualified_name("a port such as 'component.port'"));
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RParen, "to close the ports of connector '" + connector.name.text + "'");
    compound.connectors.push_back(std::move(connector));
  } while (accept(TokenKind::Comma));
}

ast::InteractionPattern Parser::parse_interaction_pattern() {
  ast::InteractionPattern pattern;
  pattern.loc = peek().loc;
  if (accept(TokenKind::Star)) {
    expect(TokenKind::Colon, "after '*' (the wildcard interaction is '*:*')");
    expect(TokenKind::Star, "after '*:' (the wildcard interaction is '*:*')");
    return pattern;
  }
  pattern.connector = expect_name("a connector name or '*:*'");
  expect(TokenKind::Colon, "after connector name '" + pattern.connector->text + "'");
  if (accept(TokenKind::Star)) {
    pattern.all_ports = true;
    return pattern;
  }
  do {
    pattern.ports.push_back(parse_qualified_name("a port such as 'component.port', or '*'"));
  } while (accept(TokenKind::Comma));
  return pattern;
}

ast::CompoundPriorityDecl Parser::parse_compound_priority() {
  ast::CompoundPriorityDecl priority;
  priority.loc = take().loc;  // `priority`
  priority.name = expect_name("a priority name after 'priority'");
  priority.low = parse_interaction_pattern();
  expect(TokenKind::Lt, "between the interactions of priority '" + priority.name.text + "'");
  priority.high = parse_interaction_pattern();
  if (accept(TokenKind::KwProvided)) priority.guard = parse_parenthesized_guard("provided");
  return priority;
}

void Parser::parse_compound_export(ast::CompoundTypeDecl& compound, ast::Annotations annotations) {
  Location start = take().loc;  // `export`
  if (accept(TokenKind::KwPort)) {
    ast::PortExportDecl port;
    port.loc = start;
    port.annotations = std::move(annotations);
    do {
      port.ports.push_back(parse_qualified_name("a port such as 'component.port'"));
    } while (accept(TokenKind::Comma));
    expect(TokenKind::KwAs, "after the exported ports");
    port.name = expect_name("the name of the exported port after 'as'");
    compound.port_exports.push_back(std::move(port));
    return;
  }
  if (accept(TokenKind::KwData)) {
    ast::DataExportDecl data;
    data.loc = start;
    data.annotations = std::move(annotations);
    data.data = parse_qualified_name("a data such as 'component.data'");
    expect(TokenKind::KwAs, "after the exported data");
    data.name = expect_name("the name of the exported data after 'as'");
    compound.data_exports.push_back(std::move(data));
    return;
  }
  fail("'port' or 'data' after 'export'");
}

}  // namespace smcbip::bipc::detail
