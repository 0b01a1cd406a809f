// Building the Petri net of a system from its IR, with the engines' listing of connectors and
// internal ports.
#include "fdir/net/petri_net.h"

#include <algorithm>
#include <span>

#include "engines/semantics/layout.h"
#include "fdir/errors.h"

namespace smcbip::fdir {

namespace {

using bipc::ir::System;

/// The transitions of `atom`'s type labelled by `port`.
std::vector<Index> labelled(const System& system, Index atom, Index port) {
  std::vector<Index> out;
  const auto& type = system.atom_types[system.atoms[atom].type];
  for (Index t = 0; t < type.transitions.size(); ++t) {
    if (type.transitions[t].port == port) out.push_back(t);
  }
  return out;
}

/// The offers of one port parameter of a connector.
std::vector<PortOffer> offers(const System& system, Index connector, Index param) {
  const bipc::ir::ConnectorInstance& c = system.connectors[connector];
  std::vector<PortOffer> out;
  for (const bipc::ir::PortRef& ref : c.bound[param]) {
    if (ref.kind != bipc::ir::PortRef::Kind::Atom) {
      throw UnsupportedModel("connector " + c.path + " binds the export of another connector (" +
                             c.bound_names[param] +
                             "): prove does not handle hierarchical connectors yet");
    }
    out.push_back({param, ref.instance, ref.port, labelled(system, ref.instance, ref.port)});
  }
  return out;
}

void add_connector(const System& system, Index connector, PetriNet& net) {
  const bipc::ir::ConnectorInstance& c = system.connectors[connector];
  const bipc::ir::ConnectorType& type = system.connector_types[c.type];
  const auto sets = engines::defined_interactions(type.define, 1u << 16);
  if (!sets) {
    throw UnsupportedModel("connector " + c.path +
                           " defines too many interactions for prove (more than 65536)");
  }
  for (engines::PortSet set : *sets) {
    NetInteraction interaction;
    interaction.connector = connector;
    interaction.name = system.root_name + "." + c.path;
    std::vector<Index> params;
    for (Index p = 0; p < type.ports.size() && p < engines::kPortSetBits; ++p) {
      if (set & (engines::PortSet{1} << p)) params.push_back(p);
    }
    interaction.code = engines::interaction_code(type, std::span<const Index>(params));
    for (Index p : params) interaction.ports.push_back(offers(system, connector, p));
    net.interactions.push_back(std::move(interaction));
  }
}

void sorted_unique(std::vector<Index>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

/// One net transition per choice of an offer and a transition for every port of the
/// interaction (an odometer over the choices).
void add_transitions(const System& system, Index k, PetriNet& net, std::size_t max) {
  const NetInteraction& interaction = net.interactions[k];
  std::vector<std::pair<Index, Index>> choices;  // per port: (offer, transition) counters
  std::vector<std::vector<std::pair<Index, Index>>> options(interaction.ports.size());
  for (std::size_t p = 0; p < interaction.ports.size(); ++p) {
    for (Index o = 0; o < interaction.ports[p].size(); ++o) {
      for (Index t : interaction.ports[p][o].transitions) options[p].push_back({o, t});
    }
    if (options[p].empty()) return;  // a port no transition offers: never enabled
  }
  std::vector<std::size_t> pick(options.size(), 0);
  for (;;) {
    NetTransition t;
    t.interaction = k;
    for (std::size_t p = 0; p < options.size(); ++p) {
      const auto [o, tr] = options[p][pick[p]];
      const Index atom = interaction.ports[p][o].atom;
      const auto& trans = system.atom_types[system.atoms[atom].type].transitions[tr];
      t.moves.push_back({atom, tr});
      for (Index pl : trans.from) t.pre.push_back(net.first_place[atom] + pl);
      for (Index pl : trans.to) t.post.push_back(net.first_place[atom] + pl);
    }
    sorted_unique(t.pre);
    sorted_unique(t.post);
    if (net.transitions.size() >= max) {
      throw UnsupportedModel("the Petri net of the model has more than " + std::to_string(max) +
                             " transitions: too large for prove");
    }
    net.transitions.push_back(std::move(t));
    std::size_t p = 0;
    while (p < pick.size() && ++pick[p] == options[p].size()) pick[p++] = 0;
    if (p == pick.size()) return;
  }
}

/// Atoms that wait inside an action (`resume`) have states between places, which the net does
/// not have.
void refuse_resumes(const bipc::ir::AtomType& type) {
  for (const bipc::ir::Transition& t : type.transitions) {
    if (t.resume) throw UnsupportedModel("prove does not handle resume yet", t.loc);
  }
  if (type.initial_resume) {
    throw UnsupportedModel("prove does not handle resume yet (in the initial action of " +
                           type.name + ")");
  }
}

void add_places(const System& system, PetriNet& net) {
  for (Index a = 0; a < system.atoms.size(); ++a) {
    const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
    refuse_resumes(type);
    net.first_place.push_back(static_cast<Index>(net.places.size()));
    for (const std::string& place : type.places) {
      net.places.push_back(system.root_name + "." + system.atoms[a].path + "." + place);
      net.initial.push_back(0);
    }
    for (Index p : type.initial_places) net.initial[net.first_place[a] + p] = 1;
  }
}

}  // namespace

PetriNet build_petri_net(const System& system, std::size_t max_transitions) {
  engines::Layout layout;
  if (std::string error = engines::build_layout(system, layout); !error.empty()) {
    throw UnsupportedModel(error);
  }
  if (!layout.extern_ports.empty()) {
    throw UnsupportedModel("prove does not handle extern ports yet");
  }
  for (const bipc::ir::ConnectorInstance& c : system.connectors) {
    if (system.connector_types[c.type].export_name) {
      throw UnsupportedModel("connector " + c.path +
                             " exports a port: prove does not handle hierarchical connectors yet");
    }
  }
  PetriNet net;
  add_places(system, net);
  for (Index c : layout.listed_connectors) add_connector(system, c, net);
  for (const auto& [atom, port] : layout.internal_ports) {
    NetInteraction interaction;
    interaction.kind = NetInteraction::Kind::InternalPort;
    interaction.name =
        layout.atom_names[atom] + "." + system.atom_types[system.atoms[atom].type].ports[port].name;
    interaction.ports.push_back({{0, atom, port, labelled(system, atom, port)}});
    net.interactions.push_back(std::move(interaction));
  }
  for (Index a = 0; a < system.atoms.size(); ++a) {
    const std::vector<Index> spontaneous = labelled(system, a, bipc::ir::kNone);
    if (spontaneous.empty()) continue;
    NetInteraction interaction;
    interaction.kind = NetInteraction::Kind::Spontaneous;
    interaction.name = layout.atom_names[a] + " (transitions without port)";
    interaction.ports.push_back({{0, a, bipc::ir::kNone, spontaneous}});
    net.interactions.push_back(std::move(interaction));
  }
  for (Index k = 0; k < net.interactions.size(); ++k) {
    add_transitions(system, k, net, max_transitions);
  }
  return net;
}

}  // namespace smcbip::fdir
