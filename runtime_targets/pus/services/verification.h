// ST01 request verification: the acceptance, start, progress and completion reports of a TC.
#pragma once

#include <cstdint>
#include <optional>

#include "packets/packets.h"
#include "tm_output.h"

namespace smcbip::pus::services {

/// Why a request failed; the failure code of the ST01 failure reports (mission-defined).
enum class FailureCode : std::uint16_t {
  Malformed = 1,          ///< refused by the decoder; data: reason (1 octet), offset (2)
  WrongApid = 2,          ///< addressed to another application process; data: its APID
  NotRouted = 3,          ///< a service this application does not provide
  UnknownId = 4,          ///< an ID the mission does not define; data: the ID
  InvalidArgument = 5,    ///< a value out of limits or an argument missing; data: the ID
  TableFull = 6,          ///< no room left in a table (schedule, event-action); data: the ID
  AlreadyDefined = 7,     ///< an event-action definition for this event exists; data: the ID
  ReleaseTimePassed = 8,  ///< a schedule release time not in the future; data: the time (s)
  FileRefused = 9,        ///< the host file system refused an ST23 request; data: its errno
};

/// A failed request: the failure code and the datum its failure data carries (four octets,
/// big-endian).
struct Failure {
  FailureCode code{};
  std::uint32_t datum = 0;
};

/// What a service did with a request: nothing (success) or why it failed.
using Outcome = std::optional<Failure>;

/// ECSS-E-ST-70-41C 6.1: success reports only for the stages the TC's acknowledgement flags ask
/// for (acceptance bit 0, start 1, progress 2, completion 3); failure reports always. Each
/// report goes to the TC's source ID.
class Verification {
 public:
  explicit Verification(TmOutput& out) : out_(out) {}

  void accepted(const Telecommand& tc, Millis now);
  /// [1,2] for a TC refused before it was decoded: the request ID is what its first four
  /// octets say (zero if fewer), the destination 0.
  void rejected(const RequestId& request, std::uint16_t source, const Failure& failure, Millis now);
  void started(const Telecommand& tc, Millis now);
  void start_failed(const Telecommand& tc, const Failure& failure, Millis now);
  void progressed(const Telecommand& tc, std::uint64_t step, Millis now);
  void progress_failed(const Telecommand& tc, std::uint64_t step, const Failure& failure,
                       Millis now);
  void completed(const Telecommand& tc, Millis now);
  void completion_failed(const Telecommand& tc, const Failure& failure, Millis now);

 private:
  void report(std::uint8_t subtype, const RequestId& request, std::uint16_t destination,
              const Failure* failure, std::uint64_t step, Millis now);

  TmOutput& out_;
};

}  // namespace smcbip::pus::services
