// The atoms of one run: offers, internal transitions, firing and invariants. Follows the
// Verimag reference engine's atom side.
#include "engines/semantics/atom_firing.h"

#include "bipc/ir/clock_guard.h"
#include "engines/semantics/atom_steps.h"

namespace smcbip::engines {

using bipc::ir::AtomType;
using bipc::ir::kNone;

AtomFiring::AtomFiring(const bipc::ir::System& system, const Layout& layout, ModelCode& eval,
                       RunState& state, ModelError& error, ConnectorCache& cache)
    : system_(system),
      layout_(layout),
      eval_(eval),
      state_(state),
      cache_(cache),
      main_scratch_{eval, error, nullptr, false, &priorities_},
      time_bounds_(state, system.atoms.size()) {
  for (Index a = 0; a < system.atoms.size(); ++a) {
    port_offset_.push_back(port_values_.size());
    port_values_.resize(port_values_.size() + system.atom_types[system.atoms[a].type].ports.size());
  }
  for (Index a = 0; a < system.atoms.size(); ++a) {
    const bool has_clocks = !system.atom_types[system.atoms[a].type].clocks.empty();
    slots_.push_back({layout.atom_data[a], layout.params.data() + layout.atom_params[a],
                      layout.atom_clocks[a], layout.clock_units.data() + layout.atom_clocks[a],
                      has_clocks});
  }
  for (Index t = 0; t < system.atom_types.size(); ++t) {
    compiled_type_.push_back(eval.compiles_atom_type(t) ? 1 : 0);
  }
}

Val* AtomFiring::instance_slot(const void* context, Index atom, std::uint16_t slot) {
  const AtomFiring& atoms = *static_cast<const AtomFiring*>(context);
  return &atoms.state_.data[atoms.layout_.atom_data[atom] + slot];
}

Frame AtomFiring::frame(const AtomScratch& s, Index atom) {
  Frame f = frame(atom);
  if (s.atom_data != nullptr) f.atom_data = s.atom_data;
  return f;
}

Frame AtomFiring::frame(Index atom) {
  const AtomSlots& slots = slots_[atom];
  Frame f;
  f.atom_data = state_.data.data() + slots.data;
  f.atom_params = slots.params;
  f.clocks = slots.has_clocks ? state_.clocks.data() + slots.clocks : nullptr;
  f.clock_units = slots.clock_units;
  f.instance_slot = &AtomFiring::instance_slot;
  f.instance_context = this;
  f.now = state_.now;
  return f;
}

void AtomFiring::initialize_data() {
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    const AtomType& type = system_.atom_types[system_.atoms[a].type];
    const Frame f = frame(a);
    for (std::size_t d = 0; d < type.data.size(); ++d) {
      if (!type.data[d].initial_value.empty()) {
        f.atom_data[d] = eval_.evaluate(type.data[d].initial_value, f);
      }
    }
  }
}

bool AtomFiring::start(Index atom) {
  const AtomType& type = system_.atom_types[system_.atoms[atom].type];
  for (Index p : type.initial_places) state_.marking[layout_.atom_places[atom] + p] = 1;
  eval_.execute(type.initial_action, frame(atom));
  if (type.initial_resume) {
    state_.resume_pending[atom] = 1;
    state_.resume_interval[atom] = eval_.holds_when(type.initial_resume->guard, frame(atom));
    time_bounds_.note(atom);
  }
  return settle(atom);
}

bool AtomFiring::settle(Index atom) {
  if (!check_invariants(atom) || !run_internal_transitions(main_scratch_, atom)) return false;
  return state_.resume_pending[atom] || update(atom);
}

bool AtomFiring::check_invariants(const AtomScratch& s, Index atom) {
  const AtomType& type = system_.atom_types[system_.atoms[atom].type];
  const std::size_t base = layout_.atom_places[atom];
  Interval& invariant = time_bounds_.invariant(atom);
  invariant = Interval::all();
  if (!s.on_worker) time_bounds_.note(atom);
  for (const bipc::ir::Invariant& inv : type.invariants) {
    bool applies = true;
    if (!inv.places.empty()) {
      std::size_t marked = 0;
      for (Index p : inv.places) marked += state_.marking[base + p];
      applies = marked == inv.places.size();
      if (applies && inv.at) {
        std::size_t total = 0;
        for (std::size_t p = 0; p < type.places.size(); ++p) total += state_.marking[base + p];
        applies = total == inv.places.size();
      }
    }
    if (!applies) continue;
    const Frame f = frame(s, atom);
    bool holds = true;
    if (bipc::ir::reads_clock(inv.guard)) {
      const Interval when = s.eval.holds_when(inv.guard, f);
      invariant = invariant.intersect(when);
      if (!s.on_worker) time_bounds_.note(atom);
      holds = when.contains(state_.now);
    } else {
      holds = s.eval.holds(inv.guard, f);
    }
    if (!holds) {
      return s.fail(5, "the invariant " + inv.name + " of component " +
                           bipc::ir::last_component(system_.atoms[atom].path) +
                           " has been violated!");
    }
  }
  return true;
}

