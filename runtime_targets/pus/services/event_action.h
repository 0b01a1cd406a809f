// ST19 event-action: the TC each event definition releases when the event occurs.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "mission/mission.h"
#include "packets/packets.h"
#include "scheduling.h"
#include "verification.h"

namespace smcbip::pus::services {

/// Event-action definitions the table holds.
inline constexpr std::size_t kEventActionCapacity = mission::kMaxEventActions;

/// The event-action definitions, keyed by event definition ID: the mission's, then those
/// [19,1] adds (disabled until [19,4] enables them, ECSS-E-ST-70-41C 6.19.5).
class EventAction {
 public:
  explicit EventAction(const mission::Mission& mission);

  /// [19,1]: each event must be defined by the mission (UnknownId), have no definition yet
  /// (AlreadyDefined) and fit the table (TableFull); otherwise none is added.
  Outcome add(const Activities& definitions);
  /// What add() would refuse, without adding.
  Outcome check(const Activities& definitions) const;
  /// [19,4]: every ID must have a definition (UnknownId).
  Outcome enable(const IdList& ids);
  /// What enable() would refuse.
  Outcome check(const IdList& ids) const;
  /// The TC to release when the event occurs, if an enabled definition has it.
  std::optional<EmbeddedTc> on_event(std::uint64_t event) const;
  bool defined(std::uint64_t event) const;

 private:
  struct Definition {
    bool used = false;
    bool enabled = false;
    std::uint64_t event = 0;
    EmbeddedTc request;
  };
  const Definition* find(std::uint64_t event) const;

  const mission::Mission& mission_;
  std::array<Definition, kEventActionCapacity> table_{};
};

}  // namespace smcbip::pus::services
