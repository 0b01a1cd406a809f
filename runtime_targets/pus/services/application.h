// The on-board PUS application: TC reception and routing over the services, and the periodic
// work (housekeeping, time reports, monitoring with its events and actions, the schedule).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "event_action.h"
#include "events.h"
#include "file_management.h"
#include "functions.h"
#include "housekeeping.h"
#include "mission/mission.h"
#include "monitoring.h"
#include "packets/packets.h"
#include "parameters.h"
#include "scheduling.h"
#include "tc_reception.h"
#include "time_reporting.h"
#include "tm_output.h"
#include "verification.h"

namespace smcbip::pus::services {

/// One application process (the mission's APID) with every service; TM goes to `tm()`.
/// The mission must outlive the application.
class Application {
 public:
  Application(const mission::Mission& mission, const Config& config, Millis start);
  Application(const Application&) = delete;
  Application& operator=(const Application&) = delete;

  /// A TC from the link at `now`: accepted ([1,1]) and executed, or refused ([1,2]).
  void receive(std::span<const std::uint8_t> bytes, Millis now);
  /// Executes an accepted TC: the service checks the request whole ([1,4] with its failure
  /// when it refuses), then [1,3], the service's work and reports, [1,5] for each activity of
  /// [11,4] and [19,1], and [1,7] ([1,8] if the work failed all the same).
  void execute(const Telecommand& tc, Millis now);
  /// What the service of an accepted TC refuses, without executing it.
  Outcome check(const Telecommand& tc, Millis now) const;
  /// Does the periodic work due at or before `now`, in order of due time, each at its time.
  void tick(Millis now);
  /// The earliest time periodic work is due, or none.
  std::optional<Millis> next_due() const;

  TmOutput& tm() { return tm_; }
  TcReception& reception() { return reception_; }
  ParameterStore& parameters() { return parameters_; }
  /// The services one by one, for a host (the BIP model's atoms) that runs their periodic
  /// work itself, each at its own pace, instead of through tick().
  EventReporting& events() { return events_; }
  Housekeeping& housekeeping() { return housekeeping_; }
  Monitoring& monitoring() { return monitoring_; }
  Schedule& schedule() { return schedule_; }
  EventAction& event_action() { return event_action_; }
  TimeReporting& time_reporting() { return time_; }
  const EventReporting& events() const { return events_; }
  const FunctionManagement& functions() const { return functions_; }
  const Housekeeping& housekeeping() const { return housekeeping_; }
  const Monitoring& monitoring() const { return monitoring_; }
  const Schedule& schedule() const { return schedule_; }
  const EventAction& event_action() const { return event_action_; }
  const TimeReporting& time_reporting() const { return time_; }

 private:
  Outcome dispatch(const Telecommand& tc, Millis now);
  void step(Millis at);
  void raise(const Transition& transition, Millis at);

  const mission::Mission& mission_;
  Config config_;
  TmOutput tm_;
  Verification verification_;
  TcReception reception_;
  ParameterStore parameters_;
  EventReporting events_;
  FunctionManagement functions_;
  Housekeeping housekeeping_;
  TimeReporting time_;
  Schedule schedule_;
  Monitoring monitoring_;
  EventAction event_action_;
  FileManagement files_;
  std::vector<Transition> transitions_;
};

}  // namespace smcbip::pus::services
