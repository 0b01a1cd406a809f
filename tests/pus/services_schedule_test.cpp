// ST11 time-based scheduling, ST12 monitoring and ST19 event-action of the on-board services,
// against the bundled mission (summarised in services_test_support.h).
#include "services_test_support.h"

namespace smcbip::pus::services {
namespace {

using testing::application;
using testing::drain;
using testing::failure_of;
using testing::ids;
using testing::Kinds;
using testing::kinds;
using testing::tc_bytes;
using testing::time_of;

/// The packets other than time reports (which run in the background).
std::vector<Telemetry> without_time(const std::vector<Telemetry>& tm) {
  std::vector<Telemetry> out;
  for (const Telemetry& p : tm) {
    if (p.header.service != 9) out.push_back(p);
  }
  return out;
}

Activities one(const Activity& a) {
  Activities out;
  out.items.push_back(a);
  return out;
}

Activity activity(Millis release, const std::vector<std::uint8_t>& request) {
  Activity a;
  a.release_time = to_cuc(release, Config{});
  a.request.assign(request);
  return a;
}

ParameterValues value(std::uint64_t id, std::uint64_t raw) {
  ParameterValues v;
  v.values.push_back(IdValue{id, raw});
  return v;
}

TEST(PusServicesSchedule, ActivityReleasedAtItsTime) {
  auto app = application();
  Activities insert;
  insert.items.push_back(activity(2500, tc_bytes(17, 1, NoData{}, 40, 0b1001)));
  app->receive(tc_bytes(11, 4, insert, 0), 1000);
  // Accepted, started, one progress step per activity, completed.
  EXPECT_EQ(kinds(drain(app->tm())), (Kinds{{1, 1}, {1, 3}, {1, 5}, {1, 7}}));
  EXPECT_EQ(app->schedule().next_due(), 2500U);
  app->tick(2499);
  EXPECT_TRUE(without_time(drain(app->tm())).empty());
  app->tick(2600);
  const auto tm = without_time(drain(app->tm()));
  ASSERT_EQ(kinds(tm), (Kinds{{1, 1}, {17, 2}, {1, 7}}));
  EXPECT_EQ(time_of(tm[1]), 2500U);
  EXPECT_EQ(std::get<pus::Verification>(tm[2].data).request.sequence_count, 40);
  EXPECT_EQ(app->schedule().size(), 0U);
}

TEST(PusServicesSchedule, PastReleaseTimeAndFullScheduleAreRefused) {
  auto app = application();
  Activities past;
  past.items.push_back(activity(1000, tc_bytes(17, 1, NoData{})));
  app->receive(tc_bytes(11, 4, past, 0, 0), 1000);
  auto tm = drain(app->tm());
  ASSERT_EQ(kinds(tm), (Kinds{{1, 4}}));
  EXPECT_EQ(failure_of(tm[0]), std::make_pair(std::uint64_t{8}, std::uint32_t{1}));
  // Four requests of four activities fill the sixteen entries; a seventeenth is refused.
  Activities four;
  for (int i = 0; i < 4; ++i) four.items.push_back(activity(5000, tc_bytes(17, 1, NoData{})));
  for (std::uint16_t seq = 1; seq <= 4; ++seq) app->receive(tc_bytes(11, 4, four, seq, 0), 1000);
  EXPECT_EQ(app->schedule().size(), kScheduleCapacity);
  app->receive(tc_bytes(11, 4, one(activity(6000, tc_bytes(17, 1, NoData{}))), 5, 0), 1000);
  tm = drain(app->tm());
  ASSERT_EQ(kinds(tm), (Kinds{{1, 4}}));
  EXPECT_EQ(failure_of(tm[0]).first, 6U);
}

TEST(PusServicesMonitoring, LimitViolationRaisesEventThatTriggersAction) {
  auto app = application();
  app->tick(1000);  // checked every 100 ms: panel_temperature 20 is within -20..60
  drain(app->tm());
  EXPECT_EQ(app->monitoring().status(1), CheckStatus::WithinLimits);
  app->receive(tc_bytes(20, 3, value(2, 80), 0, 0), 1050);
  app->tick(1100);
  const auto tm = without_time(drain(app->tm()));
  // The check at 1100 finds 80 above 60: event 100 (medium, [5,3]); its action TC[8,1]
  // heater_off (acknowledging completion only) is accepted and completed at once.
  ASSERT_EQ(kinds(tm), (Kinds{{5, 3}, {1, 7}}));
  EXPECT_EQ(time_of(tm[0]), 1100U);
  const auto& event = std::get<EventReport>(tm[0].data);
  EXPECT_EQ(event.event_id, 100U);
  // Auxiliary data: definition 1, raw value 80.
  EXPECT_EQ(std::vector<std::uint8_t>(event.aux_data.begin(), event.aux_data.end()),
            (std::vector<std::uint8_t>{0, 1, 0, 0, 0, 80}));
  EXPECT_EQ(app->monitoring().status(1), CheckStatus::AboveHighLimit);
  EXPECT_EQ(app->parameters().value(3), 0);  // the heater is off
  // Staying out of limits is no new transition.
  app->tick(1500);
  EXPECT_TRUE(without_time(drain(app->tm())).empty());
  // Back within limits: a transition, but no event for it.
  app->receive(tc_bytes(20, 3, value(2, 30), 1, 0), 1550);
  app->tick(1600);
  EXPECT_TRUE(without_time(drain(app->tm())).empty());
  EXPECT_EQ(app->monitoring().status(1), CheckStatus::WithinLimits);
}

TEST(PusServicesMonitoring, ExpectedValueConfirmedAfterRepetitions) {
  auto app = application();
  app->receive(tc_bytes(12, 1, ids({2}), 0, 0), 0);
  app->receive(tc_bytes(20, 3, value(4, 1), 1, 0), 0);
  // Checks at 500 (unexpected, once) and 1000 (twice: confirmed): event 101, low, [5,2].
  app->tick(999);
  EXPECT_TRUE(without_time(drain(app->tm())).empty());
  EXPECT_EQ(app->monitoring().status(2), CheckStatus::Unchecked);
  app->tick(1000);
  const auto tm = without_time(drain(app->tm()));
  ASSERT_EQ(kinds(tm), (Kinds{{5, 2}}));
  EXPECT_EQ(app->monitoring().status(2), CheckStatus::UnexpectedValue);
  // Disabling resets the status.
  app->receive(tc_bytes(12, 2, ids({2}), 2, 0), 1000);
  EXPECT_EQ(app->monitoring().status(2), CheckStatus::Unchecked);
}

TEST(PusServicesEventAction, AddedDefinitionActsOnceEnabled) {
  auto app = application();
  Activities add;
  Activity definition;
  definition.event_id = 101;
  definition.request.assign(tc_bytes(8, 1, FunctionCall{2, {}}, 77, 0));
  // set_mode without its argument: the released TC is refused at start, which shows it ran.
  add.items.push_back(definition);
  app->receive(tc_bytes(19, 1, add, 0, 0), 0);
  EXPECT_TRUE(app->event_action().defined(101));
  EXPECT_FALSE(app->event_action().on_event(101).has_value());  // added disabled
  app->receive(tc_bytes(19, 4, ids({101}), 1, 0), 0);
  ASSERT_TRUE(app->event_action().on_event(101).has_value());
  EXPECT_TRUE(drain(app->tm()).empty());
  app->receive(tc_bytes(12, 1, ids({2}), 2, 0), 0);
  app->receive(tc_bytes(20, 3, value(4, 3), 3, 0), 0);
  app->tick(1000);
  const auto tm = without_time(drain(app->tm()));
  ASSERT_EQ(kinds(tm), (Kinds{{5, 2}, {1, 4}}));
  EXPECT_EQ(std::get<pus::Verification>(tm[1].data).request.sequence_count, 77);
}

TEST(PusServicesEventAction, RefusedDefinitions) {
  auto app = application();
  Activity a;
  a.request.assign(tc_bytes(17, 1, NoData{}));
  const std::vector<std::pair<std::uint64_t, std::pair<std::uint64_t, std::uint32_t>>> cases{
      {100, {7, 100}},  // the mission defines an action for event 100 already
      {555, {4, 555}},  // undefined event
  };
  std::uint16_t seq = 0;
  for (const auto& [event, expected] : cases) {
    a.event_id = event;
    app->receive(tc_bytes(19, 1, one(a), seq++, 0), 0);
    const auto tm = drain(app->tm());
    ASSERT_EQ(kinds(tm), (Kinds{{1, 4}}));
    EXPECT_EQ(failure_of(tm[0]), expected);
  }
  app->receive(tc_bytes(19, 4, ids({101}), seq, 0), 0);
  EXPECT_EQ(failure_of(drain(app->tm()).at(0)),
            std::make_pair(std::uint64_t{4}, std::uint32_t{101}));
}

}  // namespace
}  // namespace smcbip::pus::services
