// Connector types: port parameters, local data, the exported port, the define expression and the
// interactions (`on p q provided (...) up {...} down {...}`).
#include <algorithm>
#include <map>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using Where = ExprContext::Where;

void declare_names(const ast::ConnectorTypeDecl& connector, Diagnostics& diags) {
  std::vector<const ast::Ident*> names;
  for (const ast::ConnectorTypeDecl::PortParam& port : connector.ports) names.push_back(&port.name);
  for (const ast::DataDecl& data : connector.data) names.push_back(&data.name);
  if (connector.export_port) names.push_back(&connector.export_port->name);
  declare_in_source_order(names, diags);
}

void check_port_params(ast::ConnectorTypeDecl& connector, const ast::Package& package,
                       const Symbols& symbols, Diagnostics& diags) {
  for (ast::ConnectorTypeDecl::PortParam& port : connector.ports) {
    port.port_type = resolve_port_type(port.type, package, symbols, diags);
  }
}

/// The exported port binds connector data, of exactly the port type's parameter types.
void check_export_port(ast::ConnectorTypeDecl& connector, const ast::Package& package,
                       const Symbols& symbols, Diagnostics& diags) {
  if (!connector.export_port) return;
  ast::ConnectorExportPort& port = *connector.export_port;
  port.port_type = resolve_port_type(port.type, package, symbols, diags);
  check_bound_count("exported port", port.name, port.type, port.port_type, port.bound_data.size(),
                    diags);
  port.bound_data_index.clear();
  for (std::size_t k = 0; k < port.bound_data.size(); ++k) {
    const ast::Ident& bound = port.bound_data[k];
    const int d = index_of(connector.data, bound.text);
    const bool constant = d >= 0
                              ? connector.data[d].type.is_const
                              : symbols.constant(package, ast::QualifiedName{{bound}}) != nullptr;
    port.bound_data_index.push_back(constant ? -1 : d);
    if (constant) {
      report_bound_constant(bound, "data", "an exported port", diags);
    } else if (d < 0) {
      diags.error(bound.loc, "undeclared connector data '" + bound.text +
                                 "' bound by exported port '" + port.name.text + "'");
    } else {
      check_bound_type("exported port", port.name, port.port_type, k, bound,
                       connector.data[d].type.resolved, diags);
    }
  }
}

/// Resolves the ports of an interaction; false when one is unknown or repeated.
bool resolve_interaction_ports(ast::InteractionDecl& interaction,
                               const ast::ConnectorTypeDecl& connector, Diagnostics& diags) {
  bool ok = true;
  interaction.port_index.clear();
  for (const ast::Ident& port : interaction.ports) {
    const int p = index_of(connector.ports, port.text);
    if (p < 0) {
      if (!port.text.empty()) {
        diags.error(port.loc, "unknown port '" + port.text +
                                  "' in interaction: expected a port "
                                  "parameter of '" +
                                  connector.name.text + "'");
      }
      ok = false;
    } else if (std::find(interaction.port_index.begin(), interaction.port_index.end(), p) !=
               interaction.port_index.end()) {
      diags.error(port.loc, "port '" + port.text + "' appears twice in interaction");
      ok = false;
    } else {
      interaction.port_index.push_back(p);
    }
  }
  return ok && !interaction.port_index.empty();
}

/// An interaction is named by its ports, so errors about it point at the first one.
Location interaction_loc(const ast::InteractionDecl& interaction) {
  return interaction.ports.empty() ? interaction.loc : interaction.ports.front().loc;
}

std::string interaction_text(const ast::InteractionDecl& interaction) {
  std::string text;
  for (const ast::Ident& port : interaction.ports) text += (text.empty() ? "" : " ") + port.text;
  return text;
}

void check_actions(ast::InteractionDecl& interaction, const ast::ConnectorTypeDecl& connector,
                   ExprContext ctx, const Symbols& symbols, Diagnostics& diags) {
  ctx.interaction = &interaction;
  if (interaction.guard) {
    ctx.where = Where::ConnectorGuard;
    check_condition(*interaction.guard, ctx, symbols, diags, "an interaction guard");
  }
  // An empty `up {}` computes nothing, so it is harmless (the Verimag compiler only warns).
  if (interaction.has_up && !interaction.up.empty() && !connector.export_port) {
    diags.error(interaction.up_loc, "'up' needs an exported port: connector type '" +
                                        connector.name.text + "' exports none");
  }
  ctx.where = Where::ConnectorUp;
  check_block(interaction.up, ctx, symbols, diags);
  ctx.where = Where::ConnectorDown;
  check_block(interaction.down, ctx, symbols, diags);
}

void check_interactions(ast::ConnectorTypeDecl& connector, const ExprContext& ctx,
                        const Symbols& symbols, Diagnostics& diags) {
  std::map<std::vector<int>, Location> declared;
  for (ast::InteractionDecl& interaction : connector.interactions) {
    if (resolve_interaction_ports(interaction, connector, diags)) {
      std::vector<int> key = interaction.port_index;
      std::sort(key.begin(), key.end());
      auto [first, inserted] = declared.emplace(key, interaction_loc(interaction));
      if (!inserted) {
        diags.error(interaction_loc(interaction), "interaction '" + interaction_text(interaction) +
                                                      "' is declared twice (duplicate "
                                                      "interaction)");
        diags.note(first->second, "it is first declared here");
      } else if (!define_allows(connector.define, key)) {
        diags.error(interaction_loc(interaction), "interaction '" + interaction_text(interaction) +
                                                      "' is not allowed by the define expression");
      }
    }
    check_actions(interaction, connector, ctx, symbols, diags);
  }
}

/// Data exported through the port are computed by `up`. Without any, the port offers the data's
/// initial values: legal, though rarely meant, so a warning as in the Verimag front end.
void check_up_exists(const ast::ConnectorTypeDecl& connector, const ast::Package& package,
                     Diagnostics& diags) {
  if (!connector.export_port || connector.export_port->bound_data.empty()) return;
  if (suppresses(connector.annotations, "missingup") ||
      suppresses(package.annotations, "missingup")) {
    return;
  }
  for (const ast::InteractionDecl& interaction : connector.interactions) {
    if (interaction.has_up) return;
  }
  const ast::ConnectorExportPort& port = *connector.export_port;
  diags.warning(port.name.loc, "exported port '" + port.name.text +
                                   "' binds data that no interaction computes: no interaction of "
                                   "connector type '" +
                                   connector.name.text +
                                   "' has an 'up', so the port offers the data's initial values");
}

}  // namespace

void check_connector_type(ast::ConnectorTypeDecl& type, const ast::Package& package,
                          const Symbols& symbols, Diagnostics& diags) {
  declare_names(type, diags);
  check_port_params(type, package, symbols, diags);
  ExprContext ctx;
  ctx.where = Where::ConnectorUp;  // data initial values: constants and connector data
  ctx.package = &package;
  ctx.connector = &type;
  check_data_declarations(type.data, ctx, symbols, diags);
  check_export_port(type, package, symbols, diags);
  check_define(type, diags);
  check_interactions(type, ctx, symbols, diags);
  check_up_exists(type, package, diags);
}

}  // namespace smcbip::bipc::detail
