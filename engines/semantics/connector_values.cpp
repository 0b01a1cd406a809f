// Connector interactions of one run: which connectors can have values, their values built
// from their ports' offers, and the optimised scheduler's reuse of unchanged ones.
#include "engines/semantics/connector_values.h"

#include <algorithm>
#include <bit>

#include "engines/semantics/compound_priorities.h"
#include "engines/semantics/detail/runtime_shared.h"
#include "engines/semantics/item_listing.h"
#include "engines/semantics/maximal_interaction.h"

namespace smcbip::engines {

using bipc::ir::kNone;
using detail::add_offer_constraint;
using detail::connector_frame;
using detail::PortContext;

ConnectorValues::ConnectorValues(const bipc::ir::System& system, const Layout& layout,
                                 const RuntimeOptions& options, ModelCode& eval, RunState& state,
                                 const std::vector<std::optional<AtomPortValue>>& port_values,
                                 const std::vector<std::size_t>& port_offset, ConnectorCache& cache,
                                 ItemListing& listing, CompoundPriorities& priorities)
    : system_(system),
      layout_(layout),
      incremental_(options.incremental),
      maximal_progress_(options.maximal_progress),
      eval_(eval),
      state_(state),
      port_values_(port_values),
      port_offset_(port_offset),
      cache_(cache),
      listing_(listing),
      priorities_(priorities) {}

void ConnectorValues::index() {
  index_port_data();
  index_single_atom_ports();
  index_required_offers();
  index_direct_connectors();
}

void ConnectorValues::index_port_data() {
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    for (const bipc::ir::Port& port : system_.atom_types[system_.atoms[a].type].ports) {
      port_data_begin_.push_back(port_data_slots_.size());
      for (Index slot : port.data) port_data_slots_.push_back(layout_.atom_data[a] + slot);
    }
  }
}

Val* ConnectorValues::port_slot(const void* context, Index port, std::uint16_t arg) {
  const auto& c = *static_cast<const detail::PortContext*>(context);
  const PortValue& pv = detail::chosen(*c.value, port);
  ConnectorValues& r = *c.connectors;
  if (pv.from_atom) {
    const std::size_t first = r.port_data_begin_[r.port_offset_[pv.atom] + pv.port];
    return &r.state_.data[r.port_data_slots_[first + arg]];
  }
  InteractionValue& sub = r.values_[pv.sub];
  const auto& type = r.system_.connector_types[r.system_.connectors[sub.connector].type];
  return &sub.data[type.export_data[arg]];
}

void ConnectorValues::index_required_offers() {
  required_offers_.resize(system_.connectors.size());
  has_sub_connectors_.assign(system_.connectors.size(), 0);
  for (Index k = 0; k < system_.connectors.size(); ++k) {
    const bipc::ir::ConnectorInstance& connector = system_.connectors[k];
    for (std::size_t i = 0; i < connector.bound.size(); ++i) {
      bool atoms_only = true;
      for (const bipc::ir::PortRef& ref : connector.bound[i]) {
        atoms_only = atoms_only && ref.kind == bipc::ir::PortRef::Kind::Atom;
      }
      if (!atoms_only) has_sub_connectors_[k] = 1;
      if (!atoms_only || i >= kPortSetBits || !(layout_.required_ports[k] & (PortSet{1} << i))) {
        continue;
      }
      for (const bipc::ir::PortRef& ref : connector.bound[i]) {
        required_offers_[k].push_back({ref.instance, port_offset_[ref.instance] + ref.port, false});
      }
      if (!required_offers_[k].empty()) required_offers_[k].back().ends_group = true;
    }
  }
}

bool ConnectorValues::misses_required_atom_port(Index k) const {
  bool offered = false;
  for (const RequiredOffer& r : required_offers_[k]) {
    offered = offered || (!state_.resume_pending[r.atom] && port_values_[r.port_value]);
    if (!r.ends_group) continue;
    if (!offered) return true;
    offered = false;
  }
  return false;
}

void ConnectorValues::index_single_atom_ports() {
  single_atom_ports_.resize(system_.connectors.size());
  for (Index k = 0; k < system_.connectors.size(); ++k) {
    const auto& bound = system_.connectors[k].bound;
    bool single = !bound.empty() && layout_.enumerated[k] && !tries_largest(k);
    for (const auto& refs : bound) {
      single = single && refs.size() == 1 && refs.front().kind == bipc::ir::PortRef::Kind::Atom;
    }
    if (!single) continue;
    for (const auto& refs : bound) {
      const bipc::ir::PortRef& ref = refs.front();
      single_atom_ports_[k].push_back(
          {ref.instance, ref.port, port_offset_[ref.instance] + ref.port});
    }
  }
}

