// Largest enabled interactions of define trees.
#include "engines/semantics/maximal_interaction.h"

#include <algorithm>

namespace smcbip::engines {

namespace {

using bipc::ir::DefineNode;

bool calls_anything(const bipc::ir::Code& code) {
  return std::any_of(code.instrs.begin(), code.instrs.end(),
                     [](const bipc::ir::Instr& in) { return in.op == bipc::ir::Op::Call; });
}

bool collect(const DefineNode& node, std::span<const std::uint8_t> enabled,
             std::vector<Index>& out);

/// Appends the largest enabled set of a sequence of define nodes: all of them when none is a
/// trigger, else every one that can take part provided a trigger does. False (leaving `out` as
/// it was) when the sequence cannot take part.
bool collect_sequence(std::span<const DefineNode> nodes, std::span<const std::uint8_t> enabled,
                      std::vector<Index>& out) {
  const std::size_t mark = out.size();
  const bool has_trigger =
      std::any_of(nodes.begin(), nodes.end(), [](const DefineNode& n) { return n.trigger; });
  bool trigger_taken = false;
  for (const DefineNode& node : nodes) {
    const bool taken = collect(node, enabled, out);
    if (!taken && !has_trigger) {
      out.resize(mark);
      return false;
    }
    trigger_taken = trigger_taken || (taken && node.trigger);
  }
  if ((has_trigger && !trigger_taken) || out.size() == mark) {
    out.resize(mark);
    return false;
  }
  return true;
}

/// Appends the node's largest enabled port set to `out`; false (leaving `out` as it was) when
/// the node cannot take part.
bool collect(const DefineNode& node, std::span<const std::uint8_t> enabled,
             std::vector<Index>& out) {
  if (!node.children.empty()) return collect_sequence(node.children, enabled, out);
  if (node.port >= enabled.size() || !enabled[node.port]) return false;
  out.push_back(node.port);
  return true;
}

}  // namespace

bool computes_maximal_only(const bipc::ir::System& system, Index k) {
  const bipc::ir::ConnectorInstance& connector = system.connectors[k];
  const bipc::ir::ConnectorType& type = system.connector_types[connector.type];
  if (type.export_name) return false;
  for (const std::vector<bipc::ir::PortRef>& refs : connector.bound) {
    for (const bipc::ir::PortRef& ref : refs) {
      if (ref.kind != bipc::ir::PortRef::Kind::Atom) return false;
    }
  }
  for (const bipc::ir::InteractionCode& code : type.interactions) {
    if (!code.guard.empty() || calls_anything(code.up)) return false;
  }
  for (const bipc::ir::Priority& rule : system.compounds[connector.parent].priorities) {
    for (Index side : {rule.low.connector, rule.high.connector}) {
      if (side == k || side == bipc::ir::kNone) return false;
    }
  }
  return true;
}

bool largest_enabled_interaction(const std::vector<DefineNode>& define,
                                 std::span<const std::uint8_t> enabled, std::vector<Index>& out) {
  out.clear();
  if (!collect_sequence(define, enabled, out)) return false;
  std::sort(out.begin(), out.end());
  return true;
}

}  // namespace smcbip::engines
