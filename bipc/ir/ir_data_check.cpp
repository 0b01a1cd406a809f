// Checks the references of a decoded System (ir_data.h lists them), so that engines and
// generators that index tables with them stay in bounds.
#include <string>
#include <vector>

#include "bipc/ir/detail/ir_data_names.h"
#include "bipc/ir/detail/ir_data_reader.h"
#include "bipc/ir/ir_data.h"

namespace smcbip::bipc::ir::detail {

namespace {

/// Fails unless `i < size`; `what` names the table, e.g. "places".
void in_range(Index i, std::size_t size, const Path& path, const char* what) {
  if (i == kNone) fail(path, std::string("null where one of the ") + what + " is required");
  if (i >= size) {
    fail(path, "index " + std::to_string(i) + " out of range (" + std::to_string(size) + " " +
                   what + ")");
  }
}

/// As in_range, with kNone allowed.
void none_or_in_range(Index i, std::size_t size, const Path& path, const char* what) {
  if (i != kNone) in_range(i, size, path, what);
}

void all_in_range(const std::vector<Index>& list, std::size_t size, const Path& path,
                  const char* what) {
  for (std::size_t i = 0; i < list.size(); ++i) in_range(list[i], size, path.item(i), what);
}

void same_size(std::size_t actual, std::size_t expected, const Path& path, const char* what) {
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
    const Path extern_types = top_.member("extern_types");
    for (std::size_t i = 0; i < s_.extern_types.size(); ++i) {
      all_in_range(s_.extern_types[i].refines, s_.extern_types.size(),
                   extern_types.item(i).member("refines"), "extern types");
    }
    const Path functions = top_.member("functions");
    for (std::size_t i = 0; i < s_.functions.size(); ++i) {
      const ExternFunction& f = s_.functions[i];
      const Path path = functions.item(i);
      if (f.result) data_type(*f.result, path.member("result"));
      const Path params = path.member("params");
      for (std::size_t p = 0; p < f.params.size(); ++p) data_type(f.params[p], params.item(p));
    }
    const Path port_types = top_.member("port_types");
    for (std::size_t i = 0; i < s_.port_types.size(); ++i) {
      typed_params(s_.port_types[i].params, port_types.item(i).member("params"));
    }
    for (std::size_t i = 0; i < s_.atom_types.size(); ++i) atom_type(i);
    for (std::size_t i = 0; i < s_.connector_types.size(); ++i) connector_type(i);
    for (std::size_t i = 0; i < s_.atoms.size(); ++i) atom(i);
    for (std::size_t i = 0; i < s_.connectors.size(); ++i) connector(i);
    for (std::size_t i = 0; i < s_.compounds.size(); ++i) compound(i);
    connectors_acyclic();
  }

 private:
  void data_type(const DataType& t, const Path& path) {
    if (t.kind == ValueKind::Extern) {
      in_range(t.extern_type, s_.extern_types.size(), path.member("extern_type"), "extern types");
    } else if (t.extern_type != kNone) {
      fail(path.member("extern_type"),
           "set on a data type of kind " + std::string(kValueKindNames[static_cast<int>(t.kind)]));
    }
  }

  void typed_params(const std::vector<std::pair<std::string, DataType>>& params, const Path& path) {
    for (std::size_t i = 0; i < params.size(); ++i)
      data_type(params[i].second, path.item(i).item(1));
  }

  void data_list(const std::vector<Data>& data, const Path& path, const CodeContext& c) {
    for (std::size_t i = 0; i < data.size(); ++i) {
      data_type(data[i].type, path.item(i).member("type"));
      code(data[i].initial_value, path.item(i).member("initial_value"), c);
    }
  }

  void code(const Code& code, const Path& path, const CodeContext& c) {
    if (code.id >= s_.code_count) {
      fail(path.member("id"), "code id " + std::to_string(code.id) + " not below code_count " +
                                  std::to_string(s_.code_count));
    }
    const Path instrs = path.member("instrs");
    for (std::size_t i = 0; i < code.instrs.size(); ++i) {
      instr(code.instrs[i], code.instrs.size(), instrs.item(i), c);
    }
  }

