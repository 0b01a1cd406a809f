#include "engines/semantics/flat_tables.h"

#include <algorithm>

#include "bipc/ir/clock_guard.h"
#include "bipc/ir/state_change.h"

namespace smcbip::engines {

namespace {

using bipc::ir::AtomType;
using bipc::ir::ConnectorInstance;
using bipc::ir::PortRef;
using bipc::ir::System;

/// Whether the compiled step path runs atoms of this type: compiled steps and nothing that
/// needs the semantics it leaves to the engines (priorities, invariants, resume).
bool covers_atom_type(const System& system, const ModelCode& code, Index t) {
  const AtomType& type = system.atom_types[t];
  if (!code.compiles_atom_type(t) || !type.priorities.empty() || !type.invariants.empty() ||
      type.initial_resume) {
    return false;
  }
  return std::none_of(type.transitions.begin(), type.transitions.end(),
                      [](const bipc::ir::Transition& tr) { return tr.resume.has_value(); });
}

/// Whether the connector's define is a flat sequence of its ports with some triggers, and it
/// has no data or code: under maximal progress it executes every offering port at once.
bool is_plain_broadcast(const System& system, const Layout& layout, Index k) {
  const ConnectorInstance& connector = system.connectors[k];
  const auto& type = system.connector_types[connector.type];
  if (!layout.untimed || !layout.maximal_only[k] || !type.data.empty() ||
      !type.interactions.empty() || type.define.size() != connector.bound.size()) {
    return false;
  }
  std::vector<std::uint8_t> seen(connector.bound.size(), 0);
  bool trigger = false;
  for (const bipc::ir::DefineNode& node : type.define) {
    if (node.port >= seen.size() || !node.children.empty() || seen[node.port]) return false;
    seen[node.port] = 1;
    trigger = trigger || node.trigger;
  }
  return trigger;
}

/// Whether connector `k` is a listed rendezvous or plain broadcast whose ports each bind one
/// atom port.
bool covers_connector(const System& system, const Layout& layout, Index k) {
  const ConnectorInstance& connector = system.connectors[k];
  const auto& type = system.connector_types[connector.type];
  const std::size_t n = connector.bound.size();
  if (n == 0 || type.resume != bipc::ir::ConnectorType::Resume::None) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& refs = connector.bound[i];
    if (refs.size() != 1 || refs.front().kind != PortRef::Kind::Atom ||
        connector.bound_through_compound[i]) {
      return false;
    }
  }
  if (is_plain_broadcast(system, layout, k)) return true;
  if (n > kPortSetBits) return false;
  const PortSet all = n == kPortSetBits ? ~PortSet{0} : (PortSet{1} << n) - 1;
  return layout.enumerated[k] && layout.defined[k].size() == 1 &&
         layout.defined[k].front().ports == all;
}

bool covers_system(const System& system, const Layout& layout, const ModelCode& code) {
  if (!layout.extern_ports.empty() || !system.functions.empty() ||
      !layout.ruled_compounds.empty() ||
      layout.listed_connectors.size() != system.connectors.size()) {
    return false;
  }
  for (Index t = 0; t < system.atom_types.size(); ++t) {
    if (!covers_atom_type(system, code, t)) return false;
  }
  for (Index k = 0; k < system.connectors.size(); ++k) {
    if (!covers_connector(system, layout, k)) return false;
  }
  return true;
}

FlatTables::AtomPort atom_port(const FlatTables& tables, Index a, Index port) {
  const FlatTables::Atom& atom = tables.atoms[a];
  return {atom, a, port, atom.first_offer + port};
}

FlatTables::Connector connector_entry(const System& system, const Layout& layout, Index k,
                                      FlatTables& tables) {
  const ConnectorInstance& connector = system.connectors[k];
  const auto& type = system.connector_types[connector.type];
  FlatTables::Connector entry;
  entry.index = k;
  entry.type = connector.type;
  entry.first_port = static_cast<std::uint32_t>(tables.ports.size());
  entry.triggered = is_plain_broadcast(system, layout, k);
  entry.enumerated = layout.enumerated[k] != 0;
  tables.has_triggered = tables.has_triggered || entry.triggered;
  for (const auto& refs : connector.bound) {
    const PortRef& ref = refs.front();
    const bipc::ir::Port& port = system.atom_types[system.atoms[ref.instance].type].ports[ref.port];
    tables.ports.push_back({atom_port(tables, ref.instance, ref.port),
                            static_cast<std::uint32_t>(tables.param_slots.size())});
    for (Index slot : port.data) {
      tables.param_slots.push_back(
          static_cast<std::uint32_t>(layout.atom_data[ref.instance] + slot));
    }
  }
  entry.ports_end = static_cast<std::uint32_t>(tables.ports.size());
  std::vector<Index> atoms;
  for (std::uint32_t i = entry.first_port; i < entry.ports_end; ++i) {
    atoms.push_back(tables.ports[i].atom);
  }
  std::sort(atoms.begin(), atoms.end());
  entry.distinct_atoms = std::adjacent_find(atoms.begin(), atoms.end()) == atoms.end();
  entry.data = static_cast<std::uint32_t>(layout.connector_data[k]);
  entry.data_size = static_cast<std::uint32_t>(type.data.size());
  entry.value_data = tables.value_data_size;
  tables.value_data_size += entry.data_size;
  if (entry.triggered) {
    for (const bipc::ir::DefineNode& node : type.define) {
      tables.ports[entry.first_port + node.port].trigger = node.trigger;
    }
    return entry;
  }
  entry.code = layout.defined[k].front().code;
  if (entry.code >= 0) {
    const auto& interaction = type.interactions[static_cast<std::size_t>(entry.code)];
    entry.guarded = !interaction.guard.empty() || !interaction.up.empty();
    entry.has_down = !interaction.down.empty();
  }
  return entry;
}

/// Per atom, the item positions whose items its offers decide, increasing.
void index_neighbours(FlatTables& tables) {
  std::vector<std::vector<std::uint32_t>> of_atom(tables.atoms.size());
  for (std::uint32_t p = 0; p < tables.connectors.size(); ++p) {
    const FlatTables::Connector& c = tables.connectors[p];
    for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) {
      auto& list = of_atom[tables.ports[i].atom];
      if (list.empty() || list.back() != p) list.push_back(p);
    }
  }
  const auto connectors = static_cast<std::uint32_t>(tables.connectors.size());
  for (std::uint32_t i = 0; i < tables.internal.size(); ++i) {
    of_atom[tables.internal[i].atom].push_back(connectors + i);
  }
  for (Index a = 0; a < tables.atoms.size(); ++a) {
    std::vector<std::uint32_t>& list = of_atom[a];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    tables.atoms[a].first_neighbour = static_cast<std::uint32_t>(tables.neighbours.size());
    tables.neighbours.insert(tables.neighbours.end(), list.begin(), list.end());
    tables.atoms[a].neighbours_end = static_cast<std::uint32_t>(tables.neighbours.size());
  }
}

