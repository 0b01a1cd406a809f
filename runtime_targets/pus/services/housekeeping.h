// ST03 housekeeping: periodic parameter reports of the mission's report structures.
#pragma once

#include <cstdint>
#include <vector>

#include "mission/mission.h"
#include "packets/packets.h"
#include "parameters.h"
#include "tm_output.h"
#include "verification.h"

namespace smcbip::pus::services {

/// Generates [3,25] for each enabled structure every period, the first one period after it
/// was enabled (or after start, for a structure the mission enables).
class Housekeeping {
 public:
  Housekeeping(const mission::Mission& mission, const ParameterStore& parameters, TmOutput& out,
               Millis start);

  /// Every ID must be defined (UnknownId with the first that is not).
  Outcome check(const IdList& ids) const;
  /// [3,5] / [3,6]: every ID must be defined (UnknownId, nothing changed otherwise).
  Outcome set_enabled(const IdList& ids, bool enabled, Millis now);
  /// Emits the reports due at or before `now`, in order of due time; returns how many.
  std::size_t tick(Millis now);
  /// The earliest due time of an enabled structure (for a scheduler), or none.
  std::optional<Millis> next_due() const;
  bool enabled(std::uint64_t id) const;

 private:
  struct Slot {
    bool enabled = false;
    Millis due = 0;
  };
  std::size_t index(std::uint64_t id) const;
  void report(std::size_t i, Millis at);

  const mission::Mission& mission_;
  const ParameterStore& parameters_;
  TmOutput& out_;
  std::vector<Slot> slots_;
};

}  // namespace smcbip::pus::services