void ConnectorValues::index_direct_connectors() {
  if (!incremental_) return;
  for (Index k = 0; k < system_.connectors.size(); ++k) {
    // Single atom ports only: no sub-connector.
    bool offers_only = !single_atom_ports_[k].empty();
    for (const bipc::ir::InteractionCode& code :
         system_.connector_types[system_.connectors[k].type].interactions) {
      offers_only = offers_only && code.guard.empty() && code.up.empty();
    }
    if (offers_only) cache_.note_offers_only(k);
  }
}

void ConnectorValues::compute_sub_connectors(Index k) {
  if (!has_sub_connectors_[k]) return;
  for (const auto& refs : system_.connectors[k].bound) {
    for (const bipc::ir::PortRef& ref : refs) {
      if (ref.kind == bipc::ir::PortRef::Kind::Connector) compute_connector(ref.instance);
    }
  }
}

void ConnectorValues::recompute_priorities(Index k) {
  priorities_.recompute(k);
  listing_.count_connector(k);
}

void ConnectorValues::compute_connector(Index k) {
  if (!cache_.claim(k)) return;
  release_values(k);
  if (!single_atom_ports_[k].empty()) {
    compute_single_offer_interactions(k);
    return;
  }
  // Most connectors of a state lack an offer that all their interactions need: they have no
  // interactions, found without gathering offers. Sub-connectors are computed all the same, in
  // the usual order, as their code may have effects (extern calls) or fail.
  if (misses_required_atom_port(k)) {
    compute_sub_connectors(k);
    return;
  }
  compute_interactions(k);
}

void ConnectorValues::release_values(Index k) {
  // Connectors binding this one are stale too, so nothing refers to its old values any more.
  if (connector_values_[k].empty()) return;
  for (Index v : connector_values_[k]) free_values_.push_back(v);
  connector_values_[k].clear();
  listing_.note_no_values(k);
}

bool ConnectorValues::tries_largest(Index k) const {
  return layout_.maximal_only[k] && maximal_progress_ &&
         (!layout_.enumerated[k] || layout_.defined[k].size() > 1);
}

void ConnectorValues::compute_interactions(Index k) {
  // Scratch per recursion depth (sub-connectors are computed from inside gather_offers).
  if (scratch_depth_ == scratch_.size()) scratch_.emplace_back();
  ConnectorScratch& scratch = scratch_[scratch_depth_];
  const struct DepthGuard {
    std::size_t& depth;
    ~DepthGuard() { --depth; }
  } depth_guard{++scratch_depth_};
  gather_offers(k, scratch);
  if (tries_largest(k) && add_largest_values(k, scratch)) return;
  if (!layout_.enumerated[k]) {
    throw UnsupportedRun{"connector '" + layout_.connector_names[k] +
                         "': its enabled ports offer different timing constraints (or maximal "
                         "progress is disabled), so its interactions would have to be enumerated, "
                         "and it has too many for that"};
  }
  const auto defined = static_cast<std::uint32_t>(layout_.defined[k].size());
  for (std::uint32_t d = 0; d < defined; ++d) add_interactions(k, d, scratch);
}

void ConnectorValues::gather_offers(Index k, ConnectorScratch& scratch) {
  const bipc::ir::ConnectorInstance& connector = system_.connectors[k];
  std::vector<PortValue>& offers = scratch.offers;
  offers.clear();
  scratch.first_offer.clear();
  for (Index i = 0; i < connector.bound.size(); ++i) {
    scratch.first_offer.push_back(static_cast<std::uint32_t>(offers.size()));
    for (const bipc::ir::PortRef& ref : connector.bound[i]) {
      if (ref.kind == bipc::ir::PortRef::Kind::Atom) {
        if (state_.resume_pending[ref.instance]) continue;
        const auto& v = port_values_[port_offset_[ref.instance] + ref.port];
        if (v) offers.push_back({true, ref.instance, ref.port, kNone, v->constraint, i});
        continue;
      }
      compute_connector(ref.instance);
      const bool maximal_only = connector.bound_through_compound[i];
      for (Index sub : connector_values_[ref.instance]) {
        const InteractionValue& sv = values_[sub];
        const Constraint& c = maximal_only ? sv.after : sv.raw;
        if (maximal_only && c.interval.empty()) continue;
        offers.push_back({false, 0, 0, sub, c, i});
      }
    }
  }
  scratch.first_offer.push_back(static_cast<std::uint32_t>(offers.size()));
}

