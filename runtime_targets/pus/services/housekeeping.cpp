// ST03: periodic housekeeping reports.
#include "housekeeping.h"

namespace smcbip::pus::services {

Housekeeping::Housekeeping(const mission::Mission& mission, const ParameterStore& parameters,
                           TmOutput& out, Millis start)
    : mission_(mission), parameters_(parameters), out_(out) {
  for (const mission::HousekeepingStructure& s : mission.housekeeping) {
    slots_.push_back(Slot{s.enabled, start + s.period_ms});
  }
}

std::size_t Housekeeping::index(std::uint64_t id) const {
  for (std::size_t i = 0; i < mission_.housekeeping.size(); ++i) {
    if (mission_.housekeeping[i].id == id) return i;
  }
  return mission_.housekeeping.size();
}

bool Housekeeping::enabled(std::uint64_t id) const {
  const std::size_t i = index(id);
  return i < slots_.size() && slots_[i].enabled;
}

Outcome Housekeeping::check(const IdList& ids) const {
  for (const std::uint64_t id : ids.ids) {
    if (index(id) == slots_.size()) {
      return Failure{FailureCode::UnknownId, static_cast<std::uint32_t>(id)};
    }
  }
  return std::nullopt;
}

Outcome Housekeeping::set_enabled(const IdList& ids, bool enabled, Millis now) {
  if (Outcome failure = check(ids)) return failure;
  for (const std::uint64_t id : ids.ids) {
    Slot& slot = slots_[index(id)];
    // Enabling an enabled structure keeps its phase.
    if (enabled && !slot.enabled) slot.due = now + mission_.housekeeping[index(id)].period_ms;
    slot.enabled = enabled;
  }
  return std::nullopt;
}

void Housekeeping::report(std::size_t i, Millis at) {
  const mission::HousekeepingStructure& s = mission_.housekeeping[i];
  HousekeepingReport data;
  data.structure_id = s.id;
  for (const std::uint64_t id : s.parameters) {
    std::uint64_t raw = 0;
    parameters_.get(id, raw);  // the mission checked every ID
    data.values.push_back(raw);
  }
  out_.emit(3, 25, data, 0, at);
}

std::optional<Millis> Housekeeping::next_due() const {
  std::optional<Millis> earliest;
  for (const Slot& slot : slots_) {
    if (slot.enabled && (!earliest || slot.due < *earliest)) earliest = slot.due;
  }
  return earliest;
}

std::size_t Housekeeping::tick(Millis now) {
  std::size_t reports = 0;
  for (auto due = next_due(); due && *due <= now; due = next_due()) {
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      if (slots_[i].enabled && slots_[i].due == *due) {
        report(i, *due);
        slots_[i].due += mission_.housekeeping[i].period_ms;
        ++reports;
      }
    }
  }
  return reports;
}

}  // namespace smcbip::pus::services
