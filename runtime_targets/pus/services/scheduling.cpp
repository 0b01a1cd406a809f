// ST11: the time-based schedule.
#include "scheduling.h"

namespace smcbip::pus::services {

std::size_t Schedule::size() const {
  std::size_t used = 0;
  for (const Entry& e : entries_) used += e.used ? 1 : 0;
  return used;
}

Outcome Schedule::check(const Activities& activities, const Config& config, Millis now) const {
  for (const Activity& a : activities.items) {
    if (to_millis(a.release_time, config) <= now) {
      return Failure{FailureCode::ReleaseTimePassed, a.release_time.coarse};
    }
  }
  if (size() + activities.items.size() > kScheduleCapacity) {
    return Failure{FailureCode::TableFull, static_cast<std::uint32_t>(kScheduleCapacity)};
  }
  return std::nullopt;
}

Outcome Schedule::insert(const Activities& activities, const Config& config, Millis now) {
  if (Outcome failure = check(activities, config, now)) return failure;
  for (const Activity& a : activities.items) {
    for (Entry& e : entries_) {
      if (e.used) continue;
      e = Entry{true, to_millis(a.release_time, config), inserted_++, a.request};
      break;
    }
  }
  return std::nullopt;
}

const Schedule::Entry* Schedule::earliest() const {
  const Entry* best = nullptr;
  for (const Entry& e : entries_) {
    if (e.used && (best == nullptr || e.release < best->release ||
                   (e.release == best->release && e.order < best->order))) {
      best = &e;
    }
  }
  return best;
}

std::optional<Millis> Schedule::next_due() const {
  const Entry* e = earliest();
  return e == nullptr ? std::nullopt : std::optional<Millis>(e->release);
}

std::optional<EmbeddedTc> Schedule::release(Millis now) {
  const Entry* e = earliest();
  if (e == nullptr || e->release > now) return std::nullopt;
  Entry& entry = entries_[static_cast<std::size_t>(e - entries_.data())];
  entry.used = false;
  return entry.request;
}

}  // namespace smcbip::pus::services
