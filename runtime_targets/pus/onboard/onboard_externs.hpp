// The extern C++ of pus_onboard.bip: the functions its atoms call (ints in, ints out) over one
// on-board application of the services library, and what a host program adds (the mission,
// the link, the TCs it receives).
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "mission/mission.h"

// Functions the model calls. Times are on-board milliseconds since the start of the run; the
// state is per thread, so that the runs of a statistical check on several threads stay apart.

/// Builds the application anew (every run starts here): the host's mission if one was
/// installed, else the file SMCBIP_PUS_MISSION names, else the bundled mission.json. Returns 1.
int pus_reset();
/// The simulated ground: queues a TC of scenario `kind` (0 ping, 1 housekeeping structure 1 on,
/// 2 panel temperature 80, 3 panel temperature 20, 4 a TC with a bad CRC, 5 set_mode(0)) in the
/// uplink. Returns the TCs queued: 1, or 0 when the uplink is full (the TC is lost).
int ground_send(int kind);
/// Takes the oldest TC of the uplink through reception ([1,1] or [1,2]); the service type it is
/// routed to, or 0 if it was refused (or the uplink was empty).
int tc_accept(int now);
/// The service `route` executes the TC reception routed to it; 1 if it completed, 0 if refused.
int service_execute(int route, int now);
/// The periodic work of service `kind` (3, 9, 11, 12) due at or before `now`: 3 returns the
/// largest lateness of the reports it made (ms, 0 for none), 9 the reports made, 11 the TCs it
/// released to the uplink, 12 the violations it found (their events wait for event_act()).
int periodic_run(int kind, int now);
/// When the periodic work of `kind` is due next, or -1 for never (nothing enabled).
int periodic_next_due(int kind);
/// The largest delay so far between a monitored parameter leaving its limits (by a TC's
/// execution) and ST12 finding it (ms).
int monitor_detect_delay();
/// Reports the events of the violations found ([5,x]) and queues the TCs their event-action
/// definitions release in the uplink; returns how many TCs.
int event_act(int now);
/// Hands every queued TM packet to the link; returns how many.
int tm_flush(int now);

namespace smcbip::pus::onboard {

/// The mission pus_reset() builds the application of (it must outlive the runs); nullptr
/// forgets it.
void install_mission(const mission::Mission* mission);
/// Where tm_flush() hands each TM packet (none: they are counted and dropped).
void set_link(std::function<void(std::span<const std::uint8_t>)> link);
/// Queues a TC received from the ground in the uplink (the host then counts it in the model's
/// uplink atom). False if the uplink is full.
bool push_tc(std::span<const std::uint8_t> bytes);
/// TM packets handed to the link since pus_reset().
std::uint64_t tm_sent();

}  // namespace smcbip::pus::onboard