bool ConnectorValues::add_largest_values(Index k, ConnectorScratch& scratch) {
  // Every smaller interaction is dominated by the largest for good only when they all offer
  // one constraint open to the right: it restricts them to after its window, which never ends.
  const Constraint* common = nullptr;
  for (const PortValue& offer : scratch.offers) {
    if (!common) common = &offer.constraint;
    if (offer.constraint.interval != common->interval ||
        offer.constraint.urgency != common->urgency) {
      return false;
    }
  }
  if (!common) return true;  // nothing offered: no value
  if (common->interval.right != kPlusInfinity) return false;
  const std::vector<std::uint32_t>& first = scratch.first_offer;
  const std::size_t n = first.size() - 1;
  scratch.enabled.resize(n);
  for (std::size_t i = 0; i < n; ++i) scratch.enabled[i] = first[i] != first[i + 1] ? 1 : 0;
  const auto& type = system_.connector_types[system_.connectors[k].type];
  if (!largest_enabled_interaction(type.define, scratch.enabled, scratch.members)) return true;
  ValueShape shape{k, InteractionValue::kLargest, 0, -1};
  scratch.pick.clear();
  for (Index i : scratch.members) {
    if (n <= kPortSetBits) shape.ports |= PortSet{1} << i;
    scratch.pick.push_back(first[i]);
  }
  shape.code = interaction_code(type, scratch.members);
  add_combinations(shape, scratch);
  return true;
}

void ConnectorValues::add_interactions(Index k, std::uint32_t d, ConnectorScratch& scratch) {
  const std::vector<std::uint32_t>& first = scratch.first_offer;
  const DefinedInteraction& defined = layout_.defined[k][d];
  scratch.members.clear();
  scratch.pick.clear();
  for (PortSet left = defined.ports; left != 0; left &= left - 1) {
    const auto i = static_cast<std::size_t>(std::countr_zero(left));
    if (first[i] == first[i + 1]) return;  // a port without offers
    scratch.members.push_back(static_cast<Index>(i));
    scratch.pick.push_back(first[i]);
  }
  add_combinations({k, d, defined.ports, defined.code}, scratch);
}

void ConnectorValues::add_combinations(const ValueShape& shape, ConnectorScratch& scratch) {
  const std::vector<std::uint32_t>& first = scratch.first_offer;
  const std::vector<Index>& members = scratch.members;
  std::vector<std::uint32_t>& pick = scratch.pick;
  for (;;) {
    const Index slot = start_value(shape);
    for (std::uint32_t offer : pick) add_choice(values_[slot], scratch.offers[offer]);
    keep_value_if_allowed(shape.connector, slot);
    // Next combination: the last port varies fastest (first port outermost).
    std::size_t m = members.size();
    while (m > 0) {
      --m;
      if (++pick[m] < first[members[m] + 1]) break;
      pick[m] = first[members[m]];
      if (m == 0) return;
    }
    if (members.empty()) return;
  }
}

inline Index ConnectorValues::acquire_value() {
  // Slots are reused with their vectors' capacity: no allocation once the pool has grown.
  if (free_values_.empty()) {
    values_.emplace_back();
    return static_cast<Index>(values_.size() - 1);
  }
  const Index slot = free_values_.back();
  free_values_.pop_back();
  values_[slot].choice.clear();
  return slot;
}

inline Index ConnectorValues::start_value(const ValueShape& shape) {
  const Index slot = acquire_value();
  InteractionValue& value = values_[slot];
  value.connector = shape.connector;
  value.defined = shape.defined;
  value.code = shape.code;
  value.ports = shape.ports;
  value.raw = Constraint{};
  return slot;
}

inline void ConnectorValues::add_choice(InteractionValue& value, const PortValue& offer) {
  value.choice.push_back(offer);
  add_offer_constraint(value.raw, offer.constraint);
}

