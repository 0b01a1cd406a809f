// ST12: parameter checks and their confirmed transitions.
#include "monitoring.h"

namespace smcbip::pus::services {

bool violation(CheckStatus status) {
  return status == CheckStatus::BelowLowLimit || status == CheckStatus::AboveHighLimit ||
         status == CheckStatus::UnexpectedValue;
}

std::array<std::uint8_t, 6> event_aux(const Transition& transition) {
  return {static_cast<std::uint8_t>(transition.definition >> 8),
          static_cast<std::uint8_t>(transition.definition),
          static_cast<std::uint8_t>(transition.raw_value >> 24),
          static_cast<std::uint8_t>(transition.raw_value >> 16),
          static_cast<std::uint8_t>(transition.raw_value >> 8),
          static_cast<std::uint8_t>(transition.raw_value)};
}

Monitoring::Monitoring(const mission::Mission& mission, const ParameterStore& parameters,
                       Millis start)
    : mission_(mission), parameters_(parameters) {
  for (const mission::MonitoringDefinition& d : mission.monitoring) {
    states_.push_back(
        State{d.enabled, start + d.interval_ms, CheckStatus::Unchecked, CheckStatus::Unchecked, 0});
  }
}

std::size_t Monitoring::index(std::uint64_t id) const {
  for (std::size_t i = 0; i < mission_.monitoring.size(); ++i) {
    if (mission_.monitoring[i].id == id) return i;
  }
  return mission_.monitoring.size();
}

CheckStatus Monitoring::status(std::uint64_t id) const {
  const std::size_t i = index(id);
  return i < states_.size() ? states_[i].status : CheckStatus::Unchecked;
}

Outcome Monitoring::check(const IdList& ids) const {
  for (const std::uint64_t id : ids.ids) {
    if (index(id) == states_.size()) {
      return Failure{FailureCode::UnknownId, static_cast<std::uint32_t>(id)};
    }
  }
  return std::nullopt;
}

Outcome Monitoring::set_enabled(const IdList& ids, bool enabled, Millis now) {
  if (Outcome failure = check(ids)) return failure;
  for (const std::uint64_t id : ids.ids) {
    const std::size_t i = index(id);
    State& s = states_[i];
    if (enabled && !s.enabled) s.due = now + mission_.monitoring[i].interval_ms;
    if (!enabled) s = State{false, s.due, CheckStatus::Unchecked, CheckStatus::Unchecked, 0};
    s.enabled = enabled;
  }
  return std::nullopt;
}

CheckStatus Monitoring::evaluate(const mission::MonitoringDefinition& d, std::uint64_t raw) const {
  if (d.kind == mission::MonitoringDefinition::Kind::ExpectedValue) {
    return (raw & d.mask) == (d.expected & d.mask) ? CheckStatus::ExpectedValue
                                                   : CheckStatus::UnexpectedValue;
  }
  const double v = mission::from_raw(mission_.find_parameter(d.parameter)->type, raw);
  if (v < d.low) return CheckStatus::BelowLowLimit;
  if (v > d.high) return CheckStatus::AboveHighLimit;
  return CheckStatus::WithinLimits;
}

void Monitoring::check(std::size_t i, std::vector<Transition>& transitions) {
  const mission::MonitoringDefinition& d = mission_.monitoring[i];
  State& s = states_[i];
  std::uint64_t raw = 0;
  parameters_.get(d.parameter, raw);  // the mission checked the reference
  const CheckStatus now_status = evaluate(d, raw);
  s.agreeing = now_status == s.candidate ? s.agreeing + 1 : 1;
  s.candidate = now_status;
  if (s.candidate != s.status && s.agreeing >= d.repetitions) {
    transitions.push_back(Transition{d.id, d.parameter, raw, s.status, s.candidate, d.event});
    s.status = s.candidate;
  }
}

std::optional<Millis> Monitoring::next_due() const {
  std::optional<Millis> earliest;
  for (const State& s : states_) {
    if (s.enabled && (!earliest || s.due < *earliest)) earliest = s.due;
  }
  return earliest;
}

void Monitoring::tick(Millis now, std::vector<Transition>& transitions) {
  for (auto due = next_due(); due && *due <= now; due = next_due()) {
    for (std::size_t i = 0; i < states_.size(); ++i) {
      if (states_[i].enabled && states_[i].due == *due) {
        check(i, transitions);
        states_[i].due += mission_.monitoring[i].interval_ms;
      }
    }
  }
}

}  // namespace smcbip::pus::services
