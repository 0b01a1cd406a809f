// The items of a state, listed or counted (see item_listing.h).
#include "engines/semantics/item_listing.h"

#include "engines/semantics/detail/runtime_shared.h"

namespace smcbip::engines {

using bipc::ir::kNone;
using detail::narrow;

ItemListing::ItemListing(const bipc::ir::System& system, const Layout& layout,
                         const RunState& state, const std::vector<InteractionValue>& values,
                         const std::vector<IndexList>& connector_values,
                         const std::vector<std::optional<AtomPortValue>>& port_values,
                         const std::vector<std::size_t>& port_offset,
                         const ExternPorts& extern_ports, bool incremental)
    : layout_(layout),
      state_(state),
      values_(values),
      connector_values_(connector_values),
      port_values_(port_values),
      port_offset_(port_offset),
      extern_ports_(extern_ports),
      counts_(incremental && layout.untimed) {
  listed_position_.assign(system.connectors.size(), kNone);
  for (Index i = 0; i < layout_.listed_connectors.size(); ++i) {
    listed_position_[layout_.listed_connectors[i]] = i;
  }
  listed_with_values_.resize(layout_.listed_connectors.size());
  internal_ports_of_.assign(system.atoms.size(), {});
  for (Index i = 0; i < layout_.internal_ports.size(); ++i) {
    internal_ports_of_[layout_.internal_ports[i].first].push_back(i);
  }
  urgent_internal_ports_.reset(layout_.internal_ports.size());
  if (counts_) item_index_.reset(layout_.listed_connectors.size() + layout_.internal_ports.size());
}

void ItemListing::count_listed(Index k) {
  std::uint32_t count = 0;
  for (Index v : connector_values_[k]) count += values_[v].after.interval.empty() ? 0 : 1;
  item_index_.set(listed_position_[k], count);
}

void ItemListing::note_internal_ports(bool full, const ConnectorCache& cache) {
  if (layout_.internal_ports.empty()) return;  // spares a lookup per touched atom
  if (full) {
    for (Index i = 0; i < layout_.internal_ports.size(); ++i) note_internal_port(i);
    return;
  }
  for (Index atom : cache.touched_atoms()) {
    for (Index i : internal_ports_of_[atom]) note_internal_port(i);
  }
}

void ItemListing::note_internal_port(Index i) {
  const auto& [atom, port] = layout_.internal_ports[i];
  const std::optional<AtomPortValue>& o = offer(atom, port);
  const bool offered = o && !state_.resume_pending[atom];
  urgent_internal_ports_.assign(i, offered && o->constraint.urgency != bipc::Urgency::Lazy);
  if (counts_) item_index_.set(layout_.listed_connectors.size() + i, offered ? 1 : 0);
}

bool ItemListing::counted() const {
  // Without clocks and extern ports the enabled values' `after` windows are all dates or none,
  // except eager values cut to after now by priorities; those make the waiting window the
  // point now. On [now, +inf) then, every counted value and port is an item of that window.
  return counts_ && !listed_ && window_ == Interval::from(state_.now);
}

std::size_t ItemListing::count() const { return counted() ? item_index_.total() : items().size(); }

bool ItemListing::cut(const Constraint& c, Item& item) const {
  Interval in = c.interval;
  narrow(in, window_);
  if (in.empty()) return false;
  // Fields are copied one by one: building an Item or an Interval in memory and copying it as
  // a whole stalled on store forwarding, which cost more than the rest of an optimised step.
  item.constraint.interval.left = in.left;
  item.constraint.interval.right = in.right;
  item.constraint.interval.left_open = in.left_open;
  item.constraint.interval.right_open = in.right_open;
  item.constraint.urgency = c.urgency;
  item.offered = c;
  return true;
}

void ItemListing::list() const {
  // Items with their windows cut to the admissible waiting interval.
  items_.clear();
  listed_ = true;
  auto add = [&](const Constraint& c) -> Item* {
    Item& item = items_.emplace_back();
    if (cut(c, item)) return &item;
    items_.pop_back();
    return nullptr;
  };
  listed_with_values_.for_each([&](std::size_t position) {
    for (Index v : connector_values_[layout_.listed_connectors[position]]) {
      const Constraint& after = values_[v].after;
      if (after.interval.empty()) continue;
      if (Item* item = add(after)) item->value = v;
    }
  });
  for (const auto& [atom, port] : layout_.internal_ports) {
    if (state_.resume_pending[atom]) continue;
    const auto& v = offer(atom, port);
    if (!v) continue;
    if (Item* item = add(v->constraint)) {
      item->kind = Item::Kind::Internal;
      item->atom = atom;
      item->port = port;
    }
  }
  for (const ExternPortState& e : extern_ports_.ports()) {
    if (!e.expected) continue;
    if (Item* item = add(*e.expected)) {
      item->kind = Item::Kind::External;
      item->atom = e.atom;
      item->port = e.port;
    }
  }
}

Item ItemListing::item(std::size_t k) const { return counted() ? counted_item(k) : items()[k]; }

Item ItemListing::counted_item(std::size_t k) const {
  const auto [position, rank] = item_index_.find(k);
  const std::size_t listed = layout_.listed_connectors.size();
  if (position < listed) return connector_item(position, rank);
  return internal_item(static_cast<Index>(position - listed));
}

Item ItemListing::connector_item(std::size_t position, std::uint32_t rank) const {
  Item item;
  for (Index v : connector_values_[layout_.listed_connectors[position]]) {
    const Constraint& after = values_[v].after;
    if (after.interval.empty()) continue;
    if (rank-- == 0) {
      cut(after, item);
      item.value = v;
      break;
    }
  }
  return item;
}

Item ItemListing::internal_item(Index i) const {
  const auto& [atom, port] = layout_.internal_ports[i];
  Item item;
  cut(offer(atom, port)->constraint, item);
  item.kind = Item::Kind::Internal;
  item.atom = atom;
  item.port = port;
  return item;
}

}  // namespace smcbip::engines
