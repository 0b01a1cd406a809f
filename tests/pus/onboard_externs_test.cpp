// The extern C++ of pus_onboard.bip, called as the model's atoms call it: the expected reports
// and returns follow the services' rules and the bundled mission (tests/pus/
// services_test_support.h summarises it).
#include "onboard/onboard_externs.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "packets/packets.h"

namespace smcbip::pus::onboard {
namespace {

using Kinds = std::vector<std::pair<int, int>>;

/// Flushes the TM queue through a link that decodes what it is handed.
std::vector<Telemetry> flushed() {
  std::vector<Telemetry> packets;
  set_link([&packets](std::span<const std::uint8_t> bytes) {
    auto tm = decode_tm(bytes, Config{});
    EXPECT_TRUE(tm.ok());
    if (tm.ok()) packets.push_back(tm.value());
  });
  tm_flush(0);
  set_link({});
  return packets;
}

Kinds kinds(const std::vector<Telemetry>& packets) {
  Kinds out;
  for (const Telemetry& tm : packets) out.emplace_back(tm.header.service, tm.header.subtype);
  return out;
}

TEST(PusOnboardExterns, PingThroughReceptionAndItsService) {
  ASSERT_EQ(pus_reset(), 1);
  EXPECT_EQ(ground_send(0), 1);
  EXPECT_EQ(tc_accept(10), 17);
  EXPECT_EQ(service_execute(17, 12), 1);
  EXPECT_EQ(kinds(flushed()), (Kinds{{1, 1}, {1, 3}, {17, 2}, {1, 7}}));
  EXPECT_EQ(tc_accept(13), 0);  // the uplink is empty
  EXPECT_EQ(tm_sent(), 4U);
}

TEST(PusOnboardExterns, SpoiltTcIsRefusedOnReception) {
  ASSERT_EQ(pus_reset(), 1);
  ASSERT_EQ(ground_send(4), 1);
  EXPECT_EQ(tc_accept(5), 0);
  EXPECT_EQ(kinds(flushed()), (Kinds{{1, 2}}));
}

TEST(PusOnboardExterns, LimitViolationFoundWithinTheIntervalAndActedUpon) {
  ASSERT_EQ(pus_reset(), 1);
  EXPECT_EQ(periodic_next_due(12), 100);  // monitoring definition 1, every 100 ms from start
  ASSERT_EQ(ground_send(2), 1);           // panel temperature 80, above 60
  ASSERT_EQ(tc_accept(1020), 20);
  ASSERT_EQ(service_execute(20, 1030), 1);
  flushed();
  EXPECT_EQ(periodic_run(12, 1100), 1);   // the checks due at 100, ..., 1100: one violation
  EXPECT_EQ(monitor_detect_delay(), 70);  // out of limits from 1030, found at 1100
  EXPECT_EQ(event_act(1103), 1);          // event 100 reported, heater_off queued
  EXPECT_EQ(kinds(flushed()), (Kinds{{5, 3}}));
  ASSERT_EQ(tc_accept(1105), 8);
  EXPECT_EQ(service_execute(8, 1108), 1);
  EXPECT_EQ(kinds(flushed()), (Kinds{{1, 7}}));  // the action TC asks for completion only
}

TEST(PusOnboardExterns, HousekeepingLatenessAndSchedule) {
  ASSERT_EQ(pus_reset(), 1);
  EXPECT_EQ(periodic_next_due(3), 5000);  // structure 2, enabled by the mission
  EXPECT_EQ(periodic_next_due(11), -1);   // nothing scheduled
  ASSERT_EQ(ground_send(1), 1);           // structure 1 on, every 200 ms
  ASSERT_EQ(tc_accept(400), 3);
  ASSERT_EQ(service_execute(3, 410), 1);
  EXPECT_EQ(periodic_next_due(3), 610);
  EXPECT_EQ(periodic_run(3, 609), 0);
  EXPECT_EQ(periodic_run(3, 613), 3);  // the report due at 610, made 3 ms late
  EXPECT_EQ(periodic_next_due(3), 810);
  EXPECT_EQ(periodic_run(9, 2000), 2);  // time reports at 1000 and 2000
  EXPECT_THROW(periodic_run(4, 0), std::invalid_argument);
}

TEST(PusOnboardExterns, EachThreadRunsItsOwnApplication) {
  ASSERT_EQ(pus_reset(), 1);
  ASSERT_EQ(ground_send(0), 1);
  std::thread other([] {
    EXPECT_THROW(tc_accept(0), std::logic_error);  // no pus_reset() on this thread yet
    ASSERT_EQ(pus_reset(), 1);
    EXPECT_EQ(tc_accept(0), 0);  // this thread's uplink is empty
  });
  other.join();
  EXPECT_EQ(tc_accept(0), 17);  // this one's still holds the ping
}

}  // namespace
}  // namespace smcbip::pus::onboard
