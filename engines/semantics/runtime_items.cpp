// The optimised scheduler's items on untimed layouts: counted per listing position as the
// connectors and atoms a step touched change, so that a step finds the item it chose in
// O(log n) and lists them all only when a trace or a prompt shows them.
#include "engines/semantics/runtime.h"

namespace smcbip::engines {

using bipc::ir::kNone;

void Runtime::index_listing() {
  listed_position_.assign(system_.connectors.size(), kNone);
  for (Index i = 0; i < layout_.listed_connectors.size(); ++i) {
    listed_position_[layout_.listed_connectors[i]] = i;
  }
  listed_with_values_.resize(layout_.listed_connectors.size());
  internal_ports_of_.assign(system_.atoms.size(), {});
  for (Index i = 0; i < layout_.internal_ports.size(); ++i) {
    internal_ports_of_[layout_.internal_ports[i].first].push_back(i);
  }
  urgent_internal_ports_.reset(layout_.internal_ports.size());
  // On an untimed layout every enabled value and offered internal port is an item whenever
  // the waiting window is [now, +inf) (see items_counted), so counts per position suffice.
  counts_items_ = options_.incremental && layout_.untimed;
  if (counts_items_) {
    item_index_.reset(layout_.listed_connectors.size() + layout_.internal_ports.size());
  }
}

void Runtime::count_connector_items(Index k) {
  if (!counts_items_ || listed_position_[k] == kNone) return;
  std::uint32_t count = 0;
  for (Index v : connector_values_[k]) count += values_[v].after.interval.empty() ? 0 : 1;
  item_index_.set(listed_position_[k], count);
}

void Runtime::note_internal_ports(bool full) {
  if (layout_.internal_ports.empty()) return;  // spares a lookup per touched atom
  if (full) {
    for (Index i = 0; i < layout_.internal_ports.size(); ++i) note_internal_port(i);
    return;
  }
  for (Index atom : cache_.touched_atoms()) {
    for (Index i : internal_ports_of_[atom]) note_internal_port(i);
  }
}

void Runtime::note_internal_port(Index i) {
  const auto& [atom, port] = layout_.internal_ports[i];
  const std::optional<AtomPortValue>& offer = port_values_[port_offset_[atom] + port];
  const bool offered = offer && !state_.resume_pending[atom];
  urgent_internal_ports_.assign(i, offered && offer->constraint.urgency != bipc::Urgency::Lazy);
  if (counts_items_) item_index_.set(layout_.listed_connectors.size() + i, offered ? 1 : 0);
}

bool Runtime::items_counted() const {
  // Without clocks and extern ports the enabled values' `after` windows are all dates or none,
  // except eager values cut to after now by priorities; those make the waiting window the
  // point now. On [now, +inf) then, every counted value and port is an item of that window.
  return counts_items_ && !items_listed_ && items_window_ == Interval::from(state_.now);
}

std::size_t Runtime::item_count() const {
  return items_counted() ? item_index_.total() : items().size();
}

Item Runtime::item(std::size_t k) const { return items_counted() ? counted_item(k) : items()[k]; }

Item Runtime::counted_item(std::size_t k) const {
  const auto [position, rank] = item_index_.find(k);
  const std::size_t listed = layout_.listed_connectors.size();
  if (position < listed) return connector_item(position, rank);
  return internal_item(static_cast<Index>(position - listed));
}

Item Runtime::connector_item(std::size_t position, std::uint32_t rank) const {
  Item item;
  for (Index v : connector_values_[layout_.listed_connectors[position]]) {
    const Constraint& after = values_[v].after;
    if (after.interval.empty()) continue;
    if (rank-- == 0) {
      cut_item(after, item);
      item.value = v;
      break;
    }
  }
  return item;
}

Item Runtime::internal_item(Index i) const {
  const auto& [atom, port] = layout_.internal_ports[i];
  Item item;
  cut_item(port_values_[port_offset_[atom] + port]->constraint, item);
  item.kind = Item::Kind::Internal;
  item.atom = atom;
  item.port = port;
  return item;
}

}  // namespace smcbip::engines
