// Shared helpers of the services' tests: the bundled mission, TCs as octets, the TM queue
// drained and decoded.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "mission/mission.h"
#include "packets/packets.h"
#include "services/application.h"

namespace smcbip::pus::services::testing {

/// The bundled mission.json (apid 18; parameters 1 battery_voltage float32 28, 2
/// panel_temperature int32 20 in -100..150, 3 heater_on bool 1, 4 mode uint32 0 in 0..3; HK 1
/// = (1, 2, 3) every 200 ms disabled, HK 2 = (4) every 5000 ms enabled; events 100 medium,
/// 101 low; functions 1 heater_off (heater_on := 0), 2 set_mode(1: mode) (mode := arg 1);
/// monitoring 1: panel_temperature in -20..60 every 100 ms -> event 100, monitoring 2: mode &
/// 3 == 0 every 500 ms, 2 repetitions -> event 101, disabled; event 100 -> TC[8,1] function 1.
inline const mission::Mission& bundled_mission() {
  static const mission::Mission mission = [] {
    mission::LoadResult loaded = mission::load_mission(PUS_MISSION_PATH);
    if (!loaded.mission) std::abort();
    return std::move(*loaded.mission);
  }();
  return mission;
}

/// The octets of a TC of the mission's APID.
inline std::vector<std::uint8_t> tc_bytes(std::uint8_t service, std::uint8_t subtype,
                                          const Message& data, std::uint16_t sequence = 0,
                                          std::uint8_t ack = 0xF, std::uint16_t apid = 18) {
  Telecommand tc;
  tc.primary.apid = apid;
  tc.primary.sequence_count = sequence;
  tc.header.ack_flags = ack;
  tc.header.service = service;
  tc.header.subtype = subtype;
  tc.header.source_id = 7;
  tc.data = data;
  std::array<std::uint8_t, 1024> out{};
  const auto length = encode(tc, Config{}, out);
  EXPECT_TRUE(length.ok());
  return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(length.ok() ? length.value() : 0)};
}

inline IdList ids(std::initializer_list<std::uint64_t> list) {
  IdList out;
  for (const std::uint64_t id : list) out.ids.push_back(id);
  return out;
}

/// Every queued TM, decoded, oldest first; the queue is left empty.
inline std::vector<Telemetry> drain(TmOutput& out) {
  std::vector<Telemetry> packets;
  while (const TmPacket* packet = out.front()) {
    auto tm = decode_tm(packet->span(), out.config());
    EXPECT_TRUE(tm.ok());
    if (tm.ok()) packets.push_back(tm.value());
    out.pop();
  }
  return packets;
}

/// [service, subtype] of each packet.
inline std::vector<std::pair<int, int>> kinds(const std::vector<Telemetry>& packets) {
  std::vector<std::pair<int, int>> out;
  for (const Telemetry& tm : packets) out.emplace_back(tm.header.service, tm.header.subtype);
  return out;
}

/// The packets of one [service, subtype].
inline std::vector<Telemetry> only(const std::vector<Telemetry>& tm, int service, int subtype) {
  std::vector<Telemetry> out;
  for (const Telemetry& p : tm) {
    if (p.header.service == service && p.header.subtype == subtype) out.push_back(p);
  }
  return out;
}

/// The on-board time of a TM, in milliseconds.
inline Millis time_of(const Telemetry& tm) { return to_millis(tm.header.time, Config{}); }

/// The failure code and four-octet datum of an ST01 failure report.
inline std::pair<std::uint64_t, std::uint32_t> failure_of(const Telemetry& tm) {
  const auto& v = std::get<pus::Verification>(tm.data);
  std::uint32_t datum = 0;
  for (const std::uint8_t octet : v.failure_data) datum = (datum << 8) | octet;
  return {v.failure_code, datum};
}

/// A fresh application of the bundled mission, started at time 0.
inline std::unique_ptr<Application> application() {
  return std::make_unique<Application>(bundled_mission(), Config{}, 0);
}

using Kinds = std::vector<std::pair<int, int>>;

}  // namespace smcbip::pus::services::testing
