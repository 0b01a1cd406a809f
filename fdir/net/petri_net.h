// The Petri net abstraction of an untimed BIP system: the places of all atoms, and one net
// transition per interaction and choice of one atom transition per participating port, plus
// the internal ones. Priorities are dropped, which over-approximates the reachable markings.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::fdir {

using bipc::ir::Index;

/// One atom transition taking part in a net transition.
struct AtomMove {
  Index atom = 0;
  Index transition = 0;  // into the atom type's transitions
};

/// A port parameter of an interaction: the atom port it binds (one of several for a merged
/// export) and the transitions labelled by that port.
struct PortOffer {
  Index param = 0;  // the connector's port parameter
  Index atom = 0, port = 0;
  std::vector<Index> transitions;  // of the atom's type, labelled by `port`
};

/// An interaction of a connector (a set of its port parameters allowed by its define), or a
/// singleton one of an internal port, or an atom's transition without a port.
struct NetInteraction {
  enum class Kind : std::uint8_t { Connector, InternalPort, Spontaneous } kind = Kind::Connector;
  Index connector = bipc::ir::kNone;  // Connector: System::connectors
  int code = -1;                      // Connector: its `on` clause, or -1
  /// Per port parameter of the interaction, every way to offer it (several through merged
  /// exports); InternalPort and Spontaneous: one offer, of their atom.
  std::vector<std::vector<PortOffer>> ports;
  std::string name;  // the connector's path, or `atom.port`
};

struct NetTransition {
  Index interaction = 0;  // into PetriNet::interactions
  std::vector<AtomMove> moves;
  std::vector<Index> pre, post;  // global place numbers, sorted, without repetition
};

struct PetriNet {
  std::vector<Index> first_place;     // per atom: the global number of its first place
  std::vector<std::string> places;    // per global place: `atom.place`
  std::vector<std::uint8_t> initial;  // per global place: marked initially
  std::vector<NetInteraction> interactions;
  std::vector<NetTransition> transitions;
};

/// Builds the net of `system`. Throws UnsupportedModel for what the abstraction does not cover
/// yet: connectors bound to the exports of other connectors, extern ports, more than
/// `max_transitions` net transitions.
PetriNet build_petri_net(const bipc::ir::System& system, std::size_t max_transitions = 1'000'000);

}  // namespace smcbip::fdir