  void instr(const Instr& in, std::size_t length, const Path& path, const CodeContext& c) {
    none_or_in_range(in.site, s_.sites.size(), path.item(6), "sites");
    const Path index = path.item(4);
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

  void slot(const Instr& in, const Path& path, const CodeContext& c) {
    const Path index = path.item(4), arg = path.item(3);
    const bool atom_scope =
        in.scope == Scope::AtomData || in.scope == Scope::AtomParam || in.scope == Scope::Clock;
    const bool connector_scope = in.scope == Scope::ConnectorData || in.scope == Scope::PortParam;
    if ((atom_scope && c.atom == nullptr) || (connector_scope && c.connector == nullptr) ||
        (in.scope == Scope::InstanceData && !c.compound)) {
      fail(path.item(2), std::string("scope ") + kScopeNames[static_cast<int>(in.scope)] +
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

  void port(const AtomType& t, const Port& p, const Path& path, const CodeContext& c) {
    in_range(p.type, s_.port_types.size(), path.member("type"), "port types");
    const Path data = path.member("data");
    all_in_range(p.data, t.data.size(), data, "data of the atom type");
    same_size(p.data.size(), s_.port_types[p.type].params.size(), data,
              "the port type's parameter list");
    if (p.stochastic) {
      const Path stochastic = path.member("stochastic"), params = stochastic.member("params");
      none_or_in_range(p.stochastic->clock, t.clocks.size(), stochastic.member("clock"),
                       "clocks of the atom type");
      for (std::size_t i = 0; i < p.stochastic->params.size(); ++i) {
        code(p.stochastic->params[i], params.item(i), c);
      }
    }
  }

  void atom_type(std::size_t index) {
    const AtomType& t = s_.atom_types[index];
    const Path atom_types = top_.member("atom_types"), path = atom_types.item(index);
    const CodeContext c{&t, nullptr, false};
    typed_params(t.params, path.member("params"));
    data_list(t.data, path.member("data"), c);
    const Path ports = path.member("ports"), interface = path.member("interface");
    for (std::size_t i = 0; i < t.ports.size(); ++i) port(t, t.ports[i], ports.item(i), c);
    for (std::size_t i = 0; i < t.interface.size(); ++i) {
      const Path ip = interface.item(i);
      in_range(t.interface[i].type, s_.port_types.size(), ip.member("type"), "port types");
      all_in_range(t.interface[i].ports, t.ports.size(), ip.member("ports"),
                   "ports of the atom type");
    }
    all_in_range(t.initial_places, t.places.size(), path.member("initial_places"), "places");
    code(t.initial_action, path.member("initial_action"), c);
    if (t.initial_resume) {
      code(t.initial_resume->guard, path.member("initial_resume").member("guard"), c);
    }
    const Path transitions = path.member("transitions");
    for (std::size_t i = 0; i < t.transitions.size(); ++i) {
      const Transition& tr = t.transitions[i];
      const Path tp = transitions.item(i);
      none_or_in_range(tr.port, t.ports.size(), tp.member("port"), "ports of the atom type");
      all_in_range(tr.from, t.places.size(), tp.member("from"), "places");
      all_in_range(tr.to, t.places.size(), tp.member("to"), "places");
      code(tr.guard, tp.member("guard"), c);
      code(tr.action, tp.member("action"), c);
      if (tr.resume) code(tr.resume->guard, tp.member("resume").member("guard"), c);
    }
    const Path priorities = path.member("priorities");
    for (std::size_t i = 0; i < t.priorities.size(); ++i) {
      const Path pp = priorities.item(i);
      none_or_in_range(t.priorities[i].low, t.ports.size(), pp.member("low"),
                       "ports of the atom type");
      none_or_in_range(t.priorities[i].high, t.ports.size(), pp.member("high"),
                       "ports of the atom type");
      code(t.priorities[i].guard, pp.member("guard"), c);
    }
    const Path invariants = path.member("invariants");
    for (std::size_t i = 0; i < t.invariants.size(); ++i) {
      const Path ip = invariants.item(i);
      all_in_range(t.invariants[i].places, t.places.size(), ip.member("places"), "places");
      code(t.invariants[i].guard, ip.member("guard"), c);
    }
  }

  void define(const std::vector<DefineNode>& nodes, std::size_t ports, const Path& path) {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const Path node = path.item(i);
      none_or_in_range(nodes[i].port, ports, node.member("port"), "ports of the connector type");
      define(nodes[i].children, ports, node.member("children"));
    }
  }

  void connector_type(std::size_t index) {
    const ConnectorType& t = s_.connector_types[index];
    const Path connector_types = top_.member("connector_types"), path = connector_types.item(index);
    const CodeContext c{nullptr, &t, false};
    const Path ports = path.member("ports");
    for (std::size_t i = 0; i < t.ports.size(); ++i) {
      in_range(t.ports[i].second, s_.port_types.size(), ports.item(i).item(1), "port types");
    }
    data_list(t.data, path.member("data"), c);
    const Path export_type = path.member("export_type"), export_data = path.member("export_data");
    if (t.export_name) {
      in_range(t.export_type, s_.port_types.size(), export_type, "port types");
      same_size(t.export_data.size(), s_.port_types[t.export_type].params.size(), export_data,
                "the export's port type");
    } else {
      none_or_in_range(t.export_type, s_.port_types.size(), export_type, "port types");
    }
    all_in_range(t.export_data, t.data.size(), export_data, "data of the connector");
    define(t.define, t.ports.size(), path.member("define"));
    const Path interactions = path.member("interactions");
    for (std::size_t i = 0; i < t.interactions.size(); ++i) {
      const InteractionCode& ic = t.interactions[i];
      const Path ip = interactions.item(i);
      all_in_range(ic.ports, t.ports.size(), ip.member("ports"), "ports of the connector type");
      code(ic.guard, ip.member("guard"), c);
      code(ic.up, ip.member("up"), c);
      code(ic.down, ip.member("down"), c);
    }
  }

  void port_ref(const PortRef& ref, const Path& path) {
    if (ref.kind == PortRef::Kind::Connector) {
      return in_range(ref.instance, s_.connectors.size(), path.member("instance"), "connectors");
    }
    in_range(ref.instance, s_.atoms.size(), path.member("instance"), "atoms");
    in_range(ref.port, s_.atom_types[s_.atoms[ref.instance].type].ports.size(), path.member("port"),
             "ports of the atom's type");
  }

  void port_refs(const std::vector<PortRef>& refs, const Path& path) {
    for (std::size_t i = 0; i < refs.size(); ++i) port_ref(refs[i], path.item(i));
  }

  void atom(std::size_t index) {
    const AtomInstance& a = s_.atoms[index];
    const Path atoms = top_.member("atoms"), path = atoms.item(index);
    in_range(a.type, s_.atom_types.size(), path.member("type"), "atom types");
    in_range(a.parent, s_.compounds.size(), path.member("parent"), "compounds");
    same_size(a.params.size(), s_.atom_types[a.type].params.size(), path.member("params"),
              "the atom type's parameter list");
  }

  void connector(std::size_t index) {
    const ConnectorInstance& k = s_.connectors[index];
    const Path connectors = top_.member("connectors"), path = connectors.item(index);
    in_range(k.type, s_.connector_types.size(), path.member("type"), "connector types");
    in_range(k.parent, s_.compounds.size(), path.member("parent"), "compounds");
    const std::size_t ports = s_.connector_types[k.type].ports.size();
    const Path bound = path.member("bound");
    same_size(k.bound.size(), ports, bound, "the connector type's port list");
    same_size(k.bound_names.size(), ports, path.member("bound_names"),
              "the connector type's port list");
    same_size(k.bound_through_compound.size(), ports, path.member("bound_through_compound"),
              "the connector type's port list");
    for (std::size_t i = 0; i < k.bound.size(); ++i) port_refs(k.bound[i], bound.item(i));
    none_or_in_range(k.bound_by, s_.connectors.size(), path.member("bound_by"), "connectors");
    all_in_range(k.bound_by_all, s_.connectors.size(), path.member("bound_by_all"), "connectors");
  }

  void side(const PatternSide& side, const Path& path) {
    none_or_in_range(side.connector, s_.connectors.size(), path.member("connector"), "connectors");
    port_refs(side.ports, path.member("ports"));
  }

  void compound(std::size_t index) {
    const CompoundInstance& c = s_.compounds[index];
    const Path compounds = top_.member("compounds"), path = compounds.item(index);
    // Parents come before their children, so that walking up always ends at the root.
    if (index == 0 && c.parent != kNone) fail(path.member("parent"), "the root has a parent");
    if (index != 0) in_range(c.parent, index, path.member("parent"), "compounds before this one");
    all_in_range(c.atoms, s_.atoms.size(), path.member("atoms"), "atoms");
    all_in_range(c.compounds, s_.compounds.size(), path.member("compounds"), "compounds");
    all_in_range(c.connectors, s_.connectors.size(), path.member("connectors"), "connectors");
    const CodeContext context{nullptr, nullptr, true};
    const Path priorities = path.member("priorities");
    for (std::size_t i = 0; i < c.priorities.size(); ++i) {
      const Path pp = priorities.item(i);
      side(c.priorities[i].low, pp.member("low"));
      side(c.priorities[i].high, pp.member("high"));
      code(c.priorities[i].guard, pp.member("guard"), context);
    }
    const Path exported_ports = path.member("exported_ports");
    for (const auto& [name, refs] : c.exported_ports) port_refs(refs, exported_ports.member(name));
    const Path exported_data = path.member("exported_data");
    for (const auto& [name, slot] : c.exported_data) {
      const Path dp = exported_data.member(name);
      in_range(slot.first, s_.atoms.size(), dp.item(0), "atoms");
      in_range(slot.second, s_.atom_types[s_.atoms[slot.first].type].data.size(), dp.item(1),
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
          const Path connectors = top_.member("connectors");
          fail(connectors.item(k).member("bound"),
               "connectors bind each other's exports in a cycle");
        }
        if (marks[sub] == Mark::New) {
          marks[sub] = Mark::Open;
          stack.push_back({sub, 0});
        }
      }
    }
  }

  const System& s_;
  const Path top_;
};

}  // namespace

void check_references(const System& system) { Checker(system).run(); }

}  // namespace smcbip::bipc::ir::detail
