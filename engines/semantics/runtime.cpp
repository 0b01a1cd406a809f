// The BIP semantics of one run: atom offers, timing constraints and execution. Connector
// interactions: connector_values.cpp; priorities: compound_priorities.cpp and
// atom_priorities.cpp; items: item_listing.cpp; extern ports: extern_ports.cpp; traces:
// runtime_trace.cpp. Follows the Verimag reference engine.
#include "engines/semantics/runtime.h"

#include <algorithm>

#include "bipc/ir/clock_guard.h"
#include "engines/api/simulate.h"
#include "engines/semantics/atom_steps.h"
#include "engines/semantics/detail/runtime_shared.h"
#include "engines/semantics/parallel_firing.h"

namespace smcbip::engines {

using bipc::Urgency;
using bipc::ir::AtomType;
using bipc::ir::kNone;
using detail::connector_frame;
using detail::narrow;
using detail::PortContext;
using detail::wait;

Runtime::Runtime(const Model& model, const Layout& layout, const BoundFunctions& functions,
                 StringPool& strings, std::ostream& out, RandomStream& random,
                 const RuntimeOptions& options)
    : system_(model.system()),
      layout_(layout),
      functions_(functions),
      strings_(strings),
      call_{out, strings, &random, {}},
      code_(model.make_code(functions, call_)),
      eval_(*code_),
      options_(options),
      cache_(system_, layout),
      connectors_(system_, layout, options, eval_, state_, port_values_, port_offset_, cache_,
                  listing_, priorities_),
      extern_ports_(system_, layout, functions, state_, port_values_, port_offset_, error_),
      listing_(system_, layout, state_, connectors_.values(), connectors_.connector_values(),
               port_values_, port_offset_, extern_ports_, options.incremental),
      priorities_(system_, layout, options.maximal_progress, eval_, state_, error_, connectors_,
                  cache_, time_bound_) {
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    port_offset_.push_back(port_values_.size());
    port_values_.resize(port_values_.size() +
                        system_.atom_types[system_.atoms[a].type].ports.size());
  }
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    const bool has_clocks = !system_.atom_types[system_.atoms[a].type].clocks.empty();
    atom_slots_.push_back({layout.atom_data[a], layout.params.data() + layout.atom_params[a],
                           layout.atom_clocks[a], layout.clock_units.data() + layout.atom_clocks[a],
                           has_clocks});
  }
  for (Index t = 0; t < system_.atom_types.size(); ++t) {
    compiled_type_.push_back(eval_.compiles_atom_type(t) ? 1 : 0);
  }
  atom_invariant_.assign(system_.atoms.size(), Interval::all());
  bounding_atoms_.reset(system_.atoms.size());
  resuming_atoms_.reset(system_.atoms.size());
  connectors_.index();
  if (options.threads > 1) {
    parallel_ = std::make_unique<ParallelFiring>(model, functions, call_, options.threads);
  }
}

void Runtime::note_atom_changed(Index atom) {
  cache_.touch_atom(atom);
  note_time_bound(atom);
}

void Runtime::note_time_bound(Index atom) {
  const bool pending = state_.resume_pending[atom] != 0;
  resuming_atoms_.assign(atom, pending);
  bounding_atoms_.assign(atom, pending || !(atom_invariant_[atom] == Interval::all()));
}

bool Runtime::fail(int code, std::string message) {
  error_ = {code, std::move(message), {}};
  return false;
}

bool Runtime::fail(const CodeFault& fault) {
  error_ = fault_error(fault);
  return false;
}

ModelError Runtime::fault_error(const CodeFault& fault) const {
  const bool known = fault.site < system_.sites.size();
  return {kInputError, fault.message, known ? where(system_.sites[fault.site]) : std::string()};
}

std::string Runtime::where(const bipc::Location& at) const {
  if (at.line == 0 || at.file >= system_.source_files.size()) return {};
  return bipc::position_text(system_.source_files[at.file], at.line, at.column);
}

Frame Runtime::atom_frame(const AtomScratch& s, Index atom) {
  Frame f = atom_frame(atom);
  if (s.atom_data != nullptr) f.atom_data = s.atom_data;
  return f;
}

