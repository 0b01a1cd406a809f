// ST19: event-action definitions.
#include "event_action.h"

namespace smcbip::pus::services {

EventAction::EventAction(const mission::Mission& mission) : mission_(mission) {
  std::size_t i = 0;
  // The mission reader bounds the definitions to the table and each request to kMaxEmbeddedTc.
  for (const mission::EventAction& a : mission.event_actions) {
    Definition& d = table_[i++];
    d = Definition{true, a.enabled, a.event, {}};
    d.request.assign(a.request);
  }
}

const EventAction::Definition* EventAction::find(std::uint64_t event) const {
  for (const Definition& d : table_) {
    if (d.used && d.event == event) return &d;
  }
  return nullptr;
}

bool EventAction::defined(std::uint64_t event) const { return find(event) != nullptr; }

Outcome EventAction::check(const Activities& definitions) const {
  std::size_t free = 0;
  for (const Definition& d : table_) free += d.used ? 0 : 1;
  for (std::size_t k = 0; k < definitions.items.size(); ++k) {
    const std::uint64_t event = definitions.items[k].event_id;
    const auto datum = static_cast<std::uint32_t>(event);
    if (mission_.find_event(event) == nullptr) return Failure{FailureCode::UnknownId, datum};
    bool repeated = defined(event);
    for (std::size_t j = 0; j < k; ++j)
      repeated = repeated || definitions.items[j].event_id == event;
    if (repeated) return Failure{FailureCode::AlreadyDefined, datum};
  }
  if (definitions.items.size() > free) {
    return Failure{FailureCode::TableFull, static_cast<std::uint32_t>(kEventActionCapacity)};
  }
  return std::nullopt;
}

Outcome EventAction::add(const Activities& definitions) {
  if (Outcome failure = check(definitions)) return failure;
  for (const Activity& a : definitions.items) {
    for (Definition& d : table_) {
      if (d.used) continue;
      d = Definition{true, false, a.event_id, a.request};
      break;
    }
  }
  return std::nullopt;
}

Outcome EventAction::check(const IdList& ids) const {
  for (const std::uint64_t id : ids.ids) {
    if (!defined(id)) return Failure{FailureCode::UnknownId, static_cast<std::uint32_t>(id)};
  }
  return std::nullopt;
}

Outcome EventAction::enable(const IdList& ids) {
  if (Outcome failure = check(ids)) return failure;
  for (const std::uint64_t id : ids.ids) {
    for (Definition& d : table_) {
      if (d.used && d.event == id) d.enabled = true;
    }
  }
  return std::nullopt;
}

std::optional<EmbeddedTc> EventAction::on_event(std::uint64_t event) const {
  const Definition* d = find(event);
  if (d == nullptr || !d->enabled) return std::nullopt;
  return d->request;
}

}  // namespace smcbip::pus::services
