// ST05: event reports and their enabling.
#include "events.h"

namespace smcbip::pus::services {

EventReporting::EventReporting(const mission::Mission& mission, TmOutput& out)
    : mission_(mission), out_(out) {
  for (const mission::Event& event : mission.events) enabled_.push_back(event.enabled);
}

std::size_t EventReporting::index(std::uint64_t id) const {
  for (std::size_t i = 0; i < mission_.events.size(); ++i) {
    if (mission_.events[i].id == id) return i;
  }
  return mission_.events.size();
}

bool EventReporting::enabled(std::uint64_t id) const {
  const std::size_t i = index(id);
  return i < enabled_.size() && enabled_[i];
}

bool EventReporting::raise(std::uint64_t id, std::span<const std::uint8_t> aux, Millis now) {
  const std::size_t i = index(id);
  if (i == enabled_.size()) return false;
  if (!enabled_[i]) return true;
  EventReport report;
  report.event_id = id;
  report.aux_data.assign(aux.first(std::min(aux.size(), kMaxAuxData)));
  const auto subtype = static_cast<std::uint8_t>(1 + static_cast<int>(mission_.events[i].severity));
  if (out_.emit(5, subtype, report, 0, now)) ++reported_;
  return true;
}

Outcome EventReporting::check(const IdList& ids) const {
  for (const std::uint64_t id : ids.ids) {
    if (index(id) == enabled_.size()) {
      return Failure{FailureCode::UnknownId, static_cast<std::uint32_t>(id)};
    }
  }
  return std::nullopt;
}

Outcome EventReporting::set_enabled(const IdList& ids, bool enabled) {
  if (Outcome failure = check(ids)) return failure;
  for (const std::uint64_t id : ids.ids) enabled_[index(id)] = enabled;
  return std::nullopt;
}

}  // namespace smcbip::pus::services
