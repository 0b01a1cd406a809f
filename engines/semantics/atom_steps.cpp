// An atom's steps by interpretation of its transitions.
#include "engines/semantics/atom_steps.h"

#include <vector>

namespace smcbip::engines {

using bipc::ir::Index;

Index interpreted_offers(const bipc::ir::System& system, const Layout& layout, Index type,
                         const std::uint8_t* marking, const Frame& f, ModelCode& eval,
                         std::optional<AtomPortValue>* offers) {
  const bipc::ir::AtomType& atom_type = system.atom_types[type];
  // A state machine looks only at the transitions from its one marked place: the same ones,
  // in the same order, that are enabled by the marking.
  const std::vector<std::vector<TransitionEntry>>& from_place = layout.labelled_from_place[type];
  const std::vector<TransitionEntry>* entries = &layout.labelled_transitions[type];
  if (!from_place.empty()) {
    std::size_t marked = 0;
    while (marked + 1 < from_place.size() && !marking[marked]) ++marked;
    entries = &from_place[marked];
  }
  for (const TransitionEntry& entry : *entries) {
    const bipc::ir::Transition& tr = atom_type.transitions[entry.transition];
    if (!from_marked(entry, tr, marking)) continue;
    if (entry.leading && !leading_holds(*entry.leading, f.atom_data, f.atom_params)) continue;
    // Built in place (no copy of a returned Interval, which stalled on store forwarding).
    const Interval when = [&] {
      if (tr.guard.empty() || (entry.leading && entry.leading->whole)) return Interval::all();
      return eval.holds_when(tr.guard, f);
    }();
    if (when.empty()) continue;
    if (offers[tr.port]) return tr.port;
    offers[tr.port] = AtomPortValue{entry.transition, {when, tr.urgency}};
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
