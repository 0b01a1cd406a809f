// Extern ports: events from sources registered in C++ (`extern port T p(x) as "<class>"
// remember|ignore|error`). An event is taken by its port when a transition labelled by the port
// is enabled and can run at or after the event's date; otherwise its policy decides: remember
// keeps it until the port can take it, ignore drops it when it arrives, error stops the run
// with error 6 when it arrives (the reference engine's checkExternals).
#include "engines/semantics/extern_ports.h"

#include <algorithm>
#include <string>

#include "engines/api/simulate.h"
#include "engines/semantics/runtime.h"

namespace smcbip::engines {

bool ExternPorts::fail(int code, std::string message) {
  error_ = {code, std::move(message), {}};
  return false;
}

bool ExternPorts::open() {
  ports_.clear();
  for (const auto& [atom, port] : layout_.extern_ports) {
    const bipc::ir::Port& p = system_.atom_types[system_.atoms[atom].type].ports[port];
    const auto found = functions_.port_classes.find(p.backend_name);
    if (found == functions_.port_classes.end() || found->second == nullptr) {
      return fail(kInputError, "no extern port class \"" + p.backend_name +
                                   "\" is registered (port " + p.name + " of " +
                                   layout_.atom_names[atom] + ")");
    }
    ExternPortState state;
    state.atom = atom;
    state.port = port;
    state.source = (*found->second)(system_.atoms[atom].path, p.name);
    state.head.values.reserve(p.data.size());
    ports_.push_back(std::move(state));
  }
  return true;
}

void ExternPorts::refresh() {
  for (ExternPortState& e : ports_) {
    e.expected.reset();
    e.unexpected = false;
    if (state_.resume_pending[e.atom]) continue;
    if (!e.has_head && !e.exhausted) {
      e.has_head = e.source->pull(state_.now, e.head);
      e.exhausted = !e.has_head;
    }
    if (!e.has_head) continue;
    const bipc::ir::Port& port = port_of(e);
    const auto& offer = port_values_[port_offset_[e.atom] + e.port];
    const TimeValue at = e.head.time;
    const bool outdated = at < state_.now;
    std::optional<Constraint> taken;
    if (offer) {
      Constraint c = offer->constraint;
      c.interval = c.interval.intersect(Interval::from(std::max(at, state_.now)));
      // An event outside its port's window is only taken when remembered.
      const bool in_window = offer->constraint.interval.contains(at);
      if (!c.interval.empty() &&
          (port.policy == bipc::ExternPolicy::Remember || (!outdated && in_window))) {
        taken = c;
      }
    }
    if (taken) {
      e.expected = taken;
    } else if (port.policy != bipc::ExternPolicy::Remember) {
      e.unexpected = true;
    }
  }
}

std::optional<TimeValue> ExternPorts::first_unexpected_arrival() const {
  std::optional<TimeValue> first;
  for (const ExternPortState& e : ports_) {
    if (!e.unexpected) continue;
    const TimeValue at = std::max(e.head.time, state_.now);
    if (!first || at < *first) first = at;
  }
  return first;
}

bool ExternPorts::receive_unexpected(TimeValue upto) {
  for (ExternPortState& e : ports_) {
    if (!e.unexpected || std::max(e.head.time, state_.now) > upto) continue;
    const bipc::ir::Port& port = port_of(e);
    if (port.policy == bipc::ExternPolicy::Ignore) {
      e.has_head = false;
      e.unexpected = false;
      continue;
    }
    const std::string& atom = layout_.atom_names[e.atom];
    if (e.head.time < state_.now) {
      return fail(kUnexpectedEvent,
                  "port " + port.name + " of component " + atom +
                      " has received an outdated event at " + format_time(e.head.time) +
                      " while current engine time is already " + format_time(state_.now) + "!");
    }
    state_.now = e.head.time;
    return fail(kUnexpectedEvent, "port " + port.name + " of component " + atom +
                                      " has received an event at " + format_time(e.head.time) +
                                      " while being disabled at current state and having event "
                                      "consumption policy 'error'!");
  }
  return true;
}

bool ExternPorts::take_event(Index atom, Index port) {
  for (ExternPortState& e : ports_) {
    if (e.atom != atom || e.port != port) continue;
    const bipc::ir::Port& p = port_of(e);
    Val* data = state_.data.data() + layout_.atom_data[e.atom];
    const std::size_t n = std::min(p.data.size(), e.head.values.size());
    for (std::size_t i = 0; i < n; ++i) data[p.data[i]] = e.head.values[i];
    e.has_head = false;
    return true;
  }
  return false;
}

void ExternPorts::wake(Index atom, Index port) {
  for (ExternPortState& e : ports_) {
    if (e.atom == atom && e.port == port) e.exhausted = false;
  }
}

}  // namespace smcbip::engines
