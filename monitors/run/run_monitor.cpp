#include "monitors/run/run_monitor.h"

#include <limits>

namespace smcbip::monitors {

double EngineState::value(const Expr& name) const {
  const Reference& r = name.reference;
  switch (r.kind) {
    case Reference::Kind::Data: {
      const bipc::ir::System& system = state_.system();
      const auto kind = system.atom_types[system.atoms[r.atom].type].data[r.index].type.kind;
      const engines::Val v = state_.data(r.atom, r.index);
      if (kind == bipc::ir::ValueKind::Bool) return v.b ? 1 : 0;
      if (kind == bipc::ir::ValueKind::Float) return v.f;
      return static_cast<double>(v.i);
    }
    case Reference::Kind::Place:
      return state_.marked(r.atom, r.index) ? 1 : 0;
    case Reference::Kind::Clock:
      return state_.clock(r.atom, r.index);
    default:  // resolve_names leaves nothing else to read from a state
      return std::numeric_limits<double>::quiet_NaN();
  }
}

double EngineState::slope(const Expr& name) const {
  const Reference& r = name.reference;
  return r.kind == Reference::Kind::Clock ? state_.clock_slope(r.atom, r.index) : 0;
}

RunEnd monitor_end(engines::RunEnd end) {
  switch (end) {
    case engines::RunEnd::Deadlock:
      return RunEnd::Deadlock;
    case engines::RunEnd::Timelock:
      return RunEnd::Timelock;
    case engines::RunEnd::Absorbing:
      return RunEnd::Absorbing;
    default:
      return RunEnd::Cut;
  }
}

bool EngineState::fired(const Expr& fired) const {
  const Reference& r = fired.reference;
  using Fired = engines::StepInfo::Fired;
  if (r.kind == Reference::Kind::Connector) {
    return step_.fired == Fired::Interaction && step_.connector == r.index;
  }
  return r.kind == Reference::Kind::InternalPort &&
         (step_.fired == Fired::Internal || step_.fired == Fired::External) &&
         step_.atom == r.atom && step_.port == r.index;
}

double RunMonitor::first_hit_ms() const {
  const online::Pos hit = monitor_.first_hit_for_sure();
  if (monitor_.verdict() != Verdict::True || hit == online::kForever) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  // Positions count half ticks of nanoseconds.
  return static_cast<double>(hit.t) / 2 / 1e6;
}

bool RunMonitor::observe(const engines::StepInfo& step, const engines::StateView& state) {
  return monitor_.step(EngineState(step, state), step.time) == Verdict::Undecided;
}

void RunMonitor::finish(engines::RunEnd end, int, const std::string&) {
  // A run stopped once the verdict was known needs no end; any other stop cuts it short.
  monitor_.end(monitor_end(end));
}

}  // namespace smcbip::monitors
