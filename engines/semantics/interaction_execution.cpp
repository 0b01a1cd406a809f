// The execution of an interaction value in sequence: downs and atom firings depth first, as the
// reference engine runs them. The multithread engine's parallel path:
// engines/multithread/pool_firing.cpp.
#include "engines/semantics/interaction_execution.h"

#include <algorithm>

#include "engines/semantics/detail/runtime_shared.h"

namespace smcbip::engines {

using detail::connector_frame;
using detail::PortContext;

InteractionExecution::InteractionExecution(const bipc::ir::System& system, const Layout& layout,
                                           ModelCode& eval, RunState& state, ModelError& error,
                                           ConnectorValues& connectors, AtomFiring& atoms,
                                           std::unique_ptr<ParallelFiring> parallel)
    : system_(system),
      layout_(layout),
      eval_(eval),
      state_(state),
      error_(error),
      connectors_(connectors),
      atoms_(atoms),
      parallel_(std::move(parallel)) {}

InteractionExecution::~InteractionExecution() = default;

void InteractionExecution::run_down(Index index) {
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

bool InteractionExecution::execute_in_sequence(Index index) {
  run_down(index);
  // Ports run in the interaction's port order, depth first: a sub-connector's down comes after
  // the atoms of earlier ports have executed (reference engine order).
  for (const PortValue& pv : connectors_.values()[index].choice) {
    if (pv.from_atom ? !atoms_.fire_port(pv.atom, pv.port) : !execute_in_sequence(pv.sub)) {
      return false;
    }
  }
  return true;
}

void InteractionExecution::append_atom_ports(Index value,
                                             std::vector<std::pair<Index, Index>>& out) const {
  for (const PortValue& pv : connectors_.values()[value].choice) {
    if (pv.from_atom) {
      out.emplace_back(pv.atom, pv.port);
    } else {
      append_atom_ports(pv.sub, out);
    }
  }
}

}  // namespace smcbip::engines