bool AtomFiring::fire_transition(const AtomScratch& s, Index atom, Index transition, Index label,
                                 const Frame& f) {
  const AtomType& type = system_.atom_types[system_.atoms[atom].type];
  const bipc::ir::Transition& t = type.transitions[transition];
  const std::size_t base = layout_.atom_places[atom];
  if (!s.on_worker) cache_.touch_atom(atom);  // parallel firing notes atoms after the join
  const auto not_safe = [&] {
    const bool labelled = label != kNone && !type.ports[label].is_extern;
    return s.fail(2,
                  "the Peri net of " + layout_.atom_names[atom] + " is not 1-safe! (when " +
                      (labelled ? "executing a transition labelled by " + type.ports[label].name
                                : std::string("executing an internal transition")) +
                      ")",
                  source_position(system_, t.loc));
  };
  const Index type_index = system_.atoms[atom].type;
  std::uint8_t* marking = &state_.marking[base];
  if (compiled_type_[type_index] ? !s.eval.atom_fire(type_index, transition, marking, f)
                                 : !interpreted_fire(t, marking, f, s.eval)) {
    return not_safe();
  }
  if (t.resume) {
    state_.resume_pending[atom] = 1;
    state_.resume_interval[atom] = s.eval.holds_when(t.resume->guard, f);
    if (!s.on_worker) time_bounds_.note(atom);
  }
  // An atom without invariants keeps `all` (its time bound is noted where its resume changes).
  return type.invariants.empty() || check_invariants(s, atom);
}

bool AtomFiring::run_internal_transitions(const AtomScratch& s, Index atom) {
  if (layout_.internal_transitions[system_.atoms[atom].type].empty()) return true;
  const Frame f = frame(s, atom);
  for (;;) {
    const Index enabled = enabled_internal_transition(s, atom, f);
    if (enabled == ModelCode::kSeveralTransitions) {
      return s.fail(1, "non-deterministic choice between internal transitions in " +
                           layout_.atom_names[atom] + "!");
    }
    if (enabled == kNone) return true;
    if (!fire_transition(s, atom, enabled, kNone, f)) return false;
  }
}

Index AtomFiring::enabled_internal_transition(const AtomScratch& s, Index atom, const Frame& f) {
  const Index type_index = system_.atoms[atom].type;
  const std::uint8_t* marking = &state_.marking[layout_.atom_places[atom]];
  if (compiled_type_[type_index]) return s.eval.atom_internal(type_index, marking, f);
  return interpreted_internal(system_, layout_, type_index, marking, f, s.eval);
}

bool AtomFiring::update(const AtomScratch& s, Index atom, const Frame& f) {
  const AtomType& type = system_.atom_types[system_.atoms[atom].type];
  const std::size_t base = layout_.atom_places[atom];
  std::optional<AtomPortValue>* values = port_values_.data() + port_offset_[atom];
  if (!s.on_worker) cache_.touch_atom(atom);  // parallel firing notes atoms after the join
  for (std::size_t p = 0; p < type.ports.size(); ++p) values[p].reset();
  const Index type_index = system_.atoms[atom].type;
  const std::uint8_t* marking = &state_.marking[base];
  const Index port = compiled_type_[type_index] ? s.eval.atom_offers(type_index, marking, f, values)
                                                : interpreted_offers(system_, layout_, type_index,
                                                                     marking, f, s.eval, values);
  if (port != kNone) return non_deterministic_offers(s, atom, port);
  return type.priorities.empty() || apply_priorities(s, atom, f);
}

bool AtomFiring::non_deterministic_offers(const AtomScratch& s, Index atom, Index port) {
  const bipc::ir::Port& p = system_.atom_types[system_.atoms[atom].type].ports[port];
  if (p.is_extern) {
    return s.fail(1, "non-deterministic choice between internal transitions in " +
                         layout_.atom_names[atom] + "!");
  }
  return s.fail(1, "non-deterministic choice between transitions labelled by " + p.name + " in " +
                       layout_.atom_names[atom] + "!");
}

bool AtomFiring::apply_priorities(const AtomScratch& s, Index atom, const Frame& f) {
  const AtomType& type = system_.atom_types[system_.atoms[atom].type];
  if (s.priorities->apply(type, s.eval, f, port_values_.data() + port_offset_[atom])) return true;
  return s.fail(4, "cycle in priorities! ()");
}

bool AtomFiring::fire_port(const AtomScratch& s, Index atom, Index port) {
  const auto& v = port_values_[port_offset_[atom] + port];
  if (!v) return true;
  // One frame serves the whole firing: the date and the state's buffers stay put.
  const Frame f = frame(s, atom);
  if (!fire_transition(s, atom, v->transition, port, f) || !run_internal_transitions(s, atom)) {
    return false;
  }
  return state_.resume_pending[atom] || update(s, atom, f);
}

bool AtomFiring::resume() {
  for (Index a : time_bounds_.resuming_in_order()) {
    state_.resume_pending[a] = 0;
    time_bounds_.note(a);
    if (!update(a)) return false;
  }
  return true;
}

}  // namespace smcbip::engines
