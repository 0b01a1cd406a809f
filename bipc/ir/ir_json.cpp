// Renders the IR as JSON: names instead of indices wherever a reader would want them.
#include "bipc/ir/ir_json.h"

#include <charconv>
#include <string>

#include "bipc/json_dump.h"

namespace smcbip::bipc::ir {

using nlohmann::json;

namespace {

std::string number_text(double f) {
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, f);
  return ec == std::errc() ? std::string(buffer, end) : std::to_string(f);
}

const char* op_name(Op op) {
  // In the order of ir::Op; the assertion catches an operation added without a name.
  static const char* const names[] = {"push",
                                      "push",
                                      "push",
                                      "push",
                                      "load",
                                      "store",
                                      "rate",
                                      "neg",
                                      "not",
                                      "bitnot",
                                      "add",
                                      "sub",
                                      "mul",
                                      "div",
                                      "mod",
                                      "bitand",
                                      "bitor",
                                      "bitxor",
                                      "eq",
                                      "ne",
                                      "lt",
                                      "le",
                                      "gt",
                                      "ge",
                                      "int_to_float",
                                      "call",
                                      "jump",
                                      "jump_if_false",
                                      "jump_if_false_keep",
                                      "jump_if_true_keep",
                                      "pop"};
  static_assert(sizeof names / sizeof names[0] == static_cast<std::size_t>(Op::Pop) + 1);
  return names[static_cast<std::size_t>(op)];
}

std::string slot_text(const Instr& in, const System& system) {
  const std::string i = std::to_string(in.index);
  switch (in.scope) {
    case Scope::AtomData:
      return "atom.data[" + i + "]";
    case Scope::AtomParam:
      return "atom.param[" + i + "]";
    case Scope::Clock:
      return "clock[" + i + "]";
    case Scope::ConnectorData:
      return "connector.data[" + i + "]";
    case Scope::PortParam:
      return "port[" + i + "].param[" + std::to_string(in.arg) + "]";
    case Scope::InstanceData: {
      std::string text = "instance[" + i + "].data[" + std::to_string(in.arg) + "]";
      if (in.index < system.atoms.size() &&
          system.atoms[in.index].type < system.atom_types.size()) {
        const auto& data = system.atom_types[system.atoms[in.index].type].data;
        if (in.arg < data.size())
          text += " ; " + system.atoms[in.index].path + "." + data[in.arg].name;
      }
      return text;
    }
  }
  return "?";
}

std::string data_type_name(const DataType& type, const System& system) {
  if (type.kind == ValueKind::Extern && type.extern_type < system.extern_types.size()) {
    return system.extern_types[type.extern_type].name;
  }
  return value_kind_name(type.kind);
}

json value_json(const Value& v) {
  switch (v.kind) {
    case ValueKind::Bool:
      return v.b;
    case ValueKind::Int:
      return v.i;
    case ValueKind::Float:
      return v.f;
    case ValueKind::String:
      return v.s;
    default:
      return nullptr;
  }
}

json code_json(const Code& code, const System& system) {
  json out = json::array();
  for (const Instr& in : code.instrs) out.push_back(instruction_text(in, system));
  return out;
}

json annotations_json(const std::vector<Annotation>& annotations) {
  json out = json::array();
  for (const Annotation& a : annotations) {
    json params = json::object();
    for (const auto& [key, value] : a.params) params[key] = value ? json(*value) : json(nullptr);
    out.push_back({{"name", a.name}, {"params", params}});
  }
  return out;
}

json names_of(const std::vector<Index>& indices, const std::vector<std::string>& names) {
  json out = json::array();
  for (Index i : indices) out.push_back(i < names.size() ? json(names[i]) : json(nullptr));
  return out;
}

json typed_params(const std::vector<std::pair<std::string, DataType>>& params, const System& s) {
  json out = json::array();
  for (const auto& [name, type] : params)
    out.push_back({{"name", name}, {"type", data_type_name(type, s)}});
  return out;
}

json data_json(const std::vector<Data>& data, const System& s) {
  json out = json::array();
  for (const Data& d : data) {
    out.push_back({{"name", d.name},
                   {"type", data_type_name(d.type, s)},
                   {"exported", d.exported},
                   {"initial", code_json(d.initial_value, s)}});
  }
  return out;
}

json port_refs_json(const std::vector<PortRef>& refs, const System& s) {
  json out = json::array();
  for (const PortRef& ref : refs) out.push_back(port_ref_name(ref, s));
  return out;
}

}  // namespace

