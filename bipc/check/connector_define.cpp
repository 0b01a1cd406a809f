// A connector's define expression: checking its leaves, and deciding whether a set of ports is
// one of the interactions it defines (language.rst, "Defined interactions").
#include <algorithm>
#include <string>
#include <unordered_map>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using PortIndex = std::unordered_map<std::string, int>;

/// Port parameter names to indices (the first of duplicates), built once: a broadcast connector
/// may have thousands of ports, so a linear search per leaf would be quadratic.
PortIndex index_ports(const ast::ConnectorTypeDecl& connector) {
  PortIndex index;
  for (std::size_t i = 0; i < connector.ports.size(); ++i) {
    index.emplace(connector.ports[i].name.text, static_cast<int>(i));
  }
  return index;
}

void visit_leaves(std::vector<ast::PortExpr>& nodes, const ast::ConnectorTypeDecl& connector,
                  const PortIndex& port_index, std::vector<bool>& seen, Diagnostics& diags) {
  for (ast::PortExpr& node : nodes) {
    visit_leaves(node.children, connector, port_index, seen, diags);
    if (!node.port) continue;
    const auto found = port_index.find(node.port->text);
    node.port_index = found == port_index.end() ? -1 : found->second;
    if (node.port_index < 0) {
      if (!node.port->text.empty()) {
        diags.error(node.port->loc, "unknown port '" + node.port->text +
                                        "' in define: undeclared port parameter of '" +
                                        connector.name.text + "'");
      }
      continue;
    }
    if (seen[node.port_index]) {
      diags.error(node.port->loc,
                  "port '" + node.port->text + "' appears twice in define (duplicate port)");
      node.port_index = -1;
      continue;
    }
    seen[node.port_index] = true;
  }
}

void collect_leaves(const ast::PortExpr& node, std::size_t owner,
                    std::unordered_map<int, std::size_t>& owners) {
  if (node.port) owners.emplace(node.port_index, owner);
  for (const ast::PortExpr& child : node.children) collect_leaves(child, owner, owners);
}

bool allows_sequence(const std::vector<ast::PortExpr>& nodes, const std::vector<int>& ports);

bool allows_node(const ast::PortExpr& node, const std::vector<int>& ports) {
  if (node.port) return ports.size() == 1 && ports.front() == node.port_index;
  return allows_sequence(node.children, ports);
}

/// `e1 ... eN` defines the unions of interactions of the e_i that include an interaction of a
/// trigger, or one of every e_i. The e_i cover disjoint ports, so the union splits uniquely.
bool allows_sequence(const std::vector<ast::PortExpr>& nodes, const std::vector<int>& ports) {
  if (ports.empty() || nodes.empty()) return false;
  std::unordered_map<int, std::size_t> owner;
  for (std::size_t i = 0; i < nodes.size(); ++i) collect_leaves(nodes[i], i, owner);
  std::vector<std::vector<int>> parts(nodes.size());
  for (int port : ports) {
    auto found = owner.find(port);
    if (found == owner.end()) return false;
    parts[found->second].push_back(port);
  }
  bool trigger = false;
  bool every = true;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (parts[i].empty()) {
      every = false;
      continue;
    }
    if (!allows_node(nodes[i], parts[i])) return false;
    trigger = trigger || nodes[i].trigger;
  }
  return trigger || every;
}

}  // namespace

void check_define(ast::ConnectorTypeDecl& connector, Diagnostics& diags) {
  std::vector<bool> seen(connector.ports.size(), false);
  visit_leaves(connector.define, connector, index_ports(connector), seen, diags);
  if (connector.define.empty()) return;  // missing define: a syntax error, reported by the parser
  for (std::size_t i = 0; i < connector.ports.size(); ++i) {
    if (seen[i] || connector.ports[i].name.text.empty()) continue;
    diags.error(connector.ports[i].name.loc, "port '" + connector.ports[i].name.text +
                                                 "' does not appear in define: every port "
                                                 "parameter must appear there exactly once");
  }
}

bool define_allows(const std::vector<ast::PortExpr>& define, const std::vector<int>& ports) {
  std::vector<int> set = ports;
  std::sort(set.begin(), set.end());
  set.erase(std::unique(set.begin(), set.end()), set.end());
  if (!set.empty() && set.front() < 0) return false;
  return allows_sequence(define, set);
}

}  // namespace smcbip::bipc::detail
