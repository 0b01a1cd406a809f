// An atom's steps by interpretation of its transitions, stated once: the Runtime takes them for
// the atom types its model's code does not compile, and the flat step path over an interpreted
// model (interpreted_steps.h) for every type, with the leading comparisons of guards
// (data_guard.h) tested from the atom's slots. They answer as ModelCode's atom_offers,
// atom_internal and atom_fire do (model.h), over the atom's own marking. Inline: they are the
// engines' innermost loop, run for every atom a step touches.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"
#include "bipc/ir/simple_action.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
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

/// Whether the leading comparisons of a guard hold on an atom's data and parameters, from test
/// `first` on.
[[gnu::always_inline]] inline bool leading_holds(const LeadingTests& c, const Val* atom_data,
                                                 const Val* atom_params, std::size_t first = 0) {
  const Val* const base[] = {atom_data, atom_params, c.literals.data()};
  for (std::size_t k = first; k < c.count; ++k) {
    const LeadingTests::Test& test = c.tests[k];
    const std::int64_t a = base[test.left_base][test.left].i;
    const std::int64_t b = base[test.right_base][test.right].i;
    // 0, 1 or 2 as a is less than, equal to or greater than b.
    const unsigned order = static_cast<unsigned>((a > b) - (a < b) + 1);
    if (((test.holds_when >> order) & 1u) == 0) return false;
  }
  return true;
}

/// Whether the leading comparisons of an entry's guard hold (true when it has none).
[[gnu::always_inline]] inline bool entry_leading_holds(const Layout& layout,
                                                       const TransitionEntry& entry,
                                                       const Frame& f) {
  return entry.leading == bipc::ir::kNone ||
         leading_holds(layout.leading_tests[entry.leading], f.atom_data, f.atom_params,
                       entry.first_test);
}

/// Offers the transition of `entry` when it is enabled; its port when that port already has an
/// offer (a non-deterministic choice), else kNone.
[[gnu::always_inline]] inline bipc::ir::Index offer(const Layout& layout,
                                                    const bipc::ir::AtomType& type,
                                                    const TransitionEntry& entry,
                                                    const std::uint8_t* marking, const Frame& f,
                                                    ModelCode& eval,
                                                    std::optional<AtomPortValue>* offers) {
  const bipc::ir::Transition& tr = type.transitions[entry.transition];
  if (!from_marked(entry, tr, marking) || !entry_leading_holds(layout, entry, f))
    return bipc::ir::kNone;
  // Built in place (no copy of a returned Interval, which stalled on store forwarding).
  const Interval when = [&] {
    if (tr.guard.empty() || entry.leading_whole) return Interval::all();
    return eval.holds_when(tr.guard, f);
  }();
  if (when.empty()) return bipc::ir::kNone;
  if (offers[tr.port]) return tr.port;
  offers[tr.port] = AtomPortValue{entry.transition, {when, tr.urgency}};
  return bipc::ir::kNone;
}

/// ModelCode::atom_offers by interpretation: the labelled transitions from the one marked place
/// of a state machine (of those led by `d == literal` on one datum, only the ones whose literal
/// is d's value), else all, in declaration order.
[[gnu::always_inline]] inline bipc::ir::Index interpreted_offers(
    const bipc::ir::System& system, const Layout& layout, bipc::ir::Index type,
    const std::uint8_t* marking, const Frame& f, ModelCode& eval,
    std::optional<AtomPortValue>* offers) {
  const bipc::ir::AtomType& atom_type = system.atom_types[type];
  const std::vector<std::vector<TransitionEntry>>& from_place = layout.labelled_from_place[type];
  const std::vector<TransitionEntry>* entries = &layout.labelled_transitions[type];
  if (!from_place.empty()) {
    std::size_t marked = 0;
    while (marked + 1 < from_place.size() && !marking[marked]) ++marked;
    entries = &from_place[marked];
    if (const std::optional<ValueDispatch>& dispatch = layout.dispatch_from_place[type][marked]) {
      for (std::uint32_t i : dispatch->entries_for(f.atom_data[dispatch->slot].i)) {
        const bipc::ir::Index port =
            offer(layout, atom_type, (*entries)[i], marking, f, eval, offers);
        if (port != bipc::ir::kNone) return port;
      }
      return bipc::ir::kNone;
    }
  }
  for (const TransitionEntry& entry : *entries) {
    const bipc::ir::Index port = offer(layout, atom_type, entry, marking, f, eval, offers);
    if (port != bipc::ir::kNone) return port;
  }
  return bipc::ir::kNone;
}

/// ModelCode::atom_internal by interpretation.
bipc::ir::Index interpreted_internal(const bipc::ir::System& system, const Layout& layout,
                                     bipc::ir::Index type, const std::uint8_t* marking,
                                     const Frame& f, ModelCode& eval);

/// The tokens of a firing move; false when one would land on a marked place.
[[gnu::always_inline]] inline bool move_tokens(const bipc::ir::Transition& transition,
                                               std::uint8_t* marking) {
  for (bipc::ir::Index p : transition.from) marking[p] = 0;
  for (bipc::ir::Index p : transition.to) {
    if (marking[p]) return false;
    marking[p] = 1;
  }
  return true;
}

/// Runs a simple action (simple_action.h) on the frame's slots: the stores the interpreter
/// would make, in its order, of the same values.
[[gnu::always_inline]] inline void run_simple_action(const bipc::ir::SimpleAssignment* first,
                                                     const bipc::ir::SimpleAssignment* end,
                                                     const Frame& f) {
  using Kind = bipc::ir::SimpleAssignment::Kind;
  for (const bipc::ir::SimpleAssignment* a = first; a != end; ++a) {
    switch (a->kind) {
      case Kind::Int:
        f.atom_data[a->target] = make_int(a->literal);
        break;
      case Kind::Float:
        f.atom_data[a->target] = make_float(a->real);
        break;
      case Kind::AddInt:
        f.atom_data[a->target] = make_int(
            static_cast<std::int64_t>(static_cast<std::uint64_t>(f.atom_data[a->source].i) +
                                      static_cast<std::uint64_t>(a->literal)));
        break;
      case Kind::ClockSet:
        f.clocks[a->target].value_at = a->real;
        f.clocks[a->target].since = f.now;
        break;
    }
  }
}

/// ModelCode::atom_fire by interpretation: the tokens move, then the action runs; false,
/// before the action, when a token would land on a marked place.
[[gnu::always_inline]] inline bool interpreted_fire(const bipc::ir::Transition& transition,
                                                    std::uint8_t* marking, const Frame& f,
                                                    ModelCode& eval) {
  if (!move_tokens(transition, marking)) return false;
  eval.execute(transition.action, f);
  return true;
}

}  // namespace smcbip::engines
