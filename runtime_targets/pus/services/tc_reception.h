// TC reception and routing: decodes the octets of a TC, refuses malformed or misaddressed
// ones with TM[1,2], accepts the others with TM[1,1] and says which service executes them.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "packets/packets.h"
#include "tm_output.h"
#include "verification.h"

namespace smcbip::pus::services {

/// The services a TC is routed to (their service type IDs).
enum class Route : std::uint8_t {
  Housekeeping = 3,
  Events = 5,
  Functions = 8,
  Time = 9,
  Scheduling = 11,
  Monitoring = 12,
  Test = 17,
  EventAction = 19,
  Parameters = 20,
  Files = 23,
};

/// Receives the TCs of one application process.
class TcReception {
 public:
  TcReception(const Config& config, std::uint16_t apid, Verification& verification)
      : config_(config), apid_(apid), verification_(verification) {}

  /// The accepted TC, or nothing after a [1,2] (decoder refusal: Malformed with the reason and
  /// the offset; another APID: WrongApid; a service with no route: NotRouted).
  std::optional<Telecommand> receive(std::span<const std::uint8_t> bytes, Millis now);

  /// The service that executes an accepted TC.
  static std::optional<Route> route(const Telecommand& tc);

  std::uint64_t accepted() const { return accepted_; }
  std::uint64_t rejected() const { return rejected_; }

 private:
  Config config_;
  std::uint16_t apid_;
  Verification& verification_;
  std::uint64_t accepted_ = 0;
  std::uint64_t rejected_ = 0;
};

}  // namespace smcbip::pus::services
