// Connector code on the compiled step path (flat_steps.h): the guard and `up` over a
// rendezvous's value, and its `down`, as Runtime::connector_code_allows and
// InteractionExecution run them, the port parameters found through the flat tables.
#pragma once

#include <algorithm>
#include <cstdint>

#include "bipc/ir/ir.h"
#include "engines/api/compiled_model.h"
#include "engines/semantics/flat_tables.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

template <class Code>
class FlatConnectorCode {
 public:
  /// `t` must outlive it.
  FlatConnectorCode(Code& code, const bipc::ir::System& system, const FlatTables& t)
      : code_(code), system_(system), t_(t) {}

  /// Runtime::connector_code_allows for a connector with data or code: its data copied from
  /// `state` into its value (in `value_data`), the guard, then `up` when it holds.
  bool allowed(const FlatTables::Connector& c, RunState& state, Val* value_data) const {
    std::copy_n(state.data.begin() + c.data, c.data_size, value_data + c.value_data);
    if (!c.guarded) return true;
    const PortContext context{this, &c, &state};
    const Frame f = frame(c, context, value_data, state.now);
    const bipc::ir::InteractionCode& code = interaction(c);
    if (!code.guard.empty() && !code_.evaluate(code.guard, f).b) return false;
    code_.execute(code.up, f);
    return true;
  }

  /// The connector's `down` over its value.
  void down(const FlatTables::Connector& c, RunState& state, Val* value_data) const {
    const PortContext context{this, &c, &state};
    code_.execute(interaction(c).down, frame(c, context, value_data, state.now));
  }

 private:
  /// What the code finds its port parameters through (Frame::port_slot).
  struct PortContext {
    const FlatConnectorCode* self;
    const FlatTables::Connector* connector;
    RunState* state;
  };
  static Val* port_slot(const void* context, Index port, std::uint16_t arg) {
    const auto& c = *static_cast<const PortContext*>(context);
    const FlatTables& t = c.self->t_;
    const FlatTables::Port& bound = t.ports[c.connector->first_port + port];
    return &c.state->data[t.param_slots[bound.first_param + arg]];
  }

  static Frame frame(const FlatTables::Connector& c, const PortContext& context, Val* value_data,
                     TimeValue now) {
    Frame f;
    f.connector_data = value_data + c.value_data;
    f.port_slot = &port_slot;
    f.port_context = &context;
    f.now = now;
    return f;
  }

  const bipc::ir::InteractionCode& interaction(const FlatTables::Connector& c) const {
    return system_.connector_types[c.type].interactions[static_cast<std::size_t>(c.code)];
  }

  Code& code_;
  const bipc::ir::System& system_;
  const FlatTables& t_;
};

}  // namespace smcbip::engines
