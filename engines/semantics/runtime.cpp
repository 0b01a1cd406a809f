// The BIP semantics of one run: atom offers, timing constraints, the items of a state, and
// execution (connector interactions: runtime_connectors.cpp; priorities: runtime_priorities.cpp).
// Follows the Verimag reference engine.
#include "engines/semantics/runtime.h"

#include <algorithm>
#include <sstream>

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
      maximal_progress_(options.maximal_progress),
      cache_(system_, layout) {
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    port_offset_.push_back(port_values_.size());
    for (const bipc::ir::Port& port : system_.atom_types[system_.atoms[a].type].ports) {
      port_values_.emplace_back();
      port_data_begin_.push_back(port_data_slots_.size());
      for (Index slot : port.data) port_data_slots_.push_back(layout.atom_data[a] + slot);
    }
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
  index_listing();
  index_single_atom_ports();
  index_required_offers();
  index_direct_connectors();
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
  if (!open_extern_ports()) return false;
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
  return check_compound_priority_cycles();
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
  std::optional<AtomPortValue>* values = port_values_.data() + port_offset_[atom];
  if (!check_atom_priority_cycle(s, atom)) return false;
  // A port is disabled when a chain of active rules from it ends at an enabled port.
  AtomPriorityBuffers& b = *s.priorities;
  const std::size_t n = type.ports.size();
  const std::size_t rules = type.priorities.size();
  b.active.assign(rules, 0);
  for (std::size_t r = 0; r < rules; ++r) b.active[r] = s.eval.holds(type.priorities[r].guard, f);
  auto in_low = [&](std::size_t r, std::size_t p) {
    const auto& rule = type.priorities[r];
    return rule.low == kNone ? rule.high != p : rule.low == p;
  };
  auto in_high = [&](std::size_t r, std::size_t p) {
    const auto& rule = type.priorities[r];
    return rule.high == kNone ? rule.low != p : rule.high == p;
  };
  auto high_enabled = [&](std::size_t r) {
    for (std::size_t q = 0; q < n; ++q) {
      if (in_high(r, q) && values[q] && !type.ports[q].is_extern) return true;
    }
    return false;
  };
  b.disabled.assign(n, 0);
  for (std::size_t p = 0; p < n; ++p) {
    if (!values[p] || type.ports[p].is_extern) continue;
    b.seen.assign(rules, 0);
    b.chain_ends.clear();
    for (std::size_t r = 0; r < rules; ++r) {
      if (b.active[r] && in_low(r, p)) {
        b.seen[r] = 1;
        b.chain_ends.push_back(r);
      }
    }
    while (!b.chain_ends.empty() && !b.disabled[p]) {
      const std::size_t r = b.chain_ends.back();
      b.chain_ends.pop_back();
      if (high_enabled(r)) {
        b.disabled[p] = 1;
        break;
      }
      for (std::size_t r2 = 0; r2 < rules; ++r2) {
        if (b.seen[r2] || !b.active[r2]) continue;
        bool chained = false;
        for (std::size_t q = 0; q < n && !chained; ++q) chained = in_high(r, q) && in_low(r2, q);
        if (chained) {
          b.seen[r2] = 1;
          b.chain_ends.push_back(r2);
        }
      }
    }
  }
  for (std::size_t p = 0; p < n; ++p) {
    if (b.disabled[p]) values[p].reset();
  }
  return true;
}

