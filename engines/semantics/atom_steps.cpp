// An atom's internal transitions by interpretation.
#include "engines/semantics/atom_steps.h"

namespace smcbip::engines {

bipc::ir::Index interpreted_internal(const bipc::ir::System& system, const Layout& layout,
                                     bipc::ir::Index type, const std::uint8_t* marking,
                                     const Frame& f, ModelCode& eval) {
  const bipc::ir::AtomType& atom_type = system.atom_types[type];
  bipc::ir::Index enabled = bipc::ir::kNone;
  for (const TransitionEntry& entry : layout.internal_transitions[type]) {
    const bipc::ir::Transition& tr = atom_type.transitions[entry.transition];
    if (!from_marked(entry, tr, marking) || !entry_leading_holds(layout, entry, f)) continue;
    if (!entry.leading_whole && !eval.holds(tr.guard, f)) continue;
    if (enabled != bipc::ir::kNone) return ModelCode::kSeveralTransitions;
    enabled = entry.transition;
  }
  return enabled;
}

}  // namespace smcbip::engines