void ConnectorValues::compute_single_offer_interactions(Index k) {
  // Each port offers at most once: one combination per defined interaction whose ports all do.
  const std::vector<SingleAtomPort>& ports = single_atom_ports_[k];
  // The offers through one pointer: the owner's vector would be loaded again after each write.
  const std::optional<AtomPortValue>* const offers = port_values_.data();
  PortSet offering = 0;
  for (std::size_t i = 0; i < ports.size(); ++i) {
    if (!state_.resume_pending[ports[i].atom] && offers[ports[i].offer]) {
      offering |= PortSet{1} << i;
    }
  }
  const std::vector<DefinedInteraction>& defined = layout_.defined[k];
  for (std::uint32_t d = 0; d < defined.size(); ++d) {
    if ((defined[d].ports & ~offering) != 0) continue;
    const Index slot = start_value({k, d, defined[d].ports, defined[d].code});
    InteractionValue& value = values_[slot];
    for (PortSet left = value.ports; left != 0; left &= left - 1) {
      const auto param = static_cast<Index>(std::countr_zero(left));
      const SingleAtomPort& port = ports[param];
      // Written field by field into the choice: a PortValue built on the stack and copied
      // stalled on store forwarding.
      PortValue& offer = value.choice.emplace_back();
      offer.atom = port.atom;
      offer.port = port.port;
      offer.param = param;
      const Constraint& offered = offers[port.offer]->constraint;
      offer.constraint = offered;
      add_offer_constraint(value.raw, offered);  // the offer, not its copy just written
    }
    keep_value_if_allowed(k, slot);
  }
}

void ConnectorValues::keep_value_if_allowed(Index k, Index slot) {
  InteractionValue& value = values_[slot];
  if (!value.raw.interval.empty() && connector_code_allows(value)) {
    value.after = value.raw;
    connector_values_[k].push_back(slot);
    listing_.note_values(k);
  } else {
    free_values_.push_back(slot);
  }
}

bool ConnectorValues::connector_code_allows(InteractionValue& value) {
  const Index k = value.connector;
  const auto& type = system_.connector_types[system_.connectors[k].type];
  const auto data = state_.data.begin() + static_cast<std::ptrdiff_t>(layout_.connector_data[k]);
  value.data.assign(data, data + static_cast<std::ptrdiff_t>(type.data.size()));
  const int code = value.code;
  if (code < 0) return true;
  const bipc::ir::InteractionCode& interaction = type.interactions[static_cast<std::size_t>(code)];
  if (interaction.guard.empty() && interaction.up.empty()) return true;  // e.g. only a `down`
  const PortContext context{this, &value};
  const Frame f = connector_frame(value, context, state_.now);
  if (!eval_.holds(interaction.guard, f)) return false;
  eval_.execute(interaction.up, f);
  return true;
}

void ConnectorValues::begin(bool full) {
  if (full) {
    // Every slot becomes free, keeping its vectors for reuse.
    free_values_.clear();
    for (Index v = static_cast<Index>(values_.size()); v-- > 0;) free_values_.push_back(v);
    connector_values_.resize(system_.connectors.size());
    for (IndexList& list : connector_values_) list.clear();
    listing_.clear_values();
  }
  cache_.begin(state_.now, full, [this](Index k) { return keeps_no_values(k); });
}

bool ConnectorValues::keeps_no_values(Index k) const {
  // Connectors binding sub-connectors are always recomputed: that computes their
  // sub-connectors in the usual order.
  return connector_values_[k].empty() && !has_sub_connectors_[k] && misses_required_atom_port(k);
}

void ConnectorValues::compute_compound(const std::vector<Index>& connectors) {
  // All values of the compound first: priorities compare them with each other. The cache is
  // read through a local reference, which the calls leave in a register.
  ConnectorCache& cache = cache_;
  for (Index k : connectors) {
    if (cache.stale(k)) compute_connector(k);
  }
  for (Index k : connectors) {
    if (cache.needs_priorities(k)) recompute_priorities(k);
  }
}

void ConnectorValues::compute(bool full) {
  // Compounds bottom-up: a compound export of a sub-connector needs its values after
  // priorities. Deeper compounds have larger indices than their parents.
  if (full) {
    for (Index c = static_cast<Index>(system_.compounds.size()); c-- > 0;) {
      compute_compound(system_.compounds[c].connectors);
    }
    return;
  }
  // Only the compounds, and their connectors, that the cache finds work in: no step walks
  // every connector. Direct connectors first: nothing else depends on them.
  for (Index k : cache_.direct_work()) {
    release_values(k);
    compute_single_offer_interactions(k);
    recompute_priorities(k);
  }
  for (Index c = 0; cache_.next_compound(c);) compute_compound(cache_.work(c));
}

}  // namespace smcbip::engines
