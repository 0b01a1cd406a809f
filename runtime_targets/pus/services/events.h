// ST05 event reporting: the mission's events, each reported at its severity while enabled.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "mission/mission.h"
#include "packets/packets.h"
#include "tm_output.h"
#include "verification.h"

namespace smcbip::pus::services {

/// Raises the mission's events as [5,1]..[5,4] (informative .. high severity).
class EventReporting {
 public:
  EventReporting(const mission::Mission& mission, TmOutput& out);

  /// Reports the event if its report generation is enabled; false for an undefined event.
  /// Whether reported or not, the event occurred (event-action definitions still respond).
  bool raise(std::uint64_t id, std::span<const std::uint8_t> aux, Millis now);
  /// Every ID must be defined (UnknownId with the first that is not).
  Outcome check(const IdList& ids) const;
  /// [5,5] / [5,6]: every ID must be defined (UnknownId, nothing changed otherwise).
  Outcome set_enabled(const IdList& ids, bool enabled);
  bool enabled(std::uint64_t id) const;
  std::uint64_t reported() const { return reported_; }

 private:
  std::size_t index(std::uint64_t id) const;

  const mission::Mission& mission_;
  TmOutput& out_;
  std::vector<bool> enabled_;
  std::uint64_t reported_ = 0;
};

}  // namespace smcbip::pus::services