bool Runtime::check_atom_priority_cycle(const AtomScratch& s, Index atom) {
  const AtomType& type = system_.atom_types[system_.atoms[atom].type];
  const std::size_t rules = type.priorities.size();
  const std::size_t n = type.ports.size();
  const Frame f = atom_frame(s, atom);
  AtomPriorityBuffers& b = *s.priorities;
  b.active.assign(rules, 0);
  for (std::size_t r = 0; r < rules; ++r) b.active[r] = s.eval.holds(type.priorities[r].guard, f);
  auto chained = [&](std::size_t r, std::size_t r2) {
    const auto& x = type.priorities[r];
    const auto& y = type.priorities[r2];
    for (std::size_t q = 0; q < n; ++q) {
      const bool high = x.high == kNone ? x.low != q : x.high == q;
      const bool low = y.low == kNone ? y.high != q : y.low == q;
      if (high && low) return true;
    }
    return false;
  };
  // Depth-first search for a cycle among active rules (colours: 0 new, 1 on path, 2 done), on
  // an explicit path of (rule, next rule to try).
  b.colour.assign(rules, 0);
  for (std::size_t root = 0; root < rules; ++root) {
    if (!b.active[root] || b.colour[root] != 0) continue;
    b.colour[root] = 1;
    b.path.assign(1, {root, 0});
    while (!b.path.empty()) {
      const std::size_t r = b.path.back().first;
      std::size_t& next = b.path.back().second;
      while (next < rules && (!b.active[next] || !chained(r, next))) ++next;
      if (next == rules) {
        b.colour[r] = 2;
        b.path.pop_back();
        continue;
      }
      const std::size_t r2 = next++;
      if (b.colour[r2] == 1) return s.fail(4, "cycle in priorities! ()");
      if (b.colour[r2] == 0) {
        b.colour[r2] = 1;
        b.path.emplace_back(r2, 0);
      }
    }
  }
  return true;
}

bool Runtime::compute_items() {
  items_.clear();
  items_listed_ = true;
  time_bound_ = time_bound();
  if (!check_compound_priority_cycles()) return false;
  const bool full = !options_.incremental || cache_.all_stale();
  note_internal_ports(full);
  begin_values(full);
  try {
    compute_values(full);
  } catch (const CodeFault& fault) {
    cache_.invalidate_all();
    return fail(fault);
  } catch (const UnsupportedRun& unsupported) {
    cache_.invalidate_all();
    return fail(kInputError, unsupported.message);
  }
  cache_.end();
  refresh_extern_events();
  items_window_ = wait_interval();
  items_listed_ = false;
  if (!counts_items_) list_items();
  return true;
}

