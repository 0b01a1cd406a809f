// ST20 on-board parameter management: the parameters' current values, reported and set.
#pragma once

#include <cstdint>
#include <vector>

#include "mission/mission.h"
#include "packets/packets.h"
#include "tm_output.h"
#include "verification.h"

namespace smcbip::pus::services {

/// The current raw values of the mission's parameters (allocated once, at start).
class ParameterStore {
 public:
  explicit ParameterStore(const mission::Mission& mission);

  /// The raw value of a parameter; false if the mission does not define it.
  bool get(std::uint64_t id, std::uint64_t& raw) const;
  /// The value as the parameter's type reads it (0 for an unknown ID).
  double value(std::uint64_t id) const;
  /// Whether a raw value may be set: the parameter exists (UnknownId) and the bits are a value
  /// of its type within its limits (InvalidArgument).
  Outcome check(std::uint64_t id, std::uint64_t raw) const;
  /// Sets a raw value if check() allows it.
  Outcome set(std::uint64_t id, std::uint64_t raw);
  /// Every ID defined (UnknownId).
  Outcome check(const IdList& ids) const;
  /// Every (ID, value) settable (as check() of one).
  Outcome check(const ParameterValues& values) const;

  /// [20,1] -> [20,2]: every ID must be defined (UnknownId otherwise, nothing reported).
  Outcome report(const IdList& ids, std::uint16_t destination, TmOutput& out, Millis now) const;
  /// [20,3]: every (ID, value) is checked before any is set (UnknownId, InvalidArgument); a
  /// parameter given twice takes the later value.
  Outcome set_all(const ParameterValues& values);

  const mission::Mission& mission() const { return mission_; }

 private:
  const mission::Mission& mission_;
  std::vector<std::uint64_t> raw_;
};

}  // namespace smcbip::pus::services