/// Per position, the positions whose items firing it may change: those of the atoms it binds,
/// increasing. Left empty when they would take much more room than the atoms' lists (a hub
/// atom in many connectors): steps then gather them from the atoms they touched.
void index_affected(FlatTables& tables) {
  const std::size_t limit = std::max<std::size_t>(65536, 4 * tables.neighbours.size());
  std::vector<std::uint32_t> list;
  const auto add_atom = [&](Index a) {
    const FlatTables::Atom& atom = tables.atoms[a];
    list.insert(list.end(), tables.neighbours.begin() + atom.first_neighbour,
                tables.neighbours.begin() + atom.neighbours_end);
  };
  for (std::uint32_t p = 0; p < tables.positions(); ++p) {
    list.clear();
    if (p < tables.connectors.size()) {
      const FlatTables::Connector& c = tables.connectors[p];
      for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) add_atom(tables.ports[i].atom);
    } else {
      add_atom(tables.internal[p - tables.connectors.size()].atom);
    }
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    if (tables.affected.size() + list.size() > limit) {
      tables.affected.clear();
      tables.first_affected.clear();
      return;
    }
    tables.first_affected.push_back(static_cast<std::uint32_t>(tables.affected.size()));
    tables.affected.insert(tables.affected.end(), list.begin(), list.end());
  }
  tables.first_affected.push_back(static_cast<std::uint32_t>(tables.affected.size()));
}

