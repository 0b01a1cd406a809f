// The items of a state: listed from the connectors' values, the internal ports' offers and the
// extern ports' events, each cut to the waiting window; or, for the optimised scheduler on
// untimed layouts, counted per listing position, so that a step finds the item it chose in
// O(log n) and lists them all only when a trace or a prompt shows them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/semantics/connector_cache.h"
#include "engines/semantics/extern_ports.h"
#include "engines/semantics/index_list.h"
#include "engines/semantics/index_set.h"
#include "engines/semantics/item_index.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/position_set.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

/// The items of a run's current state. It reads the state, the interaction values and their
/// lists per connector, the atom ports' offers (flattened by atom, port from `port_offset`) and
/// the extern ports, which its owner keeps; the owner tells it which connectors have values and
/// which counts changed.
class ItemListing {
 public:
  /// `incremental`: the values are kept between steps; on an untimed layout the items are then
  /// counted rather than listed.
  ItemListing(const bipc::ir::System& system, const Layout& layout, const RunState& state,
              const std::vector<InteractionValue>& values,
              const std::vector<IndexList>& connector_values,
              const std::vector<std::optional<AtomPortValue>>& port_values,
              const std::vector<std::size_t>& port_offset, const ExternPorts& extern_ports,
              bool incremental);

  /// The connector's index in Layout::listed_connectors, or kNone.
  Index listed_position(Index connector) const { return listed_position_[connector]; }
  /// The connector has values (has none) since its last computation.
  void note_values(Index connector) {
    if (listed_position_[connector] != bipc::ir::kNone) {
      listed_with_values_.insert(listed_position_[connector]);
    }
  }
  void note_no_values(Index connector) {
    if (listed_position_[connector] != bipc::ir::kNone) {
      listed_with_values_.erase(listed_position_[connector]);
    }
  }
  /// No connector has values (all are computed again).
  void clear_values() { listed_with_values_.clear(); }
  /// Keeps the count of the connector's items (if listed) up to date.
  void count_connector(Index connector) {
    // Inline: without counts (most runs) no call per recomputed connector.
    if (counts_ && listed_position_[connector] != bipc::ir::kNone) count_listed(connector);
  }
  /// Keeps urgent_internal_ports() and the counts up to date for the internal ports of the
  /// atoms touched since the last computation (all atoms when `full`).
  void note_internal_ports(bool full, const ConnectorCache& cache);
  /// Internal ports (indices into Layout::internal_ports) offered with an urgent constraint.
  const IndexSet& urgent_internal_ports() const { return urgent_internal_ports_; }

  /// The items are being computed: none until end().
  void begin() {
    items_.clear();
    listed_ = true;
  }
  /// The items are those of the values and offers now, cut to `window`.
  void end(const Interval& window) {
    window_ = window;
    listed_ = false;
    if (!counts_) list();
  }
  const std::vector<Item>& items() const {
    if (!listed_) list();
    return items_;
  }
  const Interval& window() const { return window_; }
  /// items().size() and items()[k], without listing the items when they are counted.
  std::size_t count() const;
  Item item(std::size_t k) const;

 private:
  void count_listed(Index connector);
  void note_internal_port(Index internal_port);
  /// items_ from the values and offers, cut to window_.
  void list() const;
  /// Whether count and item find items through item_index_ rather than items_.
  bool counted() const;
  Item counted_item(std::size_t k) const;
  /// The item of an enabled constraint with its window cut to window_; false when that leaves
  /// nothing.
  bool cut(const Constraint& c, Item& item) const;
  Item connector_item(std::size_t position, std::uint32_t rank) const;
  Item internal_item(Index internal_port) const;
  const std::optional<AtomPortValue>& offer(Index atom, Index port) const {
    return port_values_[port_offset_[atom] + port];
  }

  const Layout& layout_;
  const RunState& state_;
  const std::vector<InteractionValue>& values_;
  const std::vector<IndexList>& connector_values_;
  const std::vector<std::optional<AtomPortValue>>& port_values_;
  const std::vector<std::size_t>& port_offset_;
  const ExternPorts& extern_ports_;
  // On an untimed layout every enabled value and offered internal port is an item whenever
  // the waiting window is [now, +inf) (see counted), so counts per position suffice:
  // positions are the listed connectors, then the internal ports.
  bool counts_ = false;
  ItemIndex item_index_;
  // Listed lazily (see items()) when counted.
  mutable std::vector<Item> items_;
  mutable bool listed_ = true;
  Interval window_;
  std::vector<Index> listed_position_;  // per connector: index in listed_connectors, or kNone
  // The listed connectors that have values, by position in Layout::listed_connectors.
  PositionSet listed_with_values_;
  IndexSet urgent_internal_ports_;
  std::vector<std::vector<Index>> internal_ports_of_;  // per atom, its internal ports
};

}  // namespace smcbip::engines
