// An atom's steps by interpretation of its transitions, stated once: the Runtime takes them for
// the atom types its model's code does not compile, and the flat step path over an interpreted
// model (interpreted_steps.h) for every type. They answer as ModelCode's atom_offers,
// atom_internal and atom_fire do (model.h), over the atom's own marking.
#pragma once

#include <cstdint>
#include <optional>

#include "bipc/ir/ir.h"
#include "engines/interpreter/code_eval.h"
#include "engines/model.h"
#include "engines/semantics/layout.h"

namespace smcbip::engines {

/// Whether every `from` place of the transition is marked in the atom's `marking`.
[[gnu::always_inline]] inline bool from_marked(const TransitionEntry& entry,
                                               const bipc::ir::Transition& transition,
                                               const std::uint8_t* marking) {
  if (entry.first_place == bipc::ir::kNone) return true;
  if (!marking[entry.first_place]) return false;
  if (!entry.more_places) return true;
  for (bipc::ir::Index p : transition.from) {
    if (!marking[p]) return false;
  }
  return true;
}

/// Whether the guard of an entry holds now (internal transitions: no time sets).
[[gnu::always_inline]] inline bool guard_holds(const TransitionEntry& entry,
                                               const bipc::ir::Transition& transition,
                                               const Frame& f, ModelCode& eval) {
  if (entry.leading) {
    if (!leading_holds(*entry.leading, f.atom_data, f.atom_params)) return false;
    if (entry.leading->whole) return true;
  }
  return eval.holds(transition.guard, f);
}

/// ModelCode::atom_offers by interpretation: the labelled transitions from the one marked place
/// of a state machine, else all, in declaration order.
bipc::ir::Index interpreted_offers(const bipc::ir::System& system, const Layout& layout,
                                   bipc::ir::Index type, const std::uint8_t* marking,
                                   const Frame& f, ModelCode& eval,
                                   std::optional<AtomPortValue>* offers);

/// ModelCode::atom_internal by interpretation.
bipc::ir::Index interpreted_internal(const bipc::ir::System& system, const Layout& layout,
                                     bipc::ir::Index type, const std::uint8_t* marking,
                                     const Frame& f, ModelCode& eval);

/// ModelCode::atom_fire by interpretation: the tokens move, then the action runs; false,
/// before the action, when a token would land on a marked place.
bool interpreted_fire(const bipc::ir::Transition& transition, std::uint8_t* marking, const Frame& f,
                      ModelCode& eval);

}  // namespace smcbip::engines