bool Runtime::cut_item(const Constraint& c, Item& item) const {
  Interval in = c.interval;
  narrow(in, items_window_);
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

void Runtime::list_items() const {
  // Items with their windows cut to the admissible waiting interval.
  items_.clear();
  items_listed_ = true;
  auto add = [&](const Constraint& c) -> Item* {
    Item& item = items_.emplace_back();
    if (cut_item(c, item)) return &item;
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
    const auto& v = port_values_[port_offset_[atom] + port];
    if (!v) continue;
    if (Item* item = add(v->constraint)) {
      item->kind = Item::Kind::Internal;
      item->atom = atom;
      item->port = port;
    }
  }
  for (const ExternPortState& e : extern_ports_) {
    if (!e.expected) continue;
    if (Item* item = add(*e.expected)) {
      item->kind = Item::Kind::External;
      item->atom = e.atom;
      item->port = e.port;
    }
  }
}

Interval Runtime::wait_interval() const {
  // A lazy constraint lets time pass (its wait is `from now`, which leaves w as it is): only
  // the urgent connectors and internal ports are visited. Intersections: order-free.
  Interval w = Interval::from(state_.now);
  for (Index k : cache_.urgent()) {
    if (listed_position_[k] == kNone) continue;
    for (Index v : connector_values_[k]) {
      const InteractionValue& value = values_[v];
      if (value.raw.urgency == Urgency::Lazy || value.after.interval.empty()) continue;
      narrow(w, wait(value.raw, state_.now));
    }
  }
  for (Index i : urgent_internal_ports_) {
    const auto& [atom, port] = layout_.internal_ports[i];
    narrow(w, wait(port_values_[port_offset_[atom] + port]->constraint, state_.now));
  }
  for (const ExternPortState& e : extern_ports_) {
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
  InteractionValue& value = values_[index];
  const auto& type = system_.connector_types[system_.connectors[value.connector].type];
  const int code = value.code;
  if (code >= 0) {
    const PortContext context{this, &value};
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
  for (const PortValue& pv : values_[index].choice) {
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
  for (const PortValue& pv : values_[value].choice) {
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

std::string Runtime::format_ports(const InteractionValue& value) const {
  const bipc::ir::ConnectorInstance& connector = system_.connectors[value.connector];
  std::string text;
  for (const PortValue& pv : value.choice) {
    if (!text.empty()) text += ' ';
    text += connector.bound_names[pv.param] + "(";
    const bipc::ir::PortType* port_type = nullptr;
    std::vector<Val> values;
    if (pv.from_atom) {
      const AtomType& type = system_.atom_types[system_.atoms[pv.atom].type];
      const bipc::ir::Port& port = type.ports[pv.port];
      port_type = &system_.port_types[port.type];
      for (Index slot : port.data) values.push_back(state_.data[layout_.atom_data[pv.atom] + slot]);
    } else {
      const InteractionValue& sub = values_[pv.sub];
      const auto& type = system_.connector_types[system_.connectors[sub.connector].type];
      if (type.export_type != kNone) port_type = &system_.port_types[type.export_type];
      for (Index slot : type.export_data) values.push_back(sub.data[slot]);
    }
    if (port_type) {
      for (std::size_t p = 0; p < port_type->params.size() && p < values.size(); ++p) {
        text += port_type->params[p].first + "=" +
                format_value(values[p], port_type->params[p].second.kind) + ";";
      }
    }
    text += ")";
  }
  return text;
}

std::string Runtime::format_value(Val v, bipc::ir::ValueKind kind) const {
  switch (kind) {
    case bipc::ir::ValueKind::Bool:
      return v.b ? "true" : "false";
    case bipc::ir::ValueKind::Float: {
      std::ostringstream s;
      s << v.f;
      return s.str();
    }
    case bipc::ir::ValueKind::String:
      return strings_.text(v.s);
    default:
      return std::to_string(v.i);
  }
}

}  // namespace smcbip::engines

namespace smcbip::engines {

std::vector<std::string> Runtime::late_constraints(TimeValue t) const {
  std::vector<std::string> lines;
  auto late = [&](const Constraint& c) { return !wait(c, state_.now).contains(t); };
  auto constraint_text = [](const Constraint& c) {
    return format_interval(c.interval) + " " + urgency_name(c.urgency);
  };
  for (Index k : layout_.listed_connectors) {
    for (Index v : connector_values_[k]) {
      const InteractionValue& value = values_[v];
      if (value.after.interval.empty() || !late(value.raw)) continue;
      lines.push_back(layout_.connector_names[k] + ": " + format_ports(value) + " " +
                      constraint_text(value.raw));
    }
  }
  for (const auto& [atom, port] : layout_.internal_ports) {
    if (state_.resume_pending[atom]) continue;
    const auto& v = port_values_[port_offset_[atom] + port];
    if (!v || !late(v->constraint)) continue;
    const AtomType& type = system_.atom_types[system_.atoms[atom].type];
    lines.push_back(layout_.atom_names[atom] + "." + type.ports[port].name + " " +
                    constraint_text(v->constraint));
  }
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    if (!state_.resume_pending[a] && !atom_invariant_[a].contains(t)) {
      lines.push_back(layout_.atom_names[a] + " invariant " + format_interval(atom_invariant_[a]));
    }
  }
  for (Index a = 0; a < system_.atoms.size(); ++a) {
    if (state_.resume_pending[a] && !state_.resume_interval[a].contains(t)) {
      lines.push_back(layout_.atom_names[a] + " resume " +
                      format_interval(state_.resume_interval[a]));
    }
  }
  return lines;
}

}  // namespace smcbip::engines
