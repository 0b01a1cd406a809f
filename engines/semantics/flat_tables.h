// The tables of the compiled step path (flat_steps.h): a system whose connectors are rendezvous
// over atom ports, laid out for a step that touches a few atoms and the connectors next to them.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/semantics/layout.h"

namespace smcbip::engines {

struct FlatTables {
  struct Atom {
    Index type = 0;
    std::uint32_t data = 0, places = 0, params = 0, clocks = 0;
    std::uint32_t data_size = 0, place_count = 0;
    std::uint32_t first_offer = 0;  // into the offers, one per port of its type
    std::uint32_t port_count = 0;   // the ports of its type
    std::uint32_t first_neighbour = 0, neighbours_end = 0;  // into `neighbours`
    std::uint32_t first_transition = 0;  // into `changing`, one per transition of its type
    bool has_internal_transitions = false;
    bool has_clocks = false;
  };
  /// An atom port a step may fire, with a copy of its atom's entry: firing it then reads one
  /// entry, not two (on large systems, one cache miss fewer per port).
  struct AtomPort {
    Atom of;  // atoms[atom]
    Index atom = 0, port = 0;
    std::uint32_t offer = 0;  // into the offers
  };
  /// A port parameter of a connector and the atom port it binds.
  struct Port : AtomPort {
    std::uint32_t first_param = 0;  // into `param_slots`
    bool trigger = false;
  };
  struct Connector {
    Index index = 0;  // in System::connectors
    Index type = 0;
    std::uint32_t first_port = 0, ports_end = 0;  // into `ports`, in parameter order
    std::uint32_t data = 0, data_size = 0;        // its slots in the state
    std::uint32_t value_data = 0;                 // its value's slots in the value data
    int code = -1;                                // ConnectorType::interactions, or -1
    bool guarded = false;                         // a guard or an `up` to run
    bool has_down = false;
    /// A broadcast (some ports are triggers; untimed layouts only): its one executable
    /// interaction under maximal progress is every offering port, when a trigger offers.
    bool triggered = false;
    bool enumerated = false;     // Layout::enumerated
    bool distinct_atoms = true;  // its ports bind atom ports of different atoms
  };
  /// An internal port item.
  using Internal = AtomPort;
  std::vector<Atom> atoms;
  /// Item positions: the listed connectors in listing order, then the internal ports.
  std::vector<Connector> connectors;
  std::vector<Internal> internal;
  std::vector<Port> ports;
  std::vector<std::uint32_t> param_slots;  // state data slots of the ports' parameters
  std::vector<std::uint32_t> neighbours;   // per atom: the item positions its offers decide
  /// Per position p, affected[first_affected[p] .. first_affected[p + 1]): the positions of the
  /// atoms its item binds (their neighbours, merged), which firing it may change. Both empty
  /// when they would be much larger than `neighbours`.
  std::vector<std::uint32_t> affected, first_affected;
  /// Per position: the @stochastic atom port its item fires, if any (DatePlanner's choice).
  std::vector<std::optional<std::pair<Index, Index>>> stochastic;
  /// Per transition of each atom type (Atom::first_transition): kChanges when firing it always
  /// changes its atom's places or data, kChangesAfterDown when it does even after a connector's
  /// `down` wrote to that data (bipc/ir/state_change.h).
  static constexpr std::uint8_t kChanges = 1, kChangesAfterDown = 2;
  std::vector<std::uint8_t> changing;
  std::uint32_t offer_count = 0, value_data_size = 0;
  bool has_triggered = false;  // some connector is triggered
  /// Every offer is lazy and holds at all dates: no transition guard reads a clock and every
  /// transition is lazy. Each item's window is then every date from now on.
  bool lazy_unbounded = false;

  std::size_t positions() const { return connectors.size() + internal.size(); }
};

/// The tables of `system` when the compiled step path covers it, nullopt otherwise. It covers
/// systems without extern ports or functions, priorities, invariants or resume, whose atom
/// types `code` compiles and whose connectors are listed and bind one atom port per port
/// parameter: rendezvous (one defined interaction of all their ports), and on untimed layouts
/// also broadcasts (a flat define with triggers) without data or `on` clauses.
std::optional<FlatTables> flat_tables(const bipc::ir::System& system, const Layout& layout,
                                      const ModelCode& code);

}  // namespace smcbip::engines
