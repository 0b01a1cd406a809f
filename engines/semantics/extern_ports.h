// The extern ports of one run: their event sources, the event at the head of each queue, and
// which port takes its event now (the reference engine's checkExternals).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

/// An extern port's event source and the event at the head of its queue (pulled lazily).
struct ExternPortState {
  Index atom = 0, port = 0;
  std::unique_ptr<ExternPortSource> source;
  ExternEvent head;  // when has_head; its buffer is reused from event to event
  bool has_head = false;
  bool exhausted = false;
  std::optional<Constraint> expected;  // the head event's item, when its port can take it
  bool unexpected = false;             // the head's port cannot take it (policy error, ignore)
};

/// The extern ports of a run, in Layout::extern_ports order. It reads the run's state and the
/// atom ports' offers (flattened by atom, port from `port_offset`), which its owner keeps, and
/// records its failures in `error`.
class ExternPorts {
 public:
  ExternPorts(const bipc::ir::System& system, const Layout& layout, const BoundFunctions& functions,
              RunState& state, const std::vector<std::optional<AtomPortValue>>& port_values,
              const std::vector<std::size_t>& port_offset, ModelError& error)
      : system_(system),
        layout_(layout),
        functions_(functions),
        state_(state),
        port_values_(port_values),
        port_offset_(port_offset),
        error_(error) {}

  /// Opens a source per extern port (a run starts); false with the error set when a port's
  /// class is not registered.
  bool open();
  /// Pulls the ports' next events and decides which ports take theirs (ExternPortState::expected).
  void refresh();
  bool empty() const { return ports_.empty(); }
  const std::vector<ExternPortState>& ports() const { return ports_; }
  /// The earliest date at which a pending event that its port cannot take arrives.
  std::optional<TimeValue> first_unexpected_arrival() const;
  /// See Runtime::receive_unexpected_events.
  bool receive_unexpected(TimeValue upto);
  /// Takes the head event of extern port `port` of `atom`: its values are written to the port's
  /// data. False when that is no extern port.
  bool take_event(Index atom, Index port);
  /// See Runtime::wake_extern_port.
  void wake(Index atom, Index port);

 private:
  const bipc::ir::Port& port_of(const ExternPortState& e) const {
    return system_.atom_types[system_.atoms[e.atom].type].ports[e.port];
  }
  bool fail(int code, std::string message);

  const bipc::ir::System& system_;
  const Layout& layout_;
  const BoundFunctions& functions_;
  RunState& state_;
  const std::vector<std::optional<AtomPortValue>>& port_values_;
  const std::vector<std::size_t>& port_offset_;
  ModelError& error_;
  std::vector<ExternPortState> ports_;
};

}  // namespace smcbip::engines