Frame Runtime::atom_frame(Index atom) {
  const AtomSlots& slots = atom_slots_[atom];
  Frame f;
  f.atom_data = state_.data.data() + slots.data;
  f.atom_params = slots.params;
  f.clocks = slots.has_clocks ? state_.clocks.data() + slots.clocks : nullptr;
  f.clock_units = slots.clock_units;
  f.instance_slot = &RuntimeDetail::instance_slot;
  f.instance_context = this;
  f.now = state_.now;
  return f;
}

bool Runtime::initialize() {
  cache_.invalidate_all();
  // Assigned in place: a run started again reuses the buffers.
  state_.now = 0;
  state_.data.assign(layout_.data_size, make_int(0));
  state_.marking.assign(layout_.place_count, 0);
  state_.clocks.assign(layout_.clock_count, ClockState{});
  state_.resume_pending.assign(system_.atoms.size(), 0);
  state_.resume_interval.assign(system_.atoms.size(), Interval::all());
  for (std::optional<AtomPortValue>& offer : port_values_) offer.reset();
  if (!extern_ports_.open()) return false;
  for (Index a = 0; a < system_.atoms.size(); ++a) note_time_bound(a);
  try {
    for (Index a = 0; a < system_.atoms.size(); ++a) {
      const AtomType& type = system_.atom_types[system_.atoms[a].type];
      const Frame f = atom_frame(a);
      for (std::size_t d = 0; d < type.data.size(); ++d) {
        if (!type.data[d].initial_value.empty()) {
          f.atom_data[d] = eval_.evaluate(type.data[d].initial_value, f);
        }
      }
    }
    for (Index k = 0; k < system_.connectors.size(); ++k) {
      const auto& type = system_.connector_types[system_.connectors[k].type];
      Frame f;
      f.connector_data = state_.data.data() + layout_.connector_data[k];
      for (std::size_t d = 0; d < type.data.size(); ++d) {
        if (!type.data[d].initial_value.empty()) {
          f.connector_data[d] = eval_.evaluate(type.data[d].initial_value, f);
        }
      }
    }
    for (Index a : layout_.initial_order) {
      const AtomType& type = system_.atom_types[system_.atoms[a].type];
      for (Index p : type.initial_places) state_.marking[layout_.atom_places[a] + p] = 1;
      eval_.execute(type.initial_action, atom_frame(a));
      if (type.initial_resume) {
        state_.resume_pending[a] = 1;
        state_.resume_interval[a] = eval_.holds_when(type.initial_resume->guard, atom_frame(a));
        note_time_bound(a);
      }
      if (!check_invariants(a) || !run_internal_transitions(a)) return false;
      if (!state_.resume_pending[a] && !update_atom(a)) return false;
    }
  } catch (const CodeFault& fault) {
    return fail(fault);
  }
  return priorities_.check_cycles();
}

bool Runtime::check_invariants(const AtomScratch& s, Index atom) {
  const AtomType& type = system_.atom_types[system_.atoms[atom].type];
  const std::size_t base = layout_.atom_places[atom];
  atom_invariant_[atom] = Interval::all();
  if (!s.on_worker) note_time_bound(atom);
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
    const Frame f = atom_frame(s, atom);
    bool holds = true;
    if (bipc::ir::reads_clock(inv.guard)) {
      const Interval when = s.eval.holds_when(inv.guard, f);
      atom_invariant_[atom] = atom_invariant_[atom].intersect(when);
      if (!s.on_worker) note_time_bound(atom);
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

bool Runtime::fire_transition(const AtomScratch& s, Index atom, Index transition, Index label,
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
                  where(t.loc));
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
    if (!s.on_worker) note_time_bound(atom);
  }
  // An atom without invariants keeps `all` (its time bound is noted where its resume changes).
  return type.invariants.empty() || check_invariants(s, atom);
}

