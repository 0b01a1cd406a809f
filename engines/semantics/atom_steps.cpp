// An atom's steps by interpretation of its transitions.
#include "engines/semantics/atom_steps.h"

#include <vector>

namespace smcbip::engines {

using bipc::ir::Index;

namespace {

/// Offers the transition of `entry` when it is enabled; its port when that port already has an
/// offer (a non-deterministic choice), else kNone.
[[gnu::always_inline]] inline Index offer(const bipc::ir::AtomType& type,
                                          const TransitionEntry& entry, const std::uint8_t* marking,
                                          const Frame& f, ModelCode& eval,
                                          std::optional<AtomPortValue>* offers) {
  const bipc::ir::Transition& tr = type.transitions[entry.transition];
  if (!from_marked(entry, tr, marking)) return bipc::ir::kNone;
  if (entry.leading && !leading_holds(*entry.leading, f.atom_data, f.atom_params)) {
    return bipc::ir::kNone;
  }
  // Built in place (no copy of a returned Interval, which stalled on store forwarding).
  const Interval when = [&] {
    if (tr.guard.empty() || (entry.leading && entry.leading->whole)) return Interval::all();
    return eval.holds_when(tr.guard, f);
  }();
  if (when.empty()) return bipc::ir::kNone;
  if (offers[tr.port]) return tr.port;
  offers[tr.port] = AtomPortValue{entry.transition, {when, tr.urgency}};
  return bipc::ir::kNone;
}

}  // namespace

Index interpreted_offers(const bipc::ir::System& system, const Layout& layout, Index type,
                         const std::uint8_t* marking, const Frame& f, ModelCode& eval,
                         std::optional<AtomPortValue>* offers) {
  const bipc::ir::AtomType& atom_type = system.atom_types[type];
  // A state machine looks only at the transitions from its one marked place: the same ones,
  // in the same order, that are enabled by the marking; of those led by `d == literal` on one
  // datum, only the ones whose literal is d's value.
  const std::vector<std::vector<TransitionEntry>>& from_place = layout.labelled_from_place[type];
  if (!from_place.empty()) {
    std::size_t marked = 0;
    while (marked + 1 < from_place.size() && !marking[marked]) ++marked;
    const std::vector<TransitionEntry>& entries = from_place[marked];
    if (const std::optional<ValueDispatch>& dispatch = layout.dispatch_from_place[type][marked]) {
      for (std::uint32_t i : dispatch->entries_for(f.atom_data[dispatch->slot].i)) {
        const Index port = offer(atom_type, entries[i], marking, f, eval, offers);
        if (port != bipc::ir::kNone) return port;
      }
      return bipc::ir::kNone;
    }
    for (const TransitionEntry& entry : entries) {
      const Index port = offer(atom_type, entry, marking, f, eval, offers);
      if (port != bipc::ir::kNone) return port;
    }
    return bipc::ir::kNone;
  }
  for (const TransitionEntry& entry : layout.labelled_transitions[type]) {
    const Index port = offer(atom_type, entry, marking, f, eval, offers);
    if (port != bipc::ir::kNone) return port;
  }
  return bipc::ir::kNone;
}

Index interpreted_internal(const bipc::ir::System& system, const Layout& layout, Index type,
                           const std::uint8_t* marking, const Frame& f, ModelCode& eval) {
  const bipc::ir::AtomType& atom_type = system.atom_types[type];
  Index enabled = bipc::ir::kNone;
  for (const TransitionEntry& entry : layout.internal_transitions[type]) {
    const bipc::ir::Transition& tr = atom_type.transitions[entry.transition];
    if (!from_marked(entry, tr, marking) || !guard_holds(entry, tr, f, eval)) continue;
    if (enabled != bipc::ir::kNone) return ModelCode::kSeveralTransitions;
    enabled = entry.transition;
  }
  return enabled;
}

bool interpreted_fire(const bipc::ir::Transition& transition, std::uint8_t* marking, const Frame& f,
                      ModelCode& eval) {
  for (Index p : transition.from) marking[p] = 0;
  for (Index p : transition.to) {
    if (marking[p]) return false;
    marking[p] = 1;
  }
  eval.execute(transition.action, f);
  return true;
}

}  // namespace smcbip::engines