std::string instruction_text(const Instr& in, const System& system) {
  std::string text = op_name(in.op);
  switch (in.op) {
    case Op::PushBool:
      return text + ".bool " + (in.imm.b ? "true" : "false");
    case Op::PushInt:
      return text + ".int " + std::to_string(in.imm.i);
    case Op::PushFloat:
      return text + ".float " + number_text(in.imm.f);
    case Op::PushString:
      return text + ".string " +
             (in.index < system.strings.size() ? dump_json(json(system.strings[in.index])) : "?");
    case Op::Load:
    case Op::Store:
      return text + " " + slot_text(in, system);
    case Op::StoreRate:
      return text + " clock[" + std::to_string(in.index) + "]";
    case Op::Call: {
      const bool known = in.index < system.functions.size();
      return text + " " + (known ? system.functions[in.index].name : "?") + "/" +
             std::to_string(in.arg);
    }
    case Op::Jump:
    case Op::JumpIfFalse:
    case Op::JumpIfFalseKeep:
    case Op::JumpIfTrueKeep:
      return text + " " + std::to_string(in.index);
    case Op::Neg:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
    case Op::Eq:
    case Op::Ne:
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge:
      return text + "." + value_kind_name(in.kind);
    default:
      return text;
  }
}

namespace {

const char* unit_name(TimeUnit unit) {
  static const char* const names[] = {"nanosecond", "microsecond", "millisecond", "second",
                                      "minute",     "hour",        "day"};
  return names[static_cast<int>(unit)];
}

const char* urgency_name(Urgency urgency) {
  static const char* const names[] = {"lazy", "delayable", "eager"};
  return names[static_cast<int>(urgency)];
}

const char* policy_name(ExternPolicy policy) {
  static const char* const names[] = {"remember", "ignore", "error"};
  return names[static_cast<int>(policy)];
}

const char* distribution_name(Distribution d) {
  static const char* const names[] = {"normal",  "exponential", "gamma",   "chi2",
                                      "uniform", "lognormal",   "weibull", "custom"};
  return names[static_cast<int>(d)];
}

/// The define expression written back in BIP syntax: "p' q r", "(p' q')' r".
std::string define_text(const std::vector<DefineNode>& nodes, const ConnectorType& t) {
  std::string text;
  for (const DefineNode& node : nodes) {
    if (!text.empty()) text += ' ';
    if (node.port != kNone) {
      text += node.port < t.ports.size() ? t.ports[node.port].first : std::string("?");
    } else {
      text += "(" + define_text(node.children, t) + ")";
    }
    if (node.trigger) text += '\'';
  }
  return text;
}

std::vector<std::string> port_names(const AtomType& t) {
  std::vector<std::string> names;
  for (const Port& p : t.ports) names.push_back(p.name);
  return names;
}

json stochastic_json(const Stochastic& st, const AtomType& t, const System& s) {
  json params = json::array();
  for (const Code& c : st.params) params.push_back(code_json(c, s));
  json out = {{"dist", distribution_name(st.distribution)}, {"params", params}};
  out["clock"] = st.clock < t.clocks.size() ? json(t.clocks[st.clock].name) : json(nullptr);
  if (st.distribution == Distribution::Custom) out["file"] = st.custom_file;
  return out;
}

json port_json(const Port& p, const AtomType& t, const System& s) {
  std::vector<std::string> data_names;
  for (const Data& d : t.data) data_names.push_back(d.name);
  json out = {{"name", p.name},
              {"type", p.type < s.port_types.size() ? s.port_types[p.type].name : "?"},
              {"data", names_of(p.data, data_names)},
              {"exported", p.exported}};
  if (p.is_extern) {
    out["extern"] = {{"policy", policy_name(p.policy)}, {"backend_name", p.backend_name}};
  }
  if (p.stochastic) out["stochastic"] = stochastic_json(*p.stochastic, t, s);
  if (!p.annotations.empty()) out["annotations"] = annotations_json(p.annotations);
  return out;
}

json resume_json(const std::optional<Resume>& resume, const System& s) {
  if (!resume) return nullptr;
  return {{"guard", code_json(resume->guard, s)}};
}

json transition_json(const Transition& tr, const AtomType& t, const System& s) {
  const std::vector<std::string> ports = port_names(t);
  json out = {{"port", tr.port < ports.size() ? json(ports[tr.port]) : json(nullptr)},
              {"from", names_of(tr.from, t.places)},
              {"to", names_of(tr.to, t.places)},
              {"guard", code_json(tr.guard, s)},
              {"action", code_json(tr.action, s)},
              {"urgency", urgency_name(tr.urgency)},
              {"resume", resume_json(tr.resume, s)},
              {"line", tr.loc.line}};
  if (!tr.annotations.empty()) out["annotations"] = annotations_json(tr.annotations);
  return out;
}

json atom_type_json(const AtomType& t, const System& s) {
  const std::vector<std::string> ports = port_names(t);
  json clocks = json::array();
  for (const Clock& c : t.clocks) clocks.push_back({{"name", c.name}, {"unit", unit_name(c.unit)}});
  json port_list = json::array();
  for (const Port& p : t.ports) port_list.push_back(port_json(p, t, s));
  json interface = json::array();
  for (const InterfacePort& ip : t.interface) {
    interface.push_back({{"name", ip.name}, {"ports", names_of(ip.ports, ports)}});
  }
  json transitions = json::array();
  for (const Transition& tr : t.transitions) transitions.push_back(transition_json(tr, t, s));
  json priorities = json::array();
  for (const AtomPriority& p : t.priorities) {
    priorities.push_back({{"name", p.name},
                          {"low", p.low < ports.size() ? json(ports[p.low]) : json("*")},
                          {"high", p.high < ports.size() ? json(ports[p.high]) : json("*")},
                          {"guard", code_json(p.guard, s)}});
  }
  json invariants = json::array();
  for (const Invariant& inv : t.invariants) {
    invariants.push_back({{"name", inv.name},
                          {"at", inv.at},
                          {"places", names_of(inv.places, t.places)},
                          {"guard", code_json(inv.guard, s)}});
  }
  return {{"name", t.name},
          {"params", typed_params(t.params, s)},
          {"data", data_json(t.data, s)},
          {"clocks", clocks},
          {"places", t.places},
          {"ports", port_list},
          {"interface", interface},
          {"initial",
           {{"to", names_of(t.initial_places, t.places)},
            {"action", code_json(t.initial_action, s)},
            {"resume", resume_json(t.initial_resume, s)}}},
          {"transitions", transitions},
          {"priorities", priorities},
          {"invariants", invariants},
          {"annotations", annotations_json(t.annotations)}};
}

json connector_type_json(const ConnectorType& t, const System& s) {
  json ports = json::array();
  std::vector<std::string> names;
  for (const auto& [name, type] : t.ports) {
    ports.push_back(
        {{"name", name}, {"type", type < s.port_types.size() ? s.port_types[type].name : "?"}});
    names.push_back(name);
  }
  json interactions = json::array();
  for (const InteractionCode& i : t.interactions) {
    interactions.push_back({{"ports", names_of(i.ports, names)},
                            {"guard", code_json(i.guard, s)},
                            {"up", code_json(i.up, s)},
                            {"down", code_json(i.down, s)}});
  }
  json out = {{"name", t.name},
              {"ports", ports},
              {"data", data_json(t.data, s)},
              {"define", define_text(t.define, t)},
              {"interactions", interactions},
              {"resume", t.resume == ConnectorType::Resume::Sync    ? "sync"
                         : t.resume == ConnectorType::Resume::Async ? "async"
                                                                    : "none"},
              {"annotations", annotations_json(t.annotations)}};
  if (t.export_name) {
    std::vector<std::string> data_names;
    for (const Data& d : t.data) data_names.push_back(d.name);
    out["export"] = {
        {"name", *t.export_name},
        {"type", t.export_type < s.port_types.size() ? s.port_types[t.export_type].name : "?"},
        {"data", names_of(t.export_data, data_names)}};
  }
  return out;
}

std::string compound_path(Index c, const System& s) {
  return c < s.compounds.size() ? s.compounds[c].path : std::string();
}

json side_json(const PatternSide& side, const System& s) {
  if (side.connector == kNone) return {{"connector", "*"}, {"ports", "*"}};
  const std::string path =
      side.connector < s.connectors.size() ? s.connectors[side.connector].path : "?";
  return {{"connector", path},
          {"ports", side.all_ports ? json("*") : port_refs_json(side.ports, s)}};
}

json compound_json(const CompoundInstance& c, const System& s) {
  json atoms = json::array(), compounds = json::array(), connectors = json::array();
  for (Index a : c.atoms) atoms.push_back(a < s.atoms.size() ? s.atoms[a].path : "?");
  for (Index k : c.compounds) compounds.push_back(compound_path(k, s));
  for (Index k : c.connectors)
    connectors.push_back(k < s.connectors.size() ? s.connectors[k].path : "?");
  json priorities = json::array();
  for (const Priority& p : c.priorities) {
    priorities.push_back({{"name", p.name},
                          {"low", side_json(p.low, s)},
                          {"high", side_json(p.high, s)},
                          {"guard", code_json(p.guard, s)}});
  }
  json ports = json::object(), data = json::object();
  for (const auto& [name, refs] : c.exported_ports) ports[name] = port_refs_json(refs, s);
  for (const auto& [name, slot] : c.exported_data) {
    const auto [atom, index] = slot;
    const bool known = atom < s.atoms.size() && s.atoms[atom].type < s.atom_types.size() &&
                       index < s.atom_types[s.atoms[atom].type].data.size();
    data[name] =
        known ? s.atoms[atom].path + "." + s.atom_types[s.atoms[atom].type].data[index].name : "?";
  }
  return {{"path", c.path},
          {"type", c.type},
          {"parent", c.parent == kNone ? json(nullptr) : json(compound_path(c.parent, s))},
          {"atoms", atoms},
          {"compounds", compounds},
          {"connectors", connectors},
          {"priorities", priorities},
          {"exported_ports", ports},
          {"exported_data", data},
          {"annotations", annotations_json(c.annotations)}};
}

json connector_json(const ConnectorInstance& k, const System& s) {
  const ConnectorType* type =
      k.type < s.connector_types.size() ? &s.connector_types[k.type] : nullptr;
  json bound = json::array();
  for (std::size_t i = 0; i < k.bound.size(); ++i) {
    const bool named = type != nullptr && i < type->ports.size();
    bound.push_back(
        {{"port", named ? type->ports[i].first : "?"}, {"ports", port_refs_json(k.bound[i], s)}});
  }
  json bound_by = json::array();  // usually one connector; empty at the top level
  for (Index by : k.bound_by_all)
    bound_by.push_back(by < s.connectors.size() ? s.connectors[by].path : "?");
  return {{"path", k.path},
          {"type", type != nullptr ? type->name : "?"},
          {"parent", compound_path(k.parent, s)},
          {"bound", bound},
          {"bound_by", bound_by},
          {"annotations", annotations_json(k.annotations)}};
}

json functions_json(const System& s) {
  json functions = json::array();
  for (const ExternFunction& f : s.functions) {
    json params = json::array();
    for (std::size_t i = 0; i < f.params.size(); ++i) {
      const bool is_const = i < f.const_params.size() && f.const_params[i];
      params.push_back(std::string(is_const ? "const " : "") + data_type_name(f.params[i], s));
    }
    functions.push_back({{"name", f.name},
                         {"operator", f.is_operator},
                         {"result", f.result ? json(data_type_name(*f.result, s)) : json(nullptr)},
                         {"params", params}});
  }
  return functions;
}

}  // namespace

