// Encodes the IR as data (ir_data.h): every field, in a fixed order, nothing derived.
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "bipc/ir/detail/ir_data_names.h"
#include "bipc/ir/ir_data.h"

namespace smcbip::bipc::ir {

using nlohmann::json;

namespace {

/// The name of an enumerator. A value outside the enumeration cannot come from the front end
/// or from from_data, so it is a broken invariant of the caller's System.
template <typename Enum, std::size_t N>
const char* name_of(const std::array<const char*, N>& names, Enum value) {
  const auto i = static_cast<std::size_t>(value);
  if (i >= N) {
    std::fprintf(stderr, "ir_data: enumeration value %zu out of range (%zu names)\n", i, N);
    std::abort();
  }
  return names[i];
}

json index_data(Index i) { return i == kNone ? json(nullptr) : json(i); }

json indices_data(const std::vector<Index>& indices) {
  json out = json::array();
  for (Index i : indices) out.push_back(index_data(i));
  return out;
}

json double_data(double f) {
  if (std::isfinite(f)) return f;
  char text[24];
  std::snprintf(text, sizeof text, "f64:%016llx",
                static_cast<unsigned long long>(std::bit_cast<std::uint64_t>(f)));
  return text;
}

json location_data(const Location& loc) { return json::array({loc.file, loc.line, loc.column}); }

json data_type_data(const DataType& type) {
  return {{"kind", name_of(detail::kValueKindNames, type.kind)},
          {"extern_type", index_data(type.extern_type)}};
}

json typed_params_data(const std::vector<std::pair<std::string, DataType>>& params) {
  json out = json::array();
  for (const auto& [name, type] : params) out.push_back(json::array({name, data_type_data(type)}));
  return out;
}

json value_data(const Value& v) {
  return {{"kind", name_of(detail::kValueKindNames, v.kind)},
          {"b", v.b},
          {"i", v.i},
          {"f", double_data(v.f)},
          {"s", v.s}};
}

json instr_data(const Instr& in) {
  json imm;
  switch (in.op) {
    case Op::PushBool:
      imm = in.imm.b;
      break;
    case Op::PushFloat:
      imm = double_data(in.imm.f);
      break;
    default:
      imm = in.imm.i;
      break;
  }
  return json::array({name_of(detail::kOpNames, in.op), name_of(detail::kValueKindNames, in.kind),
                      name_of(detail::kScopeNames, in.scope), in.arg, index_data(in.index),
                      std::move(imm), index_data(in.site)});
}

json code_data(const Code& code) {
  json instrs = json::array();
  for (const Instr& in : code.instrs) instrs.push_back(instr_data(in));
  return {{"id", code.id}, {"instrs", std::move(instrs)}};
}

json codes_data(const std::vector<Code>& codes) {
  json out = json::array();
  for (const Code& code : codes) out.push_back(code_data(code));
  return out;
}

json annotations_data(const std::vector<Annotation>& annotations) {
  json out = json::array();
  for (const Annotation& a : annotations) {
    json params = json::array();
    for (const auto& [key, value] : a.params) {
      params.push_back(json::array({key, value ? json(*value) : json(nullptr)}));
    }
    out.push_back({{"name", a.name}, {"params", std::move(params)}, {"loc", location_data(a.loc)}});
  }
  return out;
}

json resume_data(const std::optional<Resume>& resume) {
  if (!resume) return nullptr;
  return {{"guard", code_data(resume->guard)}};
}

json data_list(const std::vector<Data>& data) {
  json out = json::array();
  for (const Data& d : data) {
    out.push_back({{"name", d.name},
                   {"type", data_type_data(d.type)},
                   {"exported", d.exported},
                   {"initial_value", code_data(d.initial_value)}});
  }
  return out;
}

json port_data(const Port& p) {
  json stochastic = nullptr;
  if (p.stochastic) {
    stochastic = {{"distribution", name_of(detail::kDistributionNames, p.stochastic->distribution)},
                  {"clock", index_data(p.stochastic->clock)},
                  {"params", codes_data(p.stochastic->params)},
                  {"custom_file", p.stochastic->custom_file}};
  }
  return {{"name", p.name},
          {"type", index_data(p.type)},
          {"data", indices_data(p.data)},
          {"exported", p.exported},
          {"is_extern", p.is_extern},
          {"policy", name_of(detail::kExternPolicyNames, p.policy)},
          {"backend_name", p.backend_name},
          {"stochastic", std::move(stochastic)},
          {"annotations", annotations_data(p.annotations)}};
}

json transition_data(const Transition& t) {
  return {{"port", index_data(t.port)},      {"from", indices_data(t.from)},
          {"to", indices_data(t.to)},        {"guard", code_data(t.guard)},
          {"action", code_data(t.action)},   {"urgency", name_of(detail::kUrgencyNames, t.urgency)},
          {"resume", resume_data(t.resume)}, {"annotations", annotations_data(t.annotations)},
          {"loc", location_data(t.loc)}};
}

json atom_type_data(const AtomType& t) {
  json clocks = json::array();
  for (const Clock& c : t.clocks) {
    clocks.push_back({{"name", c.name}, {"unit", name_of(detail::kTimeUnitNames, c.unit)}});
  }
  json ports = json::array();
  for (const Port& p : t.ports) ports.push_back(port_data(p));
  json interface = json::array();
  for (const InterfacePort& ip : t.interface) {
    interface.push_back(
        {{"name", ip.name}, {"type", index_data(ip.type)}, {"ports", indices_data(ip.ports)}});
  }
  json transitions = json::array();
  for (const Transition& tr : t.transitions) transitions.push_back(transition_data(tr));
  json priorities = json::array();
  for (const AtomPriority& p : t.priorities) {
    priorities.push_back({{"name", p.name},
                          {"low", index_data(p.low)},
                          {"high", index_data(p.high)},
                          {"guard", code_data(p.guard)}});
  }
  json invariants = json::array();
  for (const Invariant& inv : t.invariants) {
    invariants.push_back({{"name", inv.name},
                          {"at", inv.at},
                          {"places", indices_data(inv.places)},
                          {"guard", code_data(inv.guard)}});
  }
  return {{"name", t.name},
          {"params", typed_params_data(t.params)},
          {"data", data_list(t.data)},
          {"clocks", std::move(clocks)},
          {"places", t.places},
          {"ports", std::move(ports)},
          {"interface", std::move(interface)},
          {"initial_places", indices_data(t.initial_places)},
          {"initial_action", code_data(t.initial_action)},
          {"initial_resume", resume_data(t.initial_resume)},
          {"transitions", std::move(transitions)},
          {"priorities", std::move(priorities)},
          {"invariants", std::move(invariants)},
          {"annotations", annotations_data(t.annotations)}};
}

json define_data(const std::vector<DefineNode>& nodes) {
  json out = json::array();
  for (const DefineNode& node : nodes) {
    out.push_back({{"port", index_data(node.port)},
                   {"children", define_data(node.children)},
                   {"trigger", node.trigger}});
  }
  return out;
}

json connector_type_data(const ConnectorType& t) {
  json ports = json::array();
  for (const auto& [name, type] : t.ports) ports.push_back(json::array({name, index_data(type)}));
  json interactions = json::array();
  for (const InteractionCode& i : t.interactions) {
    interactions.push_back({{"ports", indices_data(i.ports)},
                            {"guard", code_data(i.guard)},
                            {"up", code_data(i.up)},
                            {"down", code_data(i.down)},
                            {"annotations", annotations_data(i.annotations)}});
  }
  return {{"name", t.name},
          {"ports", std::move(ports)},
          {"data", data_list(t.data)},
          {"export_name", t.export_name ? json(*t.export_name) : json(nullptr)},
          {"export_type", index_data(t.export_type)},
          {"export_data", indices_data(t.export_data)},
          {"define", define_data(t.define)},
          {"interactions", std::move(interactions)},
          {"resume", name_of(detail::kConnectorResumeNames, t.resume)},
          {"annotations", annotations_data(t.annotations)}};
}

json port_ref_data(const PortRef& ref) {
  return {{"kind", name_of(detail::kPortRefKindNames, ref.kind)},
          {"instance", index_data(ref.instance)},
          {"port", index_data(ref.port)}};
}

json port_refs_data(const std::vector<PortRef>& refs) {
  json out = json::array();
  for (const PortRef& ref : refs) out.push_back(port_ref_data(ref));
  return out;
}

json atom_data(const AtomInstance& a) {
  json params = json::array();
  for (const Value& v : a.params) params.push_back(value_data(v));
  return {{"path", a.path},
          {"type", index_data(a.type)},
          {"parent", index_data(a.parent)},
          {"params", std::move(params)},
          {"annotations", annotations_data(a.annotations)}};
}

json connector_data(const ConnectorInstance& k) {
  json bound = json::array();
  for (const std::vector<PortRef>& refs : k.bound) bound.push_back(port_refs_data(refs));
  json through = json::array();
  for (bool b : k.bound_through_compound) through.push_back(b);
  return {{"path", k.path},
          {"type", index_data(k.type)},
          {"parent", index_data(k.parent)},
          {"bound", std::move(bound)},
          {"bound_names", k.bound_names},
          {"bound_through_compound", std::move(through)},
          {"bound_by", index_data(k.bound_by)},
          {"bound_by_all", indices_data(k.bound_by_all)},
          {"annotations", annotations_data(k.annotations)}};
}

json side_data(const PatternSide& side) {
  return {{"connector", index_data(side.connector)},
          {"all_ports", side.all_ports},
          {"ports", port_refs_data(side.ports)}};
}

json compound_data(const CompoundInstance& c) {
  json priorities = json::array();
  for (const Priority& p : c.priorities) {
    priorities.push_back({{"name", p.name},
                          {"low", side_data(p.low)},
                          {"high", side_data(p.high)},
                          {"guard", code_data(p.guard)}});
  }
  json ports = json::object();
  for (const auto& [name, refs] : c.exported_ports) ports[name] = port_refs_data(refs);
  json data = json::object();
  for (const auto& [name, slot] : c.exported_data) {
    data[name] = json::array({index_data(slot.first), index_data(slot.second)});
  }
  return {{"path", c.path},
          {"type", c.type},
          {"parent", index_data(c.parent)},
          {"atoms", indices_data(c.atoms)},
          {"compounds", indices_data(c.compounds)},
          {"connectors", indices_data(c.connectors)},
          {"priorities", std::move(priorities)},
          {"exported_ports", std::move(ports)},
          {"exported_data", std::move(data)},
          {"annotations", annotations_data(c.annotations)}};
}

json extern_types_data(const std::vector<ExternType>& types) {
  json out = json::array();
  for (const ExternType& t : types) {
    out.push_back(
        {{"name", t.name}, {"backend_name", t.backend_name}, {"refines", indices_data(t.refines)}});
  }
  return out;
}

json functions_data(const std::vector<ExternFunction>& functions) {
  json out = json::array();
  for (const ExternFunction& f : functions) {
    json params = json::array();
    for (const DataType& type : f.params) params.push_back(data_type_data(type));
    json const_params = json::array();
    for (bool b : f.const_params) const_params.push_back(b);
    out.push_back({{"name", f.name},
                   {"is_operator", f.is_operator},
                   {"result", f.result ? data_type_data(*f.result) : json(nullptr)},
                   {"params", std::move(params)},
                   {"const_params", std::move(const_params)}});
  }
  return out;
}

}  // namespace

nlohmann::json to_data(const System& s) {
  json out = json::object();
  out["format"] = "smcbip-ir";
  out["version"] = kIrDataVersion;
  out["root_name"] = s.root_name;
  out["root_type"] = s.root_type;
  out["strings"] = s.strings;
  out["extern_types"] = extern_types_data(s.extern_types);
  out["functions"] = functions_data(s.functions);
  json port_types = json::array();
  for (const PortType& t : s.port_types) {
    port_types.push_back({{"name", t.name}, {"params", typed_params_data(t.params)}});
  }
  out["port_types"] = std::move(port_types);
  json atom_types = json::array();
  for (const AtomType& t : s.atom_types) atom_types.push_back(atom_type_data(t));
  out["atom_types"] = std::move(atom_types);
  json connector_types = json::array();
  for (const ConnectorType& t : s.connector_types) {
    connector_types.push_back(connector_type_data(t));
  }
  out["connector_types"] = std::move(connector_types);
  json atoms = json::array();
  for (const AtomInstance& a : s.atoms) atoms.push_back(atom_data(a));
  out["atoms"] = std::move(atoms);
  json connectors = json::array();
  for (const ConnectorInstance& k : s.connectors) connectors.push_back(connector_data(k));
  out["connectors"] = std::move(connectors);
  json compounds = json::array();
  for (const CompoundInstance& c : s.compounds) compounds.push_back(compound_data(c));
  out["compounds"] = std::move(compounds);
  out["cpp_includes"] = s.cpp_includes;
  out["cpp_sources"] = s.cpp_sources;
  out["cpp_include_dirs"] = s.cpp_include_dirs;
  out["code_count"] = s.code_count;
  json sites = json::array();
  for (const Location& loc : s.sites) sites.push_back(location_data(loc));
  out["sites"] = std::move(sites);
  out["source_files"] = s.source_files;
  return out;
}

}  // namespace smcbip::bipc::ir
