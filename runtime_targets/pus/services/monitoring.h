// ST12 on-board monitoring: limit and expected-value checks of parameters, their transitions
// reported as ST05 events.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mission/mission.h"
#include "packets/packets.h"
#include "parameters.h"
#include "tm_output.h"
#include "verification.h"

namespace smcbip::pus::services {

/// The checking status of a monitoring definition (ECSS-E-ST-70-41C 6.12.3.5).
enum class CheckStatus : std::uint8_t {
  Unchecked,
  WithinLimits,
  BelowLowLimit,
  AboveHighLimit,
  ExpectedValue,
  UnexpectedValue,
};

/// Whether a status is a violation (out of limits or unexpected).
bool violation(CheckStatus status);

/// A confirmed change of a definition's status; `event` is raised when `to` is a violation.
struct Transition {
  std::uint64_t definition = 0;
  std::uint64_t parameter = 0;
  std::uint64_t raw_value = 0;
  CheckStatus from{};
  CheckStatus to{};
  std::uint64_t event = 0;
};

/// The auxiliary data of the event a transition raises: the monitoring definition ID (2
/// octets) and the parameter's raw value (4 octets).
std::array<std::uint8_t, 6> event_aux(const Transition& transition);

/// Checks each enabled definition every interval (from start, or from its enabling); a new
/// status is confirmed after `repetitions` consecutive checks agree on it.
class Monitoring {
 public:
  Monitoring(const mission::Mission& mission, const ParameterStore& parameters, Millis start);

  /// Every ID must be defined (UnknownId with the first that is not).
  Outcome check(const IdList& ids) const;
  /// [12,1] / [12,2]: every ID must be defined (UnknownId); disabling resets to Unchecked.
  Outcome set_enabled(const IdList& ids, bool enabled, Millis now);
  /// Runs the checks due at or before `now`, appending the confirmed transitions.
  void tick(Millis now, std::vector<Transition>& transitions);
  std::optional<Millis> next_due() const;
  CheckStatus status(std::uint64_t id) const;

 private:
  struct State {
    bool enabled = true;
    Millis due = 0;
    CheckStatus status = CheckStatus::Unchecked;
    CheckStatus candidate = CheckStatus::Unchecked;
    std::uint32_t agreeing = 0;
  };
  std::size_t index(std::uint64_t id) const;
  CheckStatus evaluate(const mission::MonitoringDefinition& d, std::uint64_t raw) const;
  void check(std::size_t i, std::vector<Transition>& transitions);

  const mission::Mission& mission_;
  const ParameterStore& parameters_;
  std::vector<State> states_;
};

}  // namespace smcbip::pus::services