bool Runtime::run_internal_transitions(const AtomScratch& s, Index atom) {
  if (layout_.internal_transitions[system_.atoms[atom].type].empty()) return true;
  const Frame f = atom_frame(s, atom);
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

Index Runtime::enabled_internal_transition(const AtomScratch& s, Index atom, const Frame& f) {
  const Index type_index = system_.atoms[atom].type;
  const std::uint8_t* marking = &state_.marking[layout_.atom_places[atom]];
  if (compiled_type_[type_index]) return s.eval.atom_internal(type_index, marking, f);
  return interpreted_internal(system_, layout_, type_index, marking, f, s.eval);
}

bool Runtime::update_atom(const AtomScratch& s, Index atom, const Frame& f) {
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
  return type.priorities.empty() || apply_atom_priorities(s, atom, f);
}

bool Runtime::non_deterministic_offers(const AtomScratch& s, Index atom, Index port) {
  const bipc::ir::Port& p = system_.atom_types[system_.atoms[atom].type].ports[port];
  if (p.is_extern) {
    return s.fail(1, "non-deterministic choice between internal transitions in " +
                         layout_.atom_names[atom] + "!");
  }
  return s.fail(1, "non-deterministic choice between transitions labelled by " + p.name + " in " +
                       layout_.atom_names[atom] + "!");
}

bool Runtime::apply_atom_priorities(const AtomScratch& s, Index atom, const Frame& f) {
  const AtomType& type = system_.atom_types[system_.atoms[atom].type];
  if (s.priorities->apply(type, s.eval, f, port_values_.data() + port_offset_[atom])) return true;
  return s.fail(4, "cycle in priorities! ()");
}

bool Runtime::compute_items() {
  listing_.begin();
  time_bound_ = time_bound();
  if (!priorities_.check_cycles()) return false;
  const bool full = !options_.incremental || cache_.all_stale();
  listing_.note_internal_ports(full, cache_);
  connectors_.begin(full);
  try {
    connectors_.compute(full);
  } catch (const CodeFault& fault) {
    cache_.invalidate_all();
    return fail(fault);
  } catch (const UnsupportedRun& unsupported) {
    cache_.invalidate_all();
    return fail(kInputError, unsupported.message);
  }
  cache_.end();
  extern_ports_.refresh();
  listing_.end(wait_interval());
  return true;
}

Interval Runtime::wait_interval() const {
  // A lazy constraint lets time pass (its wait is `from now`, which leaves w as it is): only
  // the urgent connectors and internal ports are visited. Intersections: order-free.
  Interval w = Interval::from(state_.now);
  for (Index k : cache_.urgent()) {
    if (listing_.listed_position(k) == kNone) continue;
    for (Index v : connectors_.connector_values()[k]) {
      const InteractionValue& value = connectors_.values()[v];
      if (value.raw.urgency == Urgency::Lazy || value.after.interval.empty()) continue;
      narrow(w, wait(value.raw, state_.now));
    }
  }
  for (Index i : listing_.urgent_internal_ports()) {
    const auto& [atom, port] = layout_.internal_ports[i];
    narrow(w, wait(port_values_[port_offset_[atom] + port]->constraint, state_.now));
  }
  for (const ExternPortState& e : extern_ports_.ports()) {
    if (e.expected) narrow(w, wait(*e.expected, state_.now));
  }
  return w.intersect(time_bound());
}

Interval Runtime::time_bound() const {
  Interval w = Interval::all();
  for (Index a : bounding_atoms_) {
    narrow(w, state_.resume_pending[a] ? state_.resume_interval[a] : atom_invariant_[a]);
  }
  return w;
}

// ---------------------------------------------------------------------------------------------
// Execution.

void Runtime::run_down(Index index) {
  InteractionValue& value = connectors_.values()[index];
  const auto& type = system_.connector_types[system_.connectors[value.connector].type];
  const int code = value.code;
  if (code >= 0) {
    const PortContext context{&connectors_, &value};
    eval_.execute(type.interactions[static_cast<std::size_t>(code)].down,
                  connector_frame(value, context, state_.now));
  }
  std::copy(
      value.data.begin(), value.data.end(),
      state_.data.begin() + static_cast<std::ptrdiff_t>(layout_.connector_data[value.connector]));
}

bool Runtime::execute_value(Index index) {
  run_down(index);
  // Ports run in the interaction's port order, depth first: a sub-connector's down comes after
  // the atoms of earlier ports have executed (reference engine order).
  for (const PortValue& pv : connectors_.values()[index].choice) {
    if (pv.from_atom ? !fire_port(pv.atom, pv.port) : !execute_value(pv.sub)) return false;
  }
  return true;
}

bool Runtime::fire_port(const AtomScratch& s, Index atom, Index port) {
  const auto& v = port_values_[port_offset_[atom] + port];
  if (!v) return true;
  // One frame serves the whole firing: the date and the state's buffers stay put.
  const Frame f = atom_frame(s, atom);
  if (!fire_transition(s, atom, v->transition, port, f) || !run_internal_transitions(s, atom)) {
    return false;
  }
  return state_.resume_pending[atom] || update_atom(s, atom, f);
}

void Runtime::append_atom_ports(const Item& item, std::vector<std::pair<Index, Index>>& out) const {
  if (item.kind != Item::Kind::Interaction) {
    out.emplace_back(item.atom, item.port);
    return;
  }
  append_value_ports(item.value, out);
}

void Runtime::append_value_ports(Index value, std::vector<std::pair<Index, Index>>& out) const {
  for (const PortValue& pv : connectors_.values()[value].choice) {
    if (pv.from_atom) {
      out.emplace_back(pv.atom, pv.port);
    } else {
      append_value_ports(pv.sub, out);
    }
  }
}

bool Runtime::restore(const RunState& state) {
  cache_.invalidate_all();
  state_ = state;
  for (Index a = 0; a < system_.atoms.size(); ++a) note_time_bound(a);
  try {
    // The invariants' time bounds are those of the restored marking, not of the last state.
    for (Index a = 0; a < system_.atoms.size(); ++a) {
      if (!check_invariants(a)) return false;
    }
    for (Index a = 0; a < system_.atoms.size(); ++a) {
      if (!state_.resume_pending[a] && !update_atom(a)) return false;
    }
  } catch (const CodeFault& fault) {
    return fail(fault);
  }
  return true;
}

bool Runtime::execute(const Item& item, TimeValue at) {
  state_.now = at;
  try {
    if (item.kind == Item::Kind::Interaction) {
      return parallel_ ? execute_value_in_parallel(item.value) : execute_value(item.value);
    }
    if (item.kind == Item::Kind::External) return fire_extern(item);
    return fire_port(item.atom, item.port);
  } catch (const CodeFault& fault) {
    return fail(fault);
  }
}

bool Runtime::fire_extern(const Item& item) {
  return !extern_ports_.take_event(item.atom, item.port) || fire_port(item.atom, item.port);
}

bool Runtime::receive_unexpected_events(TimeValue upto) {
  return extern_ports_.receive_unexpected(upto);
}

void Runtime::wake_extern_port(Index atom, Index port) { extern_ports_.wake(atom, port); }

bool Runtime::write_data(Index atom, Index slot, Val value) {
  state_.data[layout_.atom_data[atom] + slot] = value;
  cache_.touch_atom(atom);  // also when resuming: its connectors' code may read the data
  try {
    if (!check_invariants(atom) || !run_internal_transitions(atom)) return false;
    return state_.resume_pending[atom] || update_atom(atom);
  } catch (const CodeFault& fault) {
    return fail(fault);
  }
}

/// Resumes atoms whose resume window holds `now`; returns false when one is already past.
bool Runtime::resume_atoms(TimeValue now) {
  if (!resuming_atoms_.empty()) {
    // In atom order, as the reference engine resumes them.
    std::vector<Index>& atoms = resume_order_;
    atoms.assign(resuming_atoms_.begin(), resuming_atoms_.end());
    std::sort(atoms.begin(), atoms.end());
    for (Index a : atoms) {
      state_.resume_pending[a] = 0;
      note_time_bound(a);
      if (!update_atom(a)) return false;
    }
  }
  state_.now = std::max(state_.now, now);
  return true;
}

Interval Runtime::resume_window() const {
  Interval w = Interval::all();
  for (Index a : resuming_atoms_) w = w.intersect(state_.resume_interval[a]);
  return w;
}

}  // namespace smcbip::engines
