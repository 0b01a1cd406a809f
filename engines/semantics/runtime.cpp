// The BIP semantics of one run: its start, the computation of the items, timing constraints and
// the execution of an item. Atoms: atom_firing.cpp; connector interactions:
// connector_values.cpp and interaction_execution.cpp; priorities: compound_priorities.cpp and
// atom_priorities.cpp; items: item_listing.cpp; extern ports: extern_ports.cpp; traces:
// runtime_trace.cpp. Follows the Verimag reference engine.
#include "engines/semantics/runtime.h"

#include <algorithm>

#include "engines/api/simulate.h"
#include "engines/semantics/detail/runtime_shared.h"

namespace smcbip::engines {

using bipc::Urgency;
using bipc::ir::kNone;
using detail::narrow;
using detail::wait;

Runtime::Runtime(const Model& model, const Layout& layout, const BoundFunctions& functions,
                 StringPool& strings, std::ostream& out, RandomStream& random,
                 const RuntimeOptions& options)
    : system_(model.system()),
      layout_(layout),
      strings_(strings),
      call_{out, strings, &random, {}},
      code_(model.make_code(functions, call_)),
      eval_(*code_),
      options_(options),
      cache_(system_, layout),
      atoms_(system_, layout, eval_, state_, error_, cache_),
      connectors_(system_, layout, options, eval_, state_, atoms_.port_values(),
                  atoms_.port_offset(), cache_, listing_, priorities_),
      extern_ports_(system_, layout, functions, state_, atoms_.port_values(), atoms_.port_offset(),
                    error_),
      listing_(system_, layout, state_, connectors_.values(), connectors_.connector_values(),
               atoms_.port_values(), atoms_.port_offset(), extern_ports_, options.incremental),
      priorities_(system_, layout, options.maximal_progress, eval_, state_, error_, connectors_,
                  cache_, time_bound_),
      execution_(system_, layout, eval_, state_, error_, connectors_, atoms_,
                 options.parallel_firing ? options.parallel_firing(model, functions, call_, options)
                                         : nullptr) {
  connectors_.index();
}

Runtime::~Runtime() = default;

std::string source_position(const bipc::ir::System& system, const bipc::Location& at) {
  if (at.line == 0 || at.file >= system.source_files.size()) return {};
  return bipc::position_text(system.source_files[at.file], at.line, at.column);
}

ModelError fault_error(const bipc::ir::System& system, const CodeFault& fault) {
  const bool known = fault.site < system.sites.size();
  return {kInputError, fault.message,
          known ? source_position(system, system.sites[fault.site]) : std::string()};
}

namespace {

/// Records `error` in `to` and answers false, as the runtime's calls do when they fail.
bool failed(ModelError& to, ModelError error) {
  to = std::move(error);
  return false;
}

}  // namespace

bool Runtime::initialize() {
  cache_.invalidate_all();
  // Assigned in place: a run started again reuses the buffers.
  state_.now = 0;
  state_.data.assign(layout_.data_size, make_int(0));
  state_.marking.assign(layout_.place_count, 0);
  state_.clocks.assign(layout_.clock_count, ClockState{});
  state_.resume_pending.assign(system_.atoms.size(), 0);
  state_.resume_interval.assign(system_.atoms.size(), Interval::all());
  atoms_.clear_offers();
  if (!extern_ports_.open()) return false;
  atoms_.time_bounds().note_all();
  try {
    atoms_.initialize_data();
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
      if (!atoms_.start(a)) return false;
    }
  } catch (const CodeFault& fault) {
    return failed(error_, fault_error(system_, fault));
  }
  return priorities_.check_cycles();
}

bool Runtime::compute_items() {
  listing_.begin();
  time_bound_ = atoms_.time_bounds().bound();
  if (!priorities_.check_cycles()) return false;
  const bool full = !options_.incremental || cache_.all_stale();
  listing_.note_internal_ports(full, cache_);
  connectors_.begin(full);
  try {
    connectors_.compute(full);
  } catch (const CodeFault& fault) {
    cache_.invalidate_all();
    return failed(error_, fault_error(system_, fault));
  } catch (const UnsupportedRun& unsupported) {
    cache_.invalidate_all();
    return failed(error_, {kInputError, unsupported.message, {}});
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
  const std::vector<std::optional<AtomPortValue>>& offers = atoms_.port_values();
  for (Index i : listing_.urgent_internal_ports()) {
    const auto& [atom, port] = layout_.internal_ports[i];
    narrow(w, wait(offers[atoms_.port_offset()[atom] + port]->constraint, state_.now));
  }
  for (const ExternPortState& e : extern_ports_.ports()) {
    if (e.expected) narrow(w, wait(*e.expected, state_.now));
  }
  return w.intersect(atoms_.time_bounds().bound());
}

void Runtime::append_atom_ports(const Item& item, std::vector<std::pair<Index, Index>>& out) const {
  if (item.kind != Item::Kind::Interaction) {
    out.emplace_back(item.atom, item.port);
    return;
  }
  execution_.append_atom_ports(item.value, out);
}

bool Runtime::restore(const RunState& state) {
  cache_.invalidate_all();
  state_ = state;
  atoms_.time_bounds().note_all();
  try {
    // The invariants' time bounds are those of the restored marking, not of the last state.
    for (Index a = 0; a < system_.atoms.size(); ++a) {
      if (!atoms_.check_invariants(a)) return false;
    }
    for (Index a = 0; a < system_.atoms.size(); ++a) {
      if (!state_.resume_pending[a] && !atoms_.update(a)) return false;
    }
  } catch (const CodeFault& fault) {
    return failed(error_, fault_error(system_, fault));
  }
  return true;
}

bool Runtime::execute(const Item& item, TimeValue at) {
  state_.now = at;
  try {
    if (item.kind == Item::Kind::Interaction) return execution_.execute(item.value);
    // An extern item whose port takes no event fires nothing.
    if (item.kind == Item::Kind::External && !extern_ports_.take_event(item.atom, item.port)) {
      return true;
    }
    return atoms_.fire_port(item.atom, item.port);
  } catch (const CodeFault& fault) {
    return failed(error_, fault_error(system_, fault));
  }
}

bool Runtime::receive_unexpected_events(TimeValue upto) {
  return extern_ports_.receive_unexpected(upto);
}

void Runtime::wake_extern_port(Index atom, Index port) { extern_ports_.wake(atom, port); }

bool Runtime::write_data(Index atom, Index slot, Val value) {
  state_.data[layout_.atom_data[atom] + slot] = value;
  cache_.touch_atom(atom);  // also when resuming: its connectors' code may read the data
  try {
    return atoms_.settle(atom);
  } catch (const CodeFault& fault) {
    return failed(error_, fault_error(system_, fault));
  }
}

bool Runtime::resume_atoms(TimeValue now) {
  if (!atoms_.resume()) return false;
  state_.now = std::max(state_.now, now);
  return true;
}

Interval Runtime::resume_window() const { return atoms_.time_bounds().resume_window(); }

}  // namespace smcbip::engines
