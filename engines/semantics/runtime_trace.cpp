// What a trace shows of a run: the ports of an interaction with their data, values as the
// model writes them, and the constraints a date misses.
#include <sstream>
#include <string>
#include <vector>

#include "engines/semantics/detail/runtime_shared.h"
#include "engines/semantics/runtime.h"

namespace smcbip::engines {

using bipc::ir::AtomType;
using bipc::ir::kNone;
using detail::wait;

std::string format_ports(const Runtime& runtime, const InteractionValue& value) {
  const bipc::ir::System& system = runtime.system();
  const bipc::ir::ConnectorInstance& connector = system.connectors[value.connector];
  std::string text;
  for (const PortValue& pv : value.choice) {
    if (!text.empty()) text += ' ';
    text += connector.bound_names[pv.param] + "(";
    const bipc::ir::PortType* port_type = nullptr;
    std::vector<Val> values;
    if (pv.from_atom) {
      const AtomType& type = system.atom_types[system.atoms[pv.atom].type];
      const bipc::ir::Port& port = type.ports[pv.port];
      port_type = &system.port_types[port.type];
      for (Index slot : port.data)
        values.push_back(runtime.state().data[runtime.layout().atom_data[pv.atom] + slot]);
    } else {
      const InteractionValue& sub = runtime.values()[pv.sub];
      const auto& type = system.connector_types[system.connectors[sub.connector].type];
      if (type.export_type != kNone) port_type = &system.port_types[type.export_type];
      for (Index slot : type.export_data) values.push_back(sub.data[slot]);
    }
    if (port_type) {
      for (std::size_t p = 0; p < port_type->params.size() && p < values.size(); ++p) {
        text += port_type->params[p].first + "=" +
                format_value(runtime.strings(), values[p], port_type->params[p].second.kind) + ";";
      }
    }
    text += ")";
  }
  return text;
}

std::string format_value(const StringPool& strings, Val v, bipc::ir::ValueKind kind) {
  switch (kind) {
    case bipc::ir::ValueKind::Bool:
      return v.b ? "true" : "false";
    case bipc::ir::ValueKind::Float: {
      std::ostringstream s;
      s << v.f;
      return s.str();
    }
    case bipc::ir::ValueKind::String:
      return strings.text(v.s);
    default:
      return std::to_string(v.i);
  }
}

std::vector<std::string> Runtime::late_constraints(TimeValue t) const {
  std::vector<std::string> lines;
  auto late = [&](const Constraint& c) { return !wait(c, state_.now).contains(t); };
  auto constraint_text = [](const Constraint& c) {
    return format_interval(c.interval) + " " + urgency_name(c.urgency);
  };
  for (Index k : layout_.listed_connectors) {
    for (Index v : connectors_.connector_values()[k]) {
      const InteractionValue& value = connectors_.values()[v];
      if (value.after.interval.empty() || !late(value.raw)) continue;
      lines.push_back(layout_.connector_names[k] + ": " + format_ports(*this, value) + " " +
                      constraint_text(value.raw));
    }
  }
  for (const auto& [atom, port] : layout_.internal_ports) {
    if (state_.resume_pending[atom]) continue;
    const auto& v = atoms_.port_values()[atoms_.port_offset()[atom] + port];
    if (!v || !late(v->constraint)) continue;
    const AtomType& type = system_.atom_types[system_.atoms[atom].type];
    lines.push_back(layout_.atom_names[atom] + "." + type.ports[port].name + " " +
                    constraint_text(v->constraint));
  }
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    const Interval& invariant = atoms_.time_bounds().invariant(a);
    if (!state_.resume_pending[a] && !invariant.contains(t)) {
      lines.push_back(layout_.atom_names[a] + " invariant " + format_interval(invariant));
    }
  }
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    if (state_.resume_pending[a] && !state_.resume_interval[a].contains(t)) {
      lines.push_back(layout_.atom_names[a] + " resume " +
                      format_interval(state_.resume_interval[a]));
    }
  }
  return lines;
}

}  // namespace smcbip::engines
