// The extern C++ of pus_onboard.bip over the services library: one application per thread,
// its uplink queue, the monitoring detection delays and the link to the ground.
#include "onboard/onboard_externs.hpp"

#include <array>
#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "services/application.h"

#ifndef SMCBIP_PUS_DEFAULT_MISSION
#define SMCBIP_PUS_DEFAULT_MISSION "mission.json"
#endif

namespace smcbip::pus::onboard {
namespace {

using services::Millis;

/// TCs the uplink holds, and the longest it takes.
constexpr std::size_t kUplinkCapacity = 32;
constexpr std::size_t kMaxTcLength = 1024;

struct UplinkTc {
  std::array<std::uint8_t, kMaxTcLength> bytes{};
  std::size_t length = 0;
};

/// Everything one run of the model works on.
struct Onboard {
  explicit Onboard(const mission::Mission& m) : mission(m), app(mission, Config{}, 0) {
    out_of_limit_since.assign(mission.monitoring.size(), -1);
    transitions.reserve(mission.monitoring.size());
    pending_events.reserve(4 * mission.monitoring.size() + 4);
  }
  const mission::Mission& mission;
  services::Application app;
  std::array<UplinkTc, kUplinkCapacity> uplink{};
  std::size_t uplink_head = 0;
  std::size_t uplink_size = 0;
  /// The TC reception accepted, then the one each service (by type ID) is executing.
  std::optional<Telecommand> accepted;
  std::array<std::optional<Telecommand>, 256> executing;
  std::vector<services::Transition> transitions;
  /// The violations found whose events event_act() has not reported yet.
  std::vector<services::Transition> pending_events;
  /// Per monitoring definition: when its parameter left its limits, not yet found (-1).
  std::vector<std::int64_t> out_of_limit_since;
  int detect_delay = 0;
  std::uint16_t ground_sequence = 0;
  std::uint64_t sent = 0;
};

/// What the host installs (shared by the threads: read-only once runs start).
const mission::Mission* installed_mission = nullptr;
std::function<void(std::span<const std::uint8_t>)> installed_link;

thread_local std::unique_ptr<mission::Mission> loaded_mission;
thread_local std::unique_ptr<Onboard> state;

Onboard& onboard() {
  // An extern function that runs before pus_reset() is a model error, which the engine reports.
  if (!state) throw std::logic_error("pus_onboard: pus_reset() was not called first");
  return *state;
}

const mission::Mission& mission_to_use() {
  if (installed_mission != nullptr) return *installed_mission;
  if (!loaded_mission) {
    const char* path = std::getenv("SMCBIP_PUS_MISSION");
    const std::string file = path != nullptr ? path : SMCBIP_PUS_DEFAULT_MISSION;
    mission::LoadResult result = mission::load_mission(file);
    if (!result.mission) {
      throw std::runtime_error(mission::format_diagnostics(file, result.diagnostics));
    }
    loaded_mission = std::make_unique<mission::Mission>(std::move(*result.mission));
  }
  return *loaded_mission;
}

bool queue_tc(Onboard& o, std::span<const std::uint8_t> bytes) {
  if (o.uplink_size == kUplinkCapacity || bytes.size() > kMaxTcLength) return false;
  UplinkTc& slot = o.uplink[(o.uplink_head + o.uplink_size) % kUplinkCapacity];
  std::copy(bytes.begin(), bytes.end(), slot.bytes.begin());
  slot.length = bytes.size();
  ++o.uplink_size;
  return true;
}

/// A TC of the simulated ground's scenario (see ground_send()).
Telecommand ground_tc(int kind, std::uint16_t apid, std::uint16_t sequence) {
  Telecommand tc;
  tc.primary.apid = apid;
  tc.primary.sequence_count = sequence & kMaxSequenceCount;
  ParameterValues temperature;
  switch (kind) {
    case 1: {
      IdList structures;
      structures.ids.push_back(1);
      tc.header.service = 3;
      tc.header.subtype = 5;
      tc.data = structures;
      break;
    }
    case 2:
    case 3:
      temperature.values.push_back(IdValue{2, kind == 2 ? 80U : 20U});
      tc.header.service = 20;
      tc.header.subtype = 3;
      tc.data = temperature;
      break;
    case 5: {
      FunctionCall call;
      call.function_id = 2;
      call.arguments.push_back(IdValue{1, 0});
      tc.header.service = 8;
      tc.header.subtype = 1;
      tc.data = call;
      break;
    }
    default:  // 0 and 4: a ping (4 has its CRC spoilt once encoded)
      tc.header.service = 17;
      tc.header.subtype = 1;
      tc.data = NoData{};
      break;
  }
  return tc;
}

/// After a TC changed parameters: the limit checks whose parameter just left its limits.
void note_limit_departures(Onboard& o, Millis now) {
  for (std::size_t i = 0; i < o.mission.monitoring.size(); ++i) {
    const mission::MonitoringDefinition& d = o.mission.monitoring[i];
    if (d.kind != mission::MonitoringDefinition::Kind::Limit) continue;
    const double v = o.app.parameters().value(d.parameter);
    const bool out = v < d.low || v > d.high;
    if (!out) {
      o.out_of_limit_since[i] = -1;
    } else if (o.out_of_limit_since[i] < 0 &&
               !services::violation(o.app.monitoring().status(d.id))) {
      o.out_of_limit_since[i] = static_cast<std::int64_t>(now);
    }
  }
}

}  // namespace

void install_mission(const mission::Mission* mission) { installed_mission = mission; }

void set_link(std::function<void(std::span<const std::uint8_t>)> link) {
  installed_link = std::move(link);
}

bool push_tc(std::span<const std::uint8_t> bytes) { return queue_tc(onboard(), bytes); }

std::uint64_t tm_sent() { return state ? state->sent : 0; }

}  // namespace smcbip::pus::onboard

