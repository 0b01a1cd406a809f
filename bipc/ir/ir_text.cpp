// The outline view of the IR: what a user wants to see first of an instantiated model.
#include "bipc/ir/ir_text.h"

#include <sstream>

#include "bipc/ir/ir_json.h"

namespace smcbip::bipc::ir {

namespace {

std::string instance_name(const std::string& root, const std::string& path) {
  return path.empty() ? root : root + "." + path;
}

std::string value_text(const Value& v) {
  switch (v.kind) {
    case ValueKind::Bool:
      return v.b ? "true" : "false";
    case ValueKind::Float: {
      std::ostringstream out;
      out << v.f;
      return out.str();
    }
    case ValueKind::String:
      return "\"" + v.s + "\"";
    default:
      return std::to_string(v.i);
  }
}

std::string bound_text(const std::vector<PortRef>& alternatives, const System& s) {
  std::string text;
  for (const PortRef& ref : alternatives) {
    if (!text.empty()) text += "|";
    text += instance_name(s.root_name, port_ref_name(ref, s));
  }
  return text;
}

std::string side_text(const PatternSide& side, const System& s) {
  if (side.connector == kNone) return "*:*";
  std::string text = instance_name(s.root_name, s.connectors[side.connector].path) + ":";
  if (side.all_ports) return text + "*";
  for (std::size_t i = 0; i < side.ports.size(); ++i) {
    text += (i ? "," : "") + instance_name(s.root_name, port_ref_name(side.ports[i], s));
  }
  return text;
}

void write_atoms(std::ostream& out, const System& s) {
  out << "atoms (" << s.atoms.size() << "):\n";
  for (const AtomInstance& atom : s.atoms) {
    out << "  " << instance_name(s.root_name, atom.path) << " : " << s.atom_types[atom.type].name
        << "(";
    for (std::size_t i = 0; i < atom.params.size(); ++i) {
      out << (i ? ", " : "") << value_text(atom.params[i]);
    }
    out << ")\n";
  }
}

void write_connectors(std::ostream& out, const System& s) {
  out << "connectors (" << s.connectors.size() << "):\n";
  for (const ConnectorInstance& connector : s.connectors) {
    out << "  " << instance_name(s.root_name, connector.path) << " : "
        << s.connector_types[connector.type].name << "(";
    for (std::size_t i = 0; i < connector.bound.size(); ++i) {
      out << (i ? ", " : "") << bound_text(connector.bound[i], s);
    }
    out << ")\n";
  }
}

void write_compounds(std::ostream& out, const System& s) {
  out << "compounds (" << s.compounds.size() << "):\n";
  for (const CompoundInstance& compound : s.compounds) {
    out << "  " << instance_name(s.root_name, compound.path) << " : " << compound.type << "\n";
    for (const Priority& priority : compound.priorities) {
      out << "    priority " << priority.name << ": " << side_text(priority.low, s) << " < "
          << side_text(priority.high, s) << (priority.guard.empty() ? "" : " (guarded)") << "\n";
    }
  }
}

}  // namespace

std::string to_text(const System& system) {
  std::ostringstream out;
  write_compounds(out, system);
  write_atoms(out, system);
  write_connectors(out, system);
  return out.str();
}

}  // namespace smcbip::bipc::ir
