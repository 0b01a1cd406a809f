// Decodes the IR's data encoding (ir_data.h): each struct from its JSON shape here; fields in
// detail/ir_data_reader.cpp, references in ir_data_check.cpp, CBOR framing in ir_data_bytes.cpp.
#include "bipc/ir/detail/ir_data_names.h"
#include "bipc/ir/detail/ir_data_reader.h"
#include "bipc/ir/ir_data.h"

namespace smcbip::bipc::ir {

using nlohmann::json;

namespace {

using detail::element;
using detail::fail;
using detail::Field;
using detail::got;
using detail::Object;
using detail::Path;
using detail::read_array;
using detail::read_bool;
using detail::read_double;
using detail::read_enum;
using detail::read_index;
using detail::read_int;
using detail::read_list;
using detail::read_location;
using detail::read_string;

std::vector<Index> read_indices(const Field& f) { return read_list(f, read_index); }

std::vector<std::string> read_strings(const Field& f) { return read_list(f, read_string); }

DataType read_data_type(const Field& f) {
  Object o(f);
  DataType t;
  t.kind = read_enum<ValueKind>(o["kind"], detail::kValueKindNames);
  t.extern_type = read_index(o["extern_type"]);
  o.done();
  return t;
}

std::vector<std::pair<std::string, DataType>> read_typed_params(const Field& f) {
  return read_list(f, [](const Field& p) {
    read_array(p, 2);
    return std::pair<std::string, DataType>{read_string(element(p, 0)),
                                            read_data_type(element(p, 1))};
  });
}

Value read_value(const Field& f) {
  Object o(f);
  Value v;
  v.kind = read_enum<ValueKind>(o["kind"], detail::kValueKindNames);
  v.b = read_bool(o["b"]);
  v.i = read_int<std::int64_t>(o["i"]);
  v.f = read_double(o["f"]);
  v.s = read_string(o["s"]);
  o.done();
  return v;
}

Instr read_instr(const Field& f) {
  read_array(f, 7);
  Instr in;
  in.op = read_enum<Op>(element(f, 0), detail::kOpNames);
  in.kind = read_enum<ValueKind>(element(f, 1), detail::kValueKindNames);
  in.scope = read_enum<Scope>(element(f, 2), detail::kScopeNames);
  in.arg = read_int<std::uint16_t>(element(f, 3));
  in.index = read_index(element(f, 4));
  switch (in.op) {
    case Op::PushBool:
      in.imm.b = read_bool(element(f, 5));
      break;
    case Op::PushFloat:
      in.imm.f = read_double(element(f, 5));
      break;
    default:
      in.imm.i = read_int<std::int64_t>(element(f, 5));
      break;
  }
  in.site = read_index(element(f, 6));
  return in;
}

Code read_code(const Field& f) {
  Object o(f);
  Code code;
  code.id = read_int<std::uint32_t>(o["id"]);
  code.instrs = read_list(o["instrs"], read_instr);
  o.done();
  return code;
}

std::vector<Annotation> read_annotations(const Field& f) {
  return read_list(f, [](const Field& a) {
    Object o(a);
    Annotation out;
    out.name = read_string(o["name"]);
    out.params = read_list(o["params"], [](const Field& p) {
      read_array(p, 2);
      std::pair<std::string, std::optional<std::string>> param{read_string(element(p, 0)), {}};
      if (!p.value[1].is_null()) param.second = read_string(element(p, 1));
      return param;
    });
    out.loc = read_location(o["loc"]);
    o.done();
    return out;
  });
}

std::optional<Resume> read_resume(const Field& f) {
  if (f.value.is_null()) return std::nullopt;
  Object o(f);
  Resume r{read_code(o["guard"])};
  o.done();
  return r;
}

std::vector<Data> read_data_list(const Field& f) {
  return read_list(f, [](const Field& d) {
    Object o(d);
    Data out;
    out.name = read_string(o["name"]);
    out.type = read_data_type(o["type"]);
    out.exported = read_bool(o["exported"]);
    out.initial_value = read_code(o["initial_value"]);
    o.done();
    return out;
  });
}

std::optional<Stochastic> read_stochastic(const Field& f) {
  if (f.value.is_null()) return std::nullopt;
  Object o(f);
  Stochastic s;
  s.distribution = read_enum<Distribution>(o["distribution"], detail::kDistributionNames);
  s.clock = read_index(o["clock"]);
  s.params = read_list(o["params"], read_code);
  s.custom_file = read_string(o["custom_file"]);
  o.done();
  return s;
}

Port read_port(const Field& f) {
  Object o(f);
  Port p;
  p.name = read_string(o["name"]);
  p.type = read_index(o["type"]);
  p.data = read_indices(o["data"]);
  p.exported = read_bool(o["exported"]);
  p.is_extern = read_bool(o["is_extern"]);
  p.policy = read_enum<ExternPolicy>(o["policy"], detail::kExternPolicyNames);
  p.backend_name = read_string(o["backend_name"]);
  p.stochastic = read_stochastic(o["stochastic"]);
  p.annotations = read_annotations(o["annotations"]);
  o.done();
  return p;
}

Transition read_transition(const Field& f) {
  Object o(f);
  Transition t;
  t.port = read_index(o["port"]);
  t.from = read_indices(o["from"]);
  t.to = read_indices(o["to"]);
  t.guard = read_code(o["guard"]);
  t.action = read_code(o["action"]);
  t.urgency = read_enum<Urgency>(o["urgency"], detail::kUrgencyNames);
  t.resume = read_resume(o["resume"]);
  t.annotations = read_annotations(o["annotations"]);
  t.loc = read_location(o["loc"]);
  o.done();
  return t;
}

void read_atom_type_behaviour(Object& o, AtomType& t) {
  t.initial_places = read_indices(o["initial_places"]);
  t.initial_action = read_code(o["initial_action"]);
  t.initial_resume = read_resume(o["initial_resume"]);
  t.transitions = read_list(o["transitions"], read_transition);
  t.priorities = read_list(o["priorities"], [](const Field& p) {
    Object po(p);
    AtomPriority out{read_string(po["name"]), read_index(po["low"]), read_index(po["high"]),
                     read_code(po["guard"])};
    po.done();
    return out;
  });
  t.invariants = read_list(o["invariants"], [](const Field& i) {
    Object io(i);
    Invariant out{read_string(io["name"]), read_bool(io["at"]), read_indices(io["places"]),
                  read_code(io["guard"])};
    io.done();
    return out;
  });
}

AtomType read_atom_type(const Field& f) {
  Object o(f);
  AtomType t;
  t.name = read_string(o["name"]);
  t.params = read_typed_params(o["params"]);
  t.data = read_data_list(o["data"]);
  t.clocks = read_list(o["clocks"], [](const Field& c) {
    Object co(c);
    Clock out{read_string(co["name"]), read_enum<TimeUnit>(co["unit"], detail::kTimeUnitNames)};
    co.done();
    return out;
  });
  t.places = read_strings(o["places"]);
  t.ports = read_list(o["ports"], read_port);
  t.interface = read_list(o["interface"], [](const Field& i) {
    Object io(i);
    InterfacePort out{read_string(io["name"]), read_index(io["type"]), read_indices(io["ports"])};
    io.done();
    return out;
  });
  read_atom_type_behaviour(o, t);
  t.annotations = read_annotations(o["annotations"]);
  o.done();
  return t;
}

/// The nodes of one define list, `depth` levels below the connector type.
std::vector<DefineNode> read_define(const Field& f, std::size_t depth) {
  if (depth > kMaxDefineDepth && !read_array(f).empty()) {
    fail(f.path, "define tree deeper than " + std::to_string(kMaxDefineDepth) + " levels");
  }
  return read_list(f, [depth](const Field& n) {
    Object o(n);
    DefineNode node;
    node.port = read_index(o["port"]);
    node.children = read_define(o["children"], depth + 1);
    node.trigger = read_bool(o["trigger"]);
    o.done();
    return node;
  });
}

ConnectorType read_connector_type(const Field& f) {
  Object o(f);
  ConnectorType t;
  t.name = read_string(o["name"]);
  t.ports = read_list(o["ports"], [](const Field& p) {
    read_array(p, 2);
    return std::pair<std::string, Index>{read_string(element(p, 0)), read_index(element(p, 1))};
  });
  t.data = read_data_list(o["data"]);
  const Field export_name = o["export_name"];
  if (!export_name.value.is_null()) t.export_name = read_string(export_name);
  t.export_type = read_index(o["export_type"]);
  t.export_data = read_indices(o["export_data"]);
  t.define = read_define(o["define"], 1);
  t.interactions = read_list(o["interactions"], [](const Field& i) {
    Object io(i);
    InteractionCode out{read_indices(io["ports"]), read_code(io["guard"]), read_code(io["up"]),
                        read_code(io["down"]), read_annotations(io["annotations"])};
    io.done();
    return out;
  });
  t.resume = read_enum<ConnectorType::Resume>(o["resume"], detail::kConnectorResumeNames);
  t.annotations = read_annotations(o["annotations"]);
  o.done();
  return t;
}

PortRef read_port_ref(const Field& f) {
  Object o(f);
  PortRef ref;
  ref.kind = read_enum<PortRef::Kind>(o["kind"], detail::kPortRefKindNames);
  ref.instance = read_index(o["instance"]);
  ref.port = read_index(o["port"]);
  o.done();
  return ref;
}

std::vector<PortRef> read_port_refs(const Field& f) { return read_list(f, read_port_ref); }

AtomInstance read_atom(const Field& f) {
  Object o(f);
  AtomInstance a;
  a.path = read_string(o["path"]);
  a.type = read_index(o["type"]);
  a.parent = read_index(o["parent"]);
  a.params = read_list(o["params"], read_value);
  a.annotations = read_annotations(o["annotations"]);
  o.done();
  return a;
}

ConnectorInstance read_connector(const Field& f) {
  Object o(f);
  ConnectorInstance k;
  k.path = read_string(o["path"]);
  k.type = read_index(o["type"]);
  k.parent = read_index(o["parent"]);
  k.bound = read_list(o["bound"], read_port_refs);
  k.bound_names = read_strings(o["bound_names"]);
  k.bound_through_compound = read_list(o["bound_through_compound"], read_bool);
  k.bound_by = read_index(o["bound_by"]);
  k.bound_by_all = read_indices(o["bound_by_all"]);
  k.annotations = read_annotations(o["annotations"]);
  o.done();
  return k;
}

PatternSide read_side(const Field& f) {
  Object o(f);
  PatternSide side;
  side.connector = read_index(o["connector"]);
  side.all_ports = read_bool(o["all_ports"]);
  side.ports = read_port_refs(o["ports"]);
  o.done();
  return side;
}

CompoundInstance read_compound(const Field& f) {
  Object o(f);
  CompoundInstance c;
  c.path = read_string(o["path"]);
  c.type = read_string(o["type"]);
  c.parent = read_index(o["parent"]);
  c.atoms = read_indices(o["atoms"]);
  c.compounds = read_indices(o["compounds"]);
  c.connectors = read_indices(o["connectors"]);
  c.priorities = read_list(o["priorities"], [](const Field& p) {
    Object po(p);
    Priority out{read_string(po["name"]), read_side(po["low"]), read_side(po["high"]),
                 read_code(po["guard"])};
    po.done();
    return out;
  });
  const Field ports = o["exported_ports"];
  if (!ports.value.is_object()) fail(ports.path, "expected an object" + got(ports.value));
  for (const auto& [name, refs] : ports.value.items()) {
    c.exported_ports.emplace(name, read_port_refs({refs, ports.path.member(name)}));
  }
  const Field data = o["exported_data"];
  if (!data.value.is_object()) fail(data.path, "expected an object" + got(data.value));
  for (const auto& [name, slot] : data.value.items()) {
    const Field pair{slot, data.path.member(name)};
    read_array(pair, 2);
    c.exported_data.emplace(
        name, std::pair<Index, Index>{read_index(element(pair, 0)), read_index(element(pair, 1))});
  }
  c.annotations = read_annotations(o["annotations"]);
  o.done();
  return c;
}

void read_externs(Object& o, System& s) {
  s.extern_types = read_list(o["extern_types"], [](const Field& t) {
    Object to(t);
    ExternType out{read_string(to["name"]), read_string(to["backend_name"]),
                   read_indices(to["refines"])};
    to.done();
    return out;
  });
  s.functions = read_list(o["functions"], [](const Field& fn) {
    Object fo(fn);
    ExternFunction out;
    out.name = read_string(fo["name"]);
    out.is_operator = read_bool(fo["is_operator"]);
    const Field result = fo["result"];
    if (!result.value.is_null()) out.result = read_data_type(result);
    out.params = read_list(fo["params"], read_data_type);
    out.const_params = read_list(fo["const_params"], read_bool);
    fo.done();
    return out;
  });
}

}  // namespace

System from_data(const nlohmann::json& data) {
  const Path top;
  Object o({data, top});
  if (read_string(o["format"]) != "smcbip-ir") fail(top.member("format"), "not \"smcbip-ir\"");
  if (const int version = read_int<int>(o["version"]); version != kIrDataVersion) {
    fail(top.member("version"), "version " + std::to_string(version) + " is not the supported " +
                                    std::to_string(kIrDataVersion));
  }
  System s;
  s.root_name = read_string(o["root_name"]);
  s.root_type = read_string(o["root_type"]);
  s.strings = read_strings(o["strings"]);
  read_externs(o, s);
  s.port_types = read_list(o["port_types"], [](const Field& t) {
    Object to(t);
    PortType out{read_string(to["name"]), read_typed_params(to["params"])};
    to.done();
    return out;
  });
  s.atom_types = read_list(o["atom_types"], read_atom_type);
  s.connector_types = read_list(o["connector_types"], read_connector_type);
  s.atoms = read_list(o["atoms"], read_atom);
  s.connectors = read_list(o["connectors"], read_connector);
  s.compounds = read_list(o["compounds"], read_compound);
  s.cpp_includes = read_strings(o["cpp_includes"]);
  s.cpp_sources = read_strings(o["cpp_sources"]);
  s.cpp_include_dirs = read_strings(o["cpp_include_dirs"]);
  s.code_count = read_int<std::uint32_t>(o["code_count"]);
  s.sites = read_list(o["sites"], read_location);
  s.source_files = read_strings(o["source_files"]);
  o.done();
  detail::check_references(s);
  return s;
}

}  // namespace smcbip::bipc::ir
