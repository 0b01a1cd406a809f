// The interaction values of a run's connectors: which connectors can have values, their values
// built from their ports' offers (sub-connectors first), restricted by the priorities, and the
// optimised scheduler's reuse of unchanged ones.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/connector_cache.h"
#include "engines/semantics/index_list.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

class CompoundPriorities;
class ItemListing;

/// The connectors' interaction values of a run's current state. It reads the state and the atom
/// ports' offers (flattened by atom, port from `port_offset`), which its owner keeps, runs the
/// connectors' guards and `up`s, and tells the listing which connectors have values.
class ConnectorValues {
 public:
  /// `listing` and `priorities` may be constructed after this (they read its values); they are
  /// used only once the items are computed.
  ConnectorValues(const bipc::ir::System& system, const Layout& layout,
                  const RuntimeOptions& options, ModelCode& eval, RunState& state,
                  const std::vector<std::optional<AtomPortValue>>& port_values,
                  const std::vector<std::size_t>& port_offset, ConnectorCache& cache,
                  ItemListing& listing, CompoundPriorities& priorities);

  /// Indexes the connectors' ports, once the atom ports' offsets are known.
  void index();
  /// Interaction values by index (Item::value, PortValue::sub).
  const std::vector<InteractionValue>& values() const { return values_; }
  std::vector<InteractionValue>& values() { return values_; }
  /// Per connector: its enabled values (indices into values()).
  const std::vector<IndexList>& connector_values() const { return connector_values_; }
  /// Starts a computation: every connector's values (`full`), or those of the connectors the
  /// cache finds stale.
  void begin(bool full);
  void compute(bool full);
  /// Computes the connector's values (a no-op when they are up to date).
  void compute_connector(Index connector);
  /// Where connector code finds its port parameters (Frame::port_slot); `context`: a
  /// PortContext.
  static Val* port_slot(const void* context, Index port, std::uint16_t arg);

 private:
  // Reusable buffers of compute_connector, one per depth of sub-connector recursion.
  struct ConnectorScratch {
    std::vector<PortValue> offers;           // the ports' offers, port after port
    std::vector<std::uint32_t> first_offer;  // per port, its first offer; then offers.size()
    std::vector<Index> members;              // the ports of the port set being combined
    std::vector<std::uint32_t> pick;         // per member, the offer of the combination
    std::vector<std::uint8_t> enabled;       // per port parameter: whether it has an offer
  };
  // What the values of one port set of a connector share.
  struct ValueShape {
    Index connector = 0;
    std::uint32_t defined = 0;  // InteractionValue::defined
    PortSet ports = 0;
    int code = -1;  // InteractionValue::code
  };
  /// Fills required_offers_ and has_sub_connectors_.
  void index_required_offers();
  /// Whether a port every interaction of the connector contains binds only atom ports, none of
  /// which offers anything: then the connector has no interaction.
  bool misses_required_atom_port(Index connector) const;
  /// Whether the connector had no values and, its atoms' offers being what they are, still
  /// has none: the optimised scheduler then leaves it as it is.
  bool keeps_no_values(Index connector) const;
  /// Computes the connectors bound to the connector's ports, in port order.
  void compute_sub_connectors(Index connector);
  /// Frees the connector's values of the last computation.
  void release_values(Index connector);
  /// Whether the connector's values may come from add_largest_values: a maximal_only connector
  /// under maximal progress that is not a rendezvous (one defined interaction is its own
  /// largest, and enumerating it is as quick).
  bool tries_largest(Index connector) const;
  /// The connector's interaction values, from its ports' offers.
  void compute_interactions(Index connector);
  /// Per port parameter, the offers of the atom ports and sub-connectors it binds.
  void gather_offers(Index connector, ConnectorScratch& scratch);
  /// Values of a maximal_only connector under maximal progress when its offers allow
  /// (maximal_interaction.h); false when they do not and the defined ones must be enumerated.
  bool add_largest_values(Index connector, ConnectorScratch& scratch);
  /// The values of defined interaction `d`: one per combination of its ports' offers.
  void add_interactions(Index connector, std::uint32_t d, ConnectorScratch& scratch);
  /// The values of a port set (`scratch.members`, increasing; `scratch.pick` at their first
  /// offers): one per combination of the members' offers, the last member varying fastest.
  void add_combinations(const ValueShape& shape, ConnectorScratch& scratch);
  /// compute_interactions for a connector whose ports each bind one atom port.
  void compute_single_offer_interactions(Index connector);
  /// Fills single_atom_ports_.
  void index_single_atom_ports();
  /// Tells the cache which connectors have values from their offers alone
  /// (ConnectorCache::note_offers_only); after index_single_atom_ports.
  void index_direct_connectors();
  /// Fills port_data_begin_ and port_data_slots_.
  void index_port_data();
  /// A new value of the shape, with no port chosen yet.
  [[gnu::always_inline]] inline Index start_value(const ValueShape& shape);
  /// Chooses the offer for the value's next port.
  [[gnu::always_inline]] static inline void add_choice(InteractionValue& value,
                                                       const PortValue& offer);
  /// Keeps the value among the connector's if its constraint and guard allow, else frees it.
  void keep_value_if_allowed(Index connector, Index slot);
  /// Copies the connector's data into the value and runs the guard, then `up` if it holds.
  bool connector_code_allows(InteractionValue& value);
  /// A free slot of values_ for a new value (its vectors keep their capacity).
  [[gnu::always_inline]] inline Index acquire_value();
  void compute_compound(const std::vector<Index>& connectors);
  /// The connector's values after priorities (CompoundPriorities::recompute), counted.
  void recompute_priorities(Index connector);

  const bipc::ir::System& system_;
  const Layout& layout_;
  bool incremental_;
  bool maximal_progress_;
  ModelCode& eval_;
  RunState& state_;
  const std::vector<std::optional<AtomPortValue>>& port_values_;
  const std::vector<std::size_t>& port_offset_;
  ConnectorCache& cache_;
  ItemListing& listing_;
  CompoundPriorities& priorities_;
  // Per connector: enabled interaction values (indices into values_), computed bottom up. The
  // optimised scheduler keeps them between steps: values_ is then a pool whose free slots are
  // listed in free_values_.
  std::vector<IndexList> connector_values_;
  std::vector<InteractionValue> values_;
  std::vector<Index> free_values_;
  // Per atom port (flattened like the offers): its first entry in port_data_slots_, which lists
  // the state slots of the ports' parameters (connector code reads and writes them).
  std::vector<std::size_t> port_data_begin_;
  std::vector<std::size_t> port_data_slots_;
  // Per connector whose port parameters each bind exactly one atom port: those atom ports, in
  // parameter order (empty for other connectors).
  struct SingleAtomPort {
    Index atom = 0, port = 0;
    std::size_t offer = 0;  // index into port_values_
  };
  std::vector<std::vector<SingleAtomPort>> single_atom_ports_;
  // Per connector: the atom ports bound to its port parameters that every defined interaction
  // contains (parameters binding atom ports only), parameter by parameter; and whether a
  // parameter binds a sub-connector.
  struct RequiredOffer {
    Index atom = 0;
    std::size_t port_value = 0;  // index into port_values_
    bool ends_group = false;     // the last atom port of its parameter
  };
  std::vector<std::vector<RequiredOffer>> required_offers_;
  std::vector<std::uint8_t> has_sub_connectors_;
  std::deque<ConnectorScratch> scratch_;  // deque: outer frames keep their references
  std::size_t scratch_depth_ = 0;
};

}  // namespace smcbip::engines
