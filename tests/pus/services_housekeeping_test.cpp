// ST03 housekeeping, ST05 event reporting and ST08 function management of the on-board
// services, against the bundled mission (summarised in services_test_support.h).
#include "services_test_support.h"

namespace smcbip::pus::services {
namespace {

using testing::application;
using testing::drain;
using testing::failure_of;
using testing::ids;
using testing::Kinds;
using testing::kinds;
using testing::only;
using testing::tc_bytes;
using testing::time_of;

TEST(PusServicesHousekeeping, EnabledStructureReportsEveryPeriod) {
  auto app = application();
  app->tick(999);
  EXPECT_TRUE(only(drain(app->tm()), 3, 25).empty());  // structure 1 is disabled
  app->receive(tc_bytes(3, 5, ids({1}), 0, 0), 1000);
  // Every 200 ms from the enabling: 1200, 1400, 1600, 1800.
  app->tick(1850);
  const auto hk = only(drain(app->tm()), 3, 25);
  ASSERT_EQ(hk.size(), 4U);
  EXPECT_EQ(time_of(hk[0]), 1200U);
  EXPECT_EQ(time_of(hk[3]), 1800U);
  HousekeepingReport expected;
  expected.structure_id = 1;
  for (const std::uint64_t raw : {0x41E00000U, 0x14U, 0x1U}) expected.values.push_back(raw);
  EXPECT_EQ(std::get<HousekeepingReport>(hk[0].data), expected);
  app->receive(tc_bytes(3, 6, ids({1}), 1, 0), 1850);
  app->tick(2500);
  EXPECT_TRUE(only(drain(app->tm()), 3, 25).empty());
}

TEST(PusServicesHousekeeping, StructureEnabledByTheMissionReportsFromStart) {
  auto app = application();
  app->tick(10000);
  const auto hk = only(drain(app->tm()), 3, 25);
  ASSERT_EQ(hk.size(), 2U);  // structure 2 at 5000 and 10000
  EXPECT_EQ(std::get<HousekeepingReport>(hk[1].data).structure_id, 2U);
  EXPECT_EQ(time_of(hk[1]), 10000U);
}

TEST(PusServicesHousekeeping, UnknownStructureRefusesTheWholeRequest) {
  auto app = application();
  app->receive(tc_bytes(3, 5, ids({1, 9}), 0, 0), 0);
  const auto tm = drain(app->tm());
  ASSERT_EQ(kinds(tm), (Kinds{{1, 4}}));
  EXPECT_EQ(failure_of(tm[0]), std::make_pair(std::uint64_t{4}, std::uint32_t{9}));
  EXPECT_FALSE(app->housekeeping().enabled(1));
}

TEST(PusServicesEvents, DisabledEventIsNotReported) {
  auto app = application();
  EXPECT_TRUE(app->events().enabled(100));
  app->receive(tc_bytes(5, 6, ids({100}), 0, 0), 0);
  EXPECT_FALSE(app->events().enabled(100));
  app->receive(tc_bytes(5, 5, ids({100, 101}), 1, 0), 0);
  EXPECT_TRUE(app->events().enabled(100));
  app->receive(tc_bytes(5, 5, ids({102}), 2, 0), 0);
  EXPECT_EQ(failure_of(drain(app->tm()).at(0)),
            std::make_pair(std::uint64_t{4}, std::uint32_t{102}));
}

TEST(PusServicesEvents, SeverityGivesTheSubtype) {
  const auto& mission = testing::bundled_mission();
  TmOutput out(Config{}, 18);
  EventReporting events(mission, out);
  const std::array<std::uint8_t, 2> aux{0xAB, 0xCD};
  EXPECT_TRUE(events.raise(100, aux, 0));  // medium: [5,3]
  EXPECT_TRUE(events.raise(101, {}, 0));   // low: [5,2]
  EXPECT_FALSE(events.raise(555, {}, 0));  // undefined
  const auto tm = drain(out);
  EXPECT_EQ(kinds(tm), (Kinds{{5, 3}, {5, 2}}));
  EXPECT_EQ(std::get<EventReport>(tm[0].data).event_id, 100U);
  EXPECT_EQ(std::get<EventReport>(tm[0].data).aux_data.size(), 2U);
  IdList off = ids({101});
  ASSERT_FALSE(events.set_enabled(off, false).has_value());
  EXPECT_TRUE(events.raise(101, {}, 0));  // occurred, not reported
  EXPECT_EQ(out.size(), 0U);
}

FunctionCall call(std::uint64_t function, std::initializer_list<IdValue> arguments) {
  FunctionCall c;
  c.function_id = function;
  for (const IdValue& a : arguments) c.arguments.push_back(a);
  return c;
}

TEST(PusServicesFunctions, EffectsSetParameters) {
  auto app = application();
  app->receive(tc_bytes(8, 1, call(1, {}), 0, 0b1000), 0);
  EXPECT_EQ(kinds(drain(app->tm())), (Kinds{{1, 7}}));
  EXPECT_EQ(app->parameters().value(3), 0);  // heater_off
  app->receive(tc_bytes(8, 1, call(2, {{1, 2}}), 1, 0), 0);
  EXPECT_EQ(app->parameters().value(4), 2);  // set_mode(2)
  EXPECT_EQ(app->functions().performed(), 2U);
  EXPECT_EQ(app->functions().last_function(), 2U);
}

TEST(PusServicesFunctions, RefusedCalls) {
  auto app = application();
  const std::vector<std::pair<FunctionCall, std::pair<std::uint64_t, std::uint32_t>>> cases{
      {call(3, {}), {4, 3}},                // undefined function
      {call(2, {}), {5, 1}},                // argument 1 missing
      {call(2, {{1, 1}, {1, 1}}), {5, 1}},  // argument 1 twice
      {call(2, {{2, 1}}), {5, 2}},          // undefined argument 2
      {call(2, {{1, 9}}), {5, 4}},          // mode 9 is above parameter 4's maximum
      {call(1, {{1, 0}}), {5, 1}},          // heater_off takes no argument
  };
  std::uint16_t sequence = 0;
  for (const auto& [c, expected] : cases) {
    app->receive(tc_bytes(8, 1, c, sequence++, 0), 0);
    const auto tm = drain(app->tm());
    ASSERT_EQ(kinds(tm), (Kinds{{1, 4}})) << "function " << c.function_id;
    EXPECT_EQ(failure_of(tm[0]), expected) << "function " << c.function_id;
  }
  EXPECT_EQ(app->functions().performed(), 0U);
  EXPECT_EQ(app->parameters().value(4), 0);
}

}  // namespace
}  // namespace smcbip::pus::services
