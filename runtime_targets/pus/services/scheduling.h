// ST11 time-based scheduling: TCs released at their on-board time.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "packets/packets.h"
#include "tm_output.h"
#include "verification.h"

namespace smcbip::pus::services {

/// Activities the schedule holds.
inline constexpr std::size_t kScheduleCapacity = 16;

/// A released TC: its whole octets, as [11,4] carried them.
using EmbeddedTc = FixedBytes<kMaxEmbeddedTc>;

/// The time-based schedule: [11,4] inserts activities; each is released once its time has
/// come, earliest first (insertion order among equal times).
class Schedule {
 public:
  /// [11,4]: every release time must lie after `now` (ReleaseTimePassed) and the schedule must
  /// hold them all (TableFull); otherwise none is inserted.
  Outcome insert(const Activities& activities, const Config& config, Millis now);
  /// What insert() would refuse, without inserting.
  Outcome check(const Activities& activities, const Config& config, Millis now) const;
  /// Removes and returns the next activity due at or before `now`.
  std::optional<EmbeddedTc> release(Millis now);
  /// The earliest release time, or none.
  std::optional<Millis> next_due() const;
  std::size_t size() const;

 private:
  struct Entry {
    bool used = false;
    Millis release = 0;
    std::uint64_t order = 0;
    EmbeddedTc request;
  };
  const Entry* earliest() const;

  std::array<Entry, kScheduleCapacity> entries_{};
  std::uint64_t inserted_ = 0;
};

}  // namespace smcbip::pus::services
