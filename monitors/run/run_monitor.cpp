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

namespace {

/// The values OperatorMonitor's programs load, read straight from the engine's state.
class EngineReader {
 public:
  explicit EngineReader(const engines::StateView& state) : state_(state) {}
  double load(online::StateProgram::Code code, const online::StateProgram::Op& op) const {
    using Code = online::StateProgram::Code;
    switch (code) {
      case Code::Int:
        return static_cast<double>(state_.data_at(op.offset).i);
      case Code::Bool:
        return state_.data_at(op.offset).b ? 1 : 0;
      case Code::Float:
        return state_.data_at(op.offset).f;
      case Code::Place:
        return state_.marked_at(op.offset) ? 1 : 0;
      default:  // as EngineState: nothing else to read from a state
        return std::numeric_limits<double>::quiet_NaN();
    }
  }

 private:
  const engines::StateView& state_;
};

}  // namespace

RunMonitor::RunMonitor(const Formula& formula, const TimeScale& scale, const Bindings& bindings,
                       const Bound& run, Monitoring monitoring) {
  if (monitoring == Monitoring::Fastest && OperatorMonitor::accepts(formula)) {
    fast_.emplace(formula, scale, bindings, run);
  } else {
    general_.emplace(formula, scale, bindings, run);
  }
}

void RunMonitor::bind(const engines::StateView& state) {
  const bipc::ir::System& system = state.system();
  const auto kind_of = [&](std::uint32_t atom, std::uint32_t slot) {
    using Kind = online::StateProgram::DataKind;
    const auto kind = system.atom_types[system.atoms[atom].type].data[slot].type.kind;
    return kind == bipc::ir::ValueKind::Bool    ? Kind::Bool
           : kind == bipc::ir::ValueKind::Float ? Kind::Float
                                                : Kind::Int;
  };
  const auto data_offset = [&](std::uint32_t atom, std::uint32_t slot) {
    return state.data_offset(atom, slot);
  };
  const auto place_offset = [&](std::uint32_t atom, std::uint32_t place) {
    return state.place_offset(atom, place);
  };
  for (online::StateProgram* program : {&fast_->hold_program(), &fast_->goal_program()}) {
    program->bind_data(kind_of);
    program->bind_offsets(data_offset, place_offset);
  }
  bound_ = &system;
}

double RunMonitor::first_hit_ms() const {
  const online::Pos hit = fast_ ? fast_->first_hit_for_sure() : general_->first_hit_for_sure();
  if (verdict() != Verdict::True || hit == online::kForever) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  // Positions count half ticks of nanoseconds.
  return static_cast<double>(hit.t) / 2 / 1e6;
}

bool RunMonitor::observe(const engines::StepInfo& step, const engines::StateView& state) {
  if (fast_) {
    if (&state.system() != bound_) bind(state);
    return fast_->step_with(EngineReader(state), step.time) == Verdict::Undecided;
  }
  return general_->step(EngineState(step, state), step.time) == Verdict::Undecided;
}

void RunMonitor::finish(engines::RunEnd end, int, const std::string&) {
  // A run stopped once the verdict was known needs no end; any other stop cuts it short.
  if (fast_) {
    fast_->end(monitor_end(end));
  } else {
    general_->end(monitor_end(end));
  }
}

}  // namespace smcbip::monitors