nlohmann::json to_json(const System& s) {
  json out;
  out["root"] = {{"name", s.root_name}, {"type", s.root_type}};
  out["strings"] = s.strings;
  json externs = json::array();
  for (const ExternType& t : s.extern_types) {
    json refines = json::array();
    for (Index r : t.refines)
      refines.push_back(r < s.extern_types.size() ? s.extern_types[r].name : "?");
    externs.push_back({{"name", t.name}, {"backend_name", t.backend_name}, {"refines", refines}});
  }
  out["extern_types"] = externs;
  out["functions"] = functions_json(s);
  json port_types = json::array();
  for (const PortType& t : s.port_types) {
    port_types.push_back({{"name", t.name}, {"params", typed_params(t.params, s)}});
  }
  out["port_types"] = port_types;
  out["atom_types"] = json::array();
  for (const AtomType& t : s.atom_types) out["atom_types"].push_back(atom_type_json(t, s));
  out["connector_types"] = json::array();
  for (const ConnectorType& t : s.connector_types)
    out["connector_types"].push_back(connector_type_json(t, s));
  out["compounds"] = json::array();
  for (const CompoundInstance& c : s.compounds) out["compounds"].push_back(compound_json(c, s));
  out["atoms"] = json::array();
  for (const AtomInstance& a : s.atoms) {
    json params = json::array();
    for (const Value& v : a.params) params.push_back(value_json(v));
    out["atoms"].push_back(
        {{"path", a.path},
         {"type", a.type < s.atom_types.size() ? s.atom_types[a.type].name : "?"},
         {"parent", compound_path(a.parent, s)},
         {"params", params},
         {"annotations", annotations_json(a.annotations)}});
  }
  out["connectors"] = json::array();
  for (const ConnectorInstance& k : s.connectors) out["connectors"].push_back(connector_json(k, s));
  out["cpp"] = {{"includes", s.cpp_includes},
                {"sources", s.cpp_sources},
                {"include_dirs", s.cpp_include_dirs}};
  return out;
}

std::string port_ref_name(const PortRef& ref, const System& s) {
  if (ref.kind == PortRef::Kind::Connector) {
    if (ref.instance >= s.connectors.size()) return "?";
    const ConnectorInstance& k = s.connectors[ref.instance];
    const bool typed = k.type < s.connector_types.size() && s.connector_types[k.type].export_name;
    return k.path + "." + (typed ? *s.connector_types[k.type].export_name : std::string("?"));
  }
  if (ref.instance >= s.atoms.size()) return "?";
  const AtomInstance& a = s.atoms[ref.instance];
  const bool known = a.type < s.atom_types.size() && ref.port < s.atom_types[a.type].ports.size();
  return a.path + "." + (known ? s.atom_types[a.type].ports[ref.port].name : std::string("?"));
}

}  // namespace smcbip::bipc::ir