bool is_stochastic(const System& system, Index atom, Index port) {
  return system.atom_types[system.atoms[atom].type].ports[port].stochastic.has_value();
}

/// Per position, the first @stochastic atom port its item fires (in parameter order).
void index_stochastic_ports(const System& system, FlatTables& tables) {
  for (const FlatTables::Connector& c : tables.connectors) {
    std::optional<std::pair<Index, Index>>& found = tables.stochastic.emplace_back();
    for (std::uint32_t i = c.first_port; i < c.ports_end && !found; ++i) {
      const FlatTables::Port& port = tables.ports[i];
      if (is_stochastic(system, port.atom, port.port)) found = std::pair{port.atom, port.port};
    }
  }
  for (const FlatTables::Internal& internal : tables.internal) {
    std::optional<std::pair<Index, Index>>& found = tables.stochastic.emplace_back();
    if (is_stochastic(system, internal.atom, internal.port)) {
      found = std::pair{internal.atom, internal.port};
    }
  }
}

/// FlatTables::lazy_unbounded: the transitions of every atom's type are lazy and their guards
/// read no clock.
bool offers_lazy_unbounded(const System& system) {
  return std::all_of(system.atoms.begin(), system.atoms.end(), [&](const auto& atom) {
    const AtomType& type = system.atom_types[atom.type];
    return std::all_of(
        type.transitions.begin(), type.transitions.end(), [](const bipc::ir::Transition& tr) {
          return tr.urgency == bipc::Urgency::Lazy && !bipc::ir::reads_clock(tr.guard);
        });
  });
}

/// Per atom type, the first of its transitions' entries in `changing`, which it fills.
std::vector<std::uint32_t> index_changing_transitions(const System& system, FlatTables& tables) {
  std::vector<std::uint32_t> first;
  for (const AtomType& type : system.atom_types) {
    first.push_back(static_cast<std::uint32_t>(tables.changing.size()));
    for (const bipc::ir::Transition& transition : type.transitions) {
      const bool changes = bipc::ir::always_changes_state(transition, false);
      const bool after_down = bipc::ir::always_changes_state(transition, true);
      tables.changing.push_back(static_cast<std::uint8_t>(
          (changes ? FlatTables::kChanges : 0) | (after_down ? FlatTables::kChangesAfterDown : 0)));
    }
  }
  return first;
}

}  // namespace

std::optional<FlatTables> flat_tables(const System& system, const Layout& layout,
                                      const ModelCode& code) {
  if (!covers_system(system, layout, code)) return std::nullopt;
  FlatTables tables;
  const std::vector<std::uint32_t> first_transition = index_changing_transitions(system, tables);
  for (Index a = 0; a < system.atoms.size(); ++a) {
    const Index t = system.atoms[a].type;
    FlatTables::Atom atom;
    atom.type = t;
    atom.data = static_cast<std::uint32_t>(layout.atom_data[a]);
    atom.places = static_cast<std::uint32_t>(layout.atom_places[a]);
    atom.data_size = static_cast<std::uint32_t>(system.atom_types[t].data.size());
    atom.place_count = static_cast<std::uint32_t>(system.atom_types[t].places.size());
    atom.params = static_cast<std::uint32_t>(layout.atom_params[a]);
    atom.clocks = static_cast<std::uint32_t>(layout.atom_clocks[a]);
    atom.first_offer = tables.offer_count;
    atom.port_count = static_cast<std::uint32_t>(system.atom_types[t].ports.size());
    atom.has_internal_transitions = !layout.internal_transitions[t].empty();
    atom.has_clocks = !system.atom_types[t].clocks.empty();
    atom.first_transition = first_transition[t];
    tables.offer_count += atom.port_count;
    tables.atoms.push_back(atom);
  }
  for (Index k : layout.listed_connectors) {
    tables.connectors.push_back(connector_entry(system, layout, k, tables));
  }
  for (const auto& [atom, port] : layout.internal_ports) {
    tables.internal.push_back(atom_port(tables, atom, port));
  }
  index_neighbours(tables);
  index_affected(tables);
  index_stochastic_ports(system, tables);
  tables.lazy_unbounded = offers_lazy_unbounded(system);
  return tables;
}

}  // namespace smcbip::engines