using smcbip::pus::onboard::Onboard;
using smcbip::pus::services::Millis;

int pus_reset() {
  using namespace smcbip::pus::onboard;
  state = std::make_unique<Onboard>(mission_to_use());
  return 1;
}

int ground_send(int kind) {
  Onboard& o = smcbip::pus::onboard::onboard();
  const auto tc = smcbip::pus::onboard::ground_tc(kind, o.mission.apid, o.ground_sequence++);
  std::array<std::uint8_t, 256> bytes{};
  const auto length = smcbip::pus::encode(tc, smcbip::pus::Config{}, bytes);
  if (!length) throw std::logic_error("pus_onboard: a scenario TC does not encode");
  if (kind == 4) bytes[length.value() - 1] ^= 0xFF;
  return smcbip::pus::onboard::queue_tc(o, {bytes.data(), length.value()}) ? 1 : 0;
}

int tc_accept(int now) {
  Onboard& o = smcbip::pus::onboard::onboard();
  if (o.uplink_size == 0) return 0;
  const auto& tc = o.uplink[o.uplink_head];
  o.accepted = o.app.reception().receive({tc.bytes.data(), tc.length}, static_cast<Millis>(now));
  o.uplink_head = (o.uplink_head + 1) % o.uplink.size();
  --o.uplink_size;
  if (!o.accepted) return 0;
  return o.accepted->header.service;
}

int service_execute(int route, int now) {
  Onboard& o = smcbip::pus::onboard::onboard();
  if (!o.accepted || o.accepted->header.service != route) return 0;
  const auto at = static_cast<Millis>(now);
  const auto before = o.app.functions().performed();
  const bool refused = o.app.check(*o.accepted, at).has_value();
  o.app.execute(*o.accepted, at);
  o.accepted.reset();
  if (route == 20 || (route == 8 && o.app.functions().performed() != before)) {
    smcbip::pus::onboard::note_limit_departures(o, at);
  }
  return refused ? 0 : 1;
}

int periodic_run(int kind, int now) {
  Onboard& o = smcbip::pus::onboard::onboard();
  const auto at = static_cast<Millis>(now);
  switch (kind) {
    case 3: {
      // Lateness: how long after its due time the latest report was made.
      const auto due = o.app.housekeeping().next_due();
      const std::size_t reports = o.app.housekeeping().tick(at);
      return reports > 0 && due ? static_cast<int>(at - *due) : 0;
    }
    case 9:
      return static_cast<int>(o.app.time_reporting().tick(at));
    case 11: {
      int released = 0;
      while (const auto tc = o.app.schedule().release(at)) {
        released += smcbip::pus::onboard::queue_tc(o, tc->span()) ? 1 : 0;
      }
      return released;
    }
    case 12: {
      o.transitions.clear();
      o.app.monitoring().tick(at, o.transitions);
      int violations = 0;
      for (const smcbip::pus::services::Transition& t : o.transitions) {
        if (!smcbip::pus::services::violation(t.to)) continue;
        ++violations;
        o.pending_events.push_back(t);
        for (std::size_t i = 0; i < o.mission.monitoring.size(); ++i) {
          if (o.mission.monitoring[i].id != t.definition || o.out_of_limit_since[i] < 0) continue;
          o.detect_delay =
              std::max(o.detect_delay, static_cast<int>(now - o.out_of_limit_since[i]));
          o.out_of_limit_since[i] = -1;
        }
      }
      return violations;
    }
    default:
      throw std::invalid_argument("pus_onboard: no periodic work of service " +
                                  std::to_string(kind));
  }
}

int periodic_next_due(int kind) {
  Onboard& o = smcbip::pus::onboard::onboard();
  std::optional<smcbip::pus::services::Millis> due;
  switch (kind) {
    case 3:
      due = o.app.housekeeping().next_due();
      break;
    case 9:
      due = o.app.time_reporting().next_due();
      break;
    case 11:
      due = o.app.schedule().next_due();
      break;
    case 12:
      due = o.app.monitoring().next_due();
      break;
    default:
      throw std::invalid_argument("pus_onboard: no periodic work of service " +
                                  std::to_string(kind));
  }
  return due ? static_cast<int>(std::min<smcbip::pus::services::Millis>(*due, 0x7FFFFFFF)) : -1;
}

int monitor_detect_delay() { return smcbip::pus::onboard::onboard().detect_delay; }

int event_act(int now) {
  Onboard& o = smcbip::pus::onboard::onboard();
  int released = 0;
  for (const smcbip::pus::services::Transition& t : o.pending_events) {
    const auto aux = smcbip::pus::services::event_aux(t);
    if (!o.app.events().raise(t.event, aux, static_cast<smcbip::pus::services::Millis>(now))) {
      continue;
    }
    if (const auto action = o.app.event_action().on_event(t.event)) {
      released += smcbip::pus::onboard::queue_tc(o, action->span()) ? 1 : 0;
    }
  }
  o.pending_events.clear();
  return released;
}

int tm_flush(int /*now*/) {
  Onboard& o = smcbip::pus::onboard::onboard();
  int flushed = 0;
  while (const smcbip::pus::services::TmPacket* packet = o.app.tm().front()) {
    if (smcbip::pus::onboard::installed_link) smcbip::pus::onboard::installed_link(packet->span());
    o.app.tm().pop();
    ++o.sent;
    ++flushed;
  }
  return flushed;
}
