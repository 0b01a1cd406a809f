// Checks the references of a decoded System (ir_data.h lists them), so that engines and
// generators that index tables with them stay in bounds.
#include <string>
#include <vector>

#include "bipc/ir/detail/ir_data_names.h"
#include "bipc/ir/detail/ir_data_reader.h"
#include "bipc/ir/ir_data.h"

namespace smcbip::bipc::ir::detail {

namespace {

std::string at(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

/// Fails unless `i < size`; `what` names the table, e.g. "places".
void in_range(Index i, std::size_t size, const std::string& path, const char* what) {
  if (i == kNone) fail(path, std::string("null where one of the ") + what + " is required");
  if (i >= size) {
    fail(path, "index " + std::to_string(i) + " out of range (" + std::to_string(size) + " " +
                   what + ")");
  }
}

/// As in_range, with kNone allowed.
void none_or_in_range(Index i, std::size_t size, const std::string& path, const char* what) {
  if (i != kNone) in_range(i, size, path, what);
}

void all_in_range(const std::vector<Index>& list, std::size_t size, const std::string& path,
                  const char* what) {
  for (std::size_t i = 0; i < list.size(); ++i) in_range(list[i], size, at(path, i), what);
}

void same_size(std::size_t actual, std::size_t expected, const std::string& path,
               const char* what) {
  if (actual != expected) {
    fail(path,
         std::to_string(actual) + " elements where " + what + " has " + std::to_string(expected));
  }
}

/// The tables a piece of code may name, by where it runs.
struct CodeContext {
  const AtomType* atom = nullptr;            // atom code
  const ConnectorType* connector = nullptr;  // connector code
  bool compound = false;                     // a compound's priority guard
};

class Checker {
 public:
  explicit Checker(const System& s) : s_(s) {}

  void run() {
    for (std::size_t i = 0; i < s_.extern_types.size(); ++i) {
      all_in_range(s_.extern_types[i].refines, s_.extern_types.size(),
                   at("extern_types", i) + ".refines", "extern types");
    }
    for (std::size_t i = 0; i < s_.functions.size(); ++i) {
      const ExternFunction& f = s_.functions[i];
      const std::string path = at("functions", i);
      if (f.result) data_type(*f.result, path + ".result");
      for (std::size_t p = 0; p < f.params.size(); ++p) {
        data_type(f.params[p], at(path + ".params", p));
      }
    }
    for (std::size_t i = 0; i < s_.port_types.size(); ++i) {
      typed_params(s_.port_types[i].params, at("port_types", i) + ".params");
    }
    for (std::size_t i = 0; i < s_.atom_types.size(); ++i) atom_type(i);
    for (std::size_t i = 0; i < s_.connector_types.size(); ++i) connector_type(i);
    for (std::size_t i = 0; i < s_.atoms.size(); ++i) atom(i);
    for (std::size_t i = 0; i < s_.connectors.size(); ++i) connector(i);
    for (std::size_t i = 0; i < s_.compounds.size(); ++i) compound(i);
    connectors_acyclic();
  }

 private:
  void data_type(const DataType& t, const std::string& path) {
    if (t.kind == ValueKind::Extern) {
      in_range(t.extern_type, s_.extern_types.size(), path + ".extern_type", "extern types");
    } else if (t.extern_type != kNone) {
      fail(path + ".extern_type",
           "set on a data type of kind " + std::string(kValueKindNames[static_cast<int>(t.kind)]));
    }
  }

  void typed_params(const std::vector<std::pair<std::string, DataType>>& params,
                    const std::string& path) {
    for (std::size_t i = 0; i < params.size(); ++i)
      data_type(params[i].second, at(path, i) + "[1]");
  }

  void data_list(const std::vector<Data>& data, const std::string& path, const CodeContext& c) {
    for (std::size_t i = 0; i < data.size(); ++i) {
      data_type(data[i].type, at(path, i) + ".type");
      code(data[i].initial_value, at(path, i) + ".initial_value", c);
    }
  }

  void code(const Code& code, const std::string& path, const CodeContext& c) {
    if (code.id >= s_.code_count) {
      fail(path + ".id", "code id " + std::to_string(code.id) + " not below code_count " +
                             std::to_string(s_.code_count));
    }
    for (std::size_t i = 0; i < code.instrs.size(); ++i) {
      instr(code.instrs[i], code.instrs.size(), at(path + ".instrs", i), c);
    }
  }

  void instr(const Instr& in, std::size_t length, const std::string& path, const CodeContext& c) {
    const std::string index = path + "[4]";
    switch (in.op) {
      case Op::PushString:
        return in_range(in.index, s_.strings.size(), index, "strings");
      case Op::Call:
        return in_range(in.index, s_.functions.size(), index, "functions");
      case Op::Jump:
      case Op::JumpIfFalse:
      case Op::JumpIfFalseKeep:
      case Op::JumpIfTrueKeep:
        return in_range(in.index, length + 1, index, "instructions and the end");
      case Op::StoreRate:
        if (c.atom == nullptr) fail(path, "store_rate outside atom code");
        return in_range(in.index, c.atom->clocks.size(), index, "clocks");
      case Op::Load:
      case Op::Store:
        return slot(in, path, c);
      default:
        return;
    }
  }

  void slot(const Instr& in, const std::string& path, const CodeContext& c) {
    const std::string index = path + "[4]", arg = path + "[3]";
    const bool atom_scope =
        in.scope == Scope::AtomData || in.scope == Scope::AtomParam || in.scope == Scope::Clock;
    const bool connector_scope = in.scope == Scope::ConnectorData || in.scope == Scope::PortParam;
    if ((atom_scope && c.atom == nullptr) || (connector_scope && c.connector == nullptr) ||
        (in.scope == Scope::InstanceData && !c.compound)) {
      fail(path + "[2]", std::string("scope ") + kScopeNames[static_cast<int>(in.scope)] +
                             " is not available in this code");
    }
    switch (in.scope) {
      case Scope::AtomData:
        return in_range(in.index, c.atom->data.size(), index, "data of the atom type");
      case Scope::AtomParam:
        return in_range(in.index, c.atom->params.size(), index, "parameters of the atom type");
      case Scope::Clock:
        return in_range(in.index, c.atom->clocks.size(), index, "clocks of the atom type");
      case Scope::ConnectorData:
        return in_range(in.index, c.connector->data.size(), index, "data of the connector type");
      case Scope::PortParam: {
        in_range(in.index, c.connector->ports.size(), index, "ports of the connector type");
        const PortType& type = s_.port_types[c.connector->ports[in.index].second];
        return in_range(in.arg, type.params.size(), arg, "parameters of the port type");
      }
      case Scope::InstanceData: {
        in_range(in.index, s_.atoms.size(), index, "atoms");
        const AtomType& type = s_.atom_types[s_.atoms[in.index].type];
        return in_range(in.arg, type.data.size(), arg, "data of the atom's type");
      }
    }
  }

  void port(const AtomType& t, const Port& p, const std::string& path, const CodeContext& c) {
    in_range(p.type, s_.port_types.size(), path + ".type", "port types");
    all_in_range(p.data, t.data.size(), path + ".data", "data of the atom type");
    same_size(p.data.size(), s_.port_types[p.type].params.size(), path + ".data",
              "the port type's parameter list");
    if (p.stochastic) {
      none_or_in_range(p.stochastic->clock, t.clocks.size(), path + ".stochastic.clock",
                       "clocks of the atom type");
      for (std::size_t i = 0; i < p.stochastic->params.size(); ++i) {
        code(p.stochastic->params[i], at(path + ".stochastic.params", i), c);
      }
    }
  }

  void atom_type(std::size_t index) {
    const AtomType& t = s_.atom_types[index];
    const std::string path = at("atom_types", index);
    const CodeContext c{&t, nullptr, false};
    typed_params(t.params, path + ".params");
    data_list(t.data, path + ".data", c);
    for (std::size_t i = 0; i < t.ports.size(); ++i) port(t, t.ports[i], at(path + ".ports", i), c);
    for (std::size_t i = 0; i < t.interface.size(); ++i) {
      const std::string ip = at(path + ".interface", i);
      in_range(t.interface[i].type, s_.port_types.size(), ip + ".type", "port types");
      all_in_range(t.interface[i].ports, t.ports.size(), ip + ".ports", "ports of the atom type");
    }
    all_in_range(t.initial_places, t.places.size(), path + ".initial_places", "places");
    code(t.initial_action, path + ".initial_action", c);
    if (t.initial_resume) code(t.initial_resume->guard, path + ".initial_resume.guard", c);
    for (std::size_t i = 0; i < t.transitions.size(); ++i) {
      const Transition& tr = t.transitions[i];
      const std::string tp = at(path + ".transitions", i);
      none_or_in_range(tr.port, t.ports.size(), tp + ".port", "ports of the atom type");
      all_in_range(tr.from, t.places.size(), tp + ".from", "places");
      all_in_range(tr.to, t.places.size(), tp + ".to", "places");
      code(tr.guard, tp + ".guard", c);
      code(tr.action, tp + ".action", c);
      if (tr.resume) code(tr.resume->guard, tp + ".resume.guard", c);
    }
    for (std::size_t i = 0; i < t.priorities.size(); ++i) {
      const std::string pp = at(path + ".priorities", i);
      none_or_in_range(t.priorities[i].low, t.ports.size(), pp + ".low", "ports of the atom type");
      none_or_in_range(t.priorities[i].high, t.ports.size(), pp + ".high",
                       "ports of the atom type");
      code(t.priorities[i].guard, pp + ".guard", c);
    }
    for (std::size_t i = 0; i < t.invariants.size(); ++i) {
      const std::string ip = at(path + ".invariants", i);
      all_in_range(t.invariants[i].places, t.places.size(), ip + ".places", "places");
      code(t.invariants[i].guard, ip + ".guard", c);
    }
  }

  void define(const std::vector<DefineNode>& nodes, std::size_t ports, const std::string& path) {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      none_or_in_range(nodes[i].port, ports, at(path, i) + ".port", "ports of the connector type");
      define(nodes[i].children, ports, at(path, i) + ".children");
    }
  }

  void connector_type(std::size_t index) {
    const ConnectorType& t = s_.connector_types[index];
    const std::string path = at("connector_types", index);
    const CodeContext c{nullptr, &t, false};
    for (std::size_t i = 0; i < t.ports.size(); ++i) {
      in_range(t.ports[i].second, s_.port_types.size(), at(path + ".ports", i) + "[1]",
               "port types");
    }
    data_list(t.data, path + ".data", c);
    if (t.export_name) {
      in_range(t.export_type, s_.port_types.size(), path + ".export_type", "port types");
      same_size(t.export_data.size(), s_.port_types[t.export_type].params.size(),
                path + ".export_data", "the export's port type");
    } else {
      none_or_in_range(t.export_type, s_.port_types.size(), path + ".export_type", "port types");
    }
    all_in_range(t.export_data, t.data.size(), path + ".export_data", "data of the connector");
    define(t.define, t.ports.size(), path + ".define");
    for (std::size_t i = 0; i < t.interactions.size(); ++i) {
      const InteractionCode& ic = t.interactions[i];
      const std::string ip = at(path + ".interactions", i);
      all_in_range(ic.ports, t.ports.size(), ip + ".ports", "ports of the connector type");
      code(ic.guard, ip + ".guard", c);
      code(ic.up, ip + ".up", c);
      code(ic.down, ip + ".down", c);
    }
  }

  void port_ref(const PortRef& ref, const std::string& path) {
    if (ref.kind == PortRef::Kind::Connector) {
      return in_range(ref.instance, s_.connectors.size(), path + ".instance", "connectors");
    }
    in_range(ref.instance, s_.atoms.size(), path + ".instance", "atoms");
    in_range(ref.port, s_.atom_types[s_.atoms[ref.instance].type].ports.size(), path + ".port",
             "ports of the atom's type");
  }

  void port_refs(const std::vector<PortRef>& refs, const std::string& path) {
    for (std::size_t i = 0; i < refs.size(); ++i) port_ref(refs[i], at(path, i));
  }

  void atom(std::size_t index) {
    const AtomInstance& a = s_.atoms[index];
    const std::string path = at("atoms", index);
    in_range(a.type, s_.atom_types.size(), path + ".type", "atom types");
    in_range(a.parent, s_.compounds.size(), path + ".parent", "compounds");
    same_size(a.params.size(), s_.atom_types[a.type].params.size(), path + ".params",
              "the atom type's parameter list");
  }

  void connector(std::size_t index) {
    const ConnectorInstance& k = s_.connectors[index];
    const std::string path = at("connectors", index);
    in_range(k.type, s_.connector_types.size(), path + ".type", "connector types");
    in_range(k.parent, s_.compounds.size(), path + ".parent", "compounds");
    const std::size_t ports = s_.connector_types[k.type].ports.size();
    same_size(k.bound.size(), ports, path + ".bound", "the connector type's port list");
    same_size(k.bound_names.size(), ports, path + ".bound_names", "the connector type's port list");
    same_size(k.bound_through_compound.size(), ports, path + ".bound_through_compound",
              "the connector type's port list");
    for (std::size_t i = 0; i < k.bound.size(); ++i) port_refs(k.bound[i], at(path + ".bound", i));
    none_or_in_range(k.bound_by, s_.connectors.size(), path + ".bound_by", "connectors");
    all_in_range(k.bound_by_all, s_.connectors.size(), path + ".bound_by_all", "connectors");
  }

  void side(const PatternSide& side, const std::string& path) {
    none_or_in_range(side.connector, s_.connectors.size(), path + ".connector", "connectors");
    port_refs(side.ports, path + ".ports");
  }

  void compound(std::size_t index) {
    const CompoundInstance& c = s_.compounds[index];
    const std::string path = at("compounds", index);
    // Parents come before their children, so that walking up always ends at the root.
    if (index == 0 && c.parent != kNone) fail(path + ".parent", "the root has a parent");
    if (index != 0) in_range(c.parent, index, path + ".parent", "compounds before this one");
    all_in_range(c.atoms, s_.atoms.size(), path + ".atoms", "atoms");
    all_in_range(c.compounds, s_.compounds.size(), path + ".compounds", "compounds");
    all_in_range(c.connectors, s_.connectors.size(), path + ".connectors", "connectors");
    const CodeContext context{nullptr, nullptr, true};
    for (std::size_t i = 0; i < c.priorities.size(); ++i) {
      const std::string pp = at(path + ".priorities", i);
      side(c.priorities[i].low, pp + ".low");
      side(c.priorities[i].high, pp + ".high");
      code(c.priorities[i].guard, pp + ".guard", context);
    }
    for (const auto& [name, refs] : c.exported_ports) {
      port_refs(refs, path + ".exported_ports." + name);
    }
    for (const auto& [name, slot] : c.exported_data) {
      const std::string dp = path + ".exported_data." + name;
      in_range(slot.first, s_.atoms.size(), dp + "[0]", "atoms");
      in_range(slot.second, s_.atom_types[s_.atoms[slot.first].type].data.size(), dp + "[1]",
               "data of the atom's type");
    }
  }

  /// A connector bound to another's export executes through it: a cycle would never end.
  void connectors_acyclic() {
    std::vector<std::vector<Index>> below(s_.connectors.size());
    for (std::size_t k = 0; k < s_.connectors.size(); ++k) {
      for (const std::vector<PortRef>& refs : s_.connectors[k].bound) {
        for (const PortRef& ref : refs) {
          if (ref.kind == PortRef::Kind::Connector) below[k].push_back(ref.instance);
        }
      }
    }
    enum class Mark : std::uint8_t { New, Open, Done };
    std::vector<Mark> marks(s_.connectors.size(), Mark::New);
    // Depth first, with an explicit stack of (connector, next sub-connector to visit).
    std::vector<std::pair<Index, std::size_t>> stack;
    for (Index start = 0; start < s_.connectors.size(); ++start) {
      if (marks[start] != Mark::New) continue;
      stack.push_back({start, 0});
      marks[start] = Mark::Open;
      while (!stack.empty()) {
        const auto [k, next] = stack.back();
        if (next == below[k].size()) {
          marks[k] = Mark::Done;
          stack.pop_back();
          continue;
        }
        ++stack.back().second;
        const Index sub = below[k][next];
        if (marks[sub] == Mark::Open) {
          fail(at("connectors", k) + ".bound", "connectors bind each other's exports in a cycle");
        }
        if (marks[sub] == Mark::New) {
          marks[sub] = Mark::Open;
          stack.push_back({sub, 0});
        }
      }
    }
  }

  const System& s_;
};

}  // namespace

void check_references(const System& system) { Checker(system).run(); }

}  // namespace smcbip::bipc::ir::detail
