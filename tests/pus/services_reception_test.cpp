// TC reception and ST01 verification, ST17, ST09 and ST20 of the on-board services. Expected
// reports follow ECSS-E-ST-70-41C 6.1 (success reports per acknowledgement flag, failures
// always) and the bundled mission, as summarised in services_test_support.h.
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

TEST(PusServicesReception, PingIsVerifiedAtEveryStageItAsksFor) {
  auto app = application();
  app->receive(tc_bytes(17, 1, NoData{}, 5), 1500);
  const auto tm = drain(app->tm());
  EXPECT_EQ(kinds(tm), (Kinds{{1, 1}, {1, 3}, {17, 2}, {1, 7}}));
  const auto& accepted = std::get<pus::Verification>(tm[0].data);
  EXPECT_EQ(accepted.request.apid, 18);
  EXPECT_EQ(accepted.request.sequence_count, 5);
  for (const Telemetry& packet : tm) {
    EXPECT_EQ(packet.primary.apid, 18);
    EXPECT_EQ(packet.header.destination_id, 7);  // the TC's source
    EXPECT_EQ(time_of(packet), 1500U);
  }
  // One sequence count over all packets; one message type counter per [service, subtype].
  EXPECT_EQ(tm[3].primary.sequence_count, 3);
  EXPECT_EQ(tm[3].header.message_type_counter, 0);
  app->receive(tc_bytes(17, 1, NoData{}, 6), 1600);
  EXPECT_EQ(drain(app->tm())[3].header.message_type_counter, 1);
}

TEST(PusServicesReception, AcknowledgementFlagsSelectTheSuccessReports) {
  auto app = application();
  app->receive(tc_bytes(17, 1, NoData{}, 0, 0b1001), 0);  // acceptance and completion
  EXPECT_EQ(kinds(drain(app->tm())), (Kinds{{1, 1}, {17, 2}, {1, 7}}));
  app->receive(tc_bytes(17, 1, NoData{}, 1, 0), 0);
  EXPECT_EQ(kinds(drain(app->tm())), (Kinds{{17, 2}}));
  // A failure is reported whatever the flags.
  app->receive(tc_bytes(20, 1, ids({99}), 2, 0), 0);
  const auto tm = drain(app->tm());
  ASSERT_EQ(kinds(tm), (Kinds{{1, 4}}));
  EXPECT_EQ(failure_of(tm[0]), std::make_pair(std::uint64_t{4}, std::uint32_t{99}));
}

TEST(PusServicesReception, EveryStageReportsItsSuccessOrFailure) {
  TmOutput out(Config{}, 18);
  services::Verification verification(out);
  Telecommand tc;
  tc.primary.apid = 18;
  tc.primary.sequence_count = 3;
  tc.header.source_id = 9;
  tc.header.ack_flags = 0b0100;  // progress only
  const Failure failure{FailureCode::InvalidArgument, 0x01020304};
  verification.accepted(tc, 0);
  verification.started(tc, 0);
  verification.progressed(tc, 2, 0);
  verification.completed(tc, 0);
  verification.start_failed(tc, failure, 0);
  verification.progress_failed(tc, 3, failure, 0);
  verification.completion_failed(tc, failure, 0);
  const auto tm = drain(out);
  // Successes as the flags ask (progress only), failures always.
  ASSERT_EQ(kinds(tm), (Kinds{{1, 5}, {1, 4}, {1, 6}, {1, 8}}));
  EXPECT_EQ(std::get<pus::Verification>(tm[0].data).step_id, 2U);
  EXPECT_EQ(std::get<pus::Verification>(tm[2].data).step_id, 3U);
  for (const Telemetry& packet : tm) {
    EXPECT_EQ(packet.header.destination_id, 9);
    EXPECT_EQ(std::get<pus::Verification>(packet.data).request, RequestId::of(tc.primary));
  }
  EXPECT_EQ(failure_of(tm[3]), std::make_pair(std::uint64_t{5}, std::uint32_t{0x01020304}));
}

TEST(PusServicesReception, MalformedTcIsRejectedWithItsReason) {
  auto app = application();
  auto bytes = tc_bytes(17, 1, NoData{}, 9);
  bytes.back() ^= 0x01;  // the CRC's last octet
  app->receive(bytes, 0);
  const auto tm = drain(app->tm());
  ASSERT_EQ(kinds(tm), (Kinds{{1, 2}}));
  // Datum: the reason (BadCrc = 2) in the third octet, the offset (11 = the CRC of this
  // 13-octet packet) in the last two.
  EXPECT_EQ(failure_of(tm[0]), std::make_pair(std::uint64_t{1}, std::uint32_t{0x0002000B}));
  EXPECT_EQ(std::get<pus::Verification>(tm[0].data).request.sequence_count, 9);
  EXPECT_EQ(app->reception().rejected(), 1U);
  // Too short for a request ID: rejected with a zero request ID.
  app->receive(std::vector<std::uint8_t>{0x18, 0x12}, 0);
  const auto short_tm = drain(app->tm());
  ASSERT_EQ(kinds(short_tm), (Kinds{{1, 2}}));
  EXPECT_EQ(std::get<pus::Verification>(short_tm[0].data).request, RequestId{});
}

TEST(PusServicesReception, TcOfAnotherApplicationIsRejected) {
  auto app = application();
  app->receive(tc_bytes(17, 1, NoData{}, 0, 0xF, 0x33), 0);
  const auto tm = drain(app->tm());
  ASSERT_EQ(kinds(tm), (Kinds{{1, 2}}));
  EXPECT_EQ(failure_of(tm[0]), std::make_pair(std::uint64_t{2}, std::uint32_t{0x33}));
}

TEST(PusServicesTime, OnboardTimeAsCuc) {
  // Two fine octets: half a second is 2^15 units; 1 ms is 65.536 units, rounded to 66.
  EXPECT_EQ(to_cuc(1500, Config{}), (CucTime{1, 32768}));
  EXPECT_EQ(to_cuc(2001, Config{}), (CucTime{2, 66}));
  EXPECT_EQ(to_cuc(999'999, Config{}), (CucTime{999, 65470}));
  for (Millis t = 0; t < 3000; ++t) EXPECT_EQ(to_millis(to_cuc(t, Config{}), Config{}), t);
}

TEST(PusServicesTime, ReportsEveryTwoToTheRatePeriods) {
  auto app = application();
  // Base period 1000 ms from start: reports at 1000, 2000, 3000.
  app->tick(3500);
  auto tm = only(drain(app->tm()), 9, 2);
  ASSERT_EQ(kinds(tm), (Kinds{{9, 2}, {9, 2}, {9, 2}}));
  EXPECT_EQ(time_of(tm[2]), 3000U);
  EXPECT_EQ(std::get<TimeReport>(tm[2].data).time, to_cuc(3000, Config{}));
  // Rate 2 from 3500: every 4000 ms, first at 7500.
  app->receive(tc_bytes(9, 1, TimeReportRate{2}, 0, 0), 3500);
  app->tick(11499);
  tm = only(drain(app->tm()), 9, 2);
  ASSERT_EQ(kinds(tm), (Kinds{{9, 2}}));
  EXPECT_EQ(time_of(tm[0]), 7500U);
  EXPECT_EQ(std::get<TimeReport>(tm[0].data).rate_exponent, 2);
}

TEST(PusServicesParameters, ReportAndSetWithinLimits) {
  auto app = application();
  app->receive(tc_bytes(20, 1, ids({1, 2}), 0, 0), 0);
  auto tm = drain(app->tm());
  ASSERT_EQ(kinds(tm), (Kinds{{20, 2}}));
  // 28.0 as binary32 is 0x41E00000; 20 as int32 is 0x14.
  ParameterValues expected;
  expected.values.push_back(IdValue{1, 0x41E00000});
  expected.values.push_back(IdValue{2, 0x14});
  EXPECT_EQ(std::get<ParameterValues>(tm[0].data), expected);

  ParameterValues set;
  set.values.push_back(IdValue{2, 0xFFFFFFF6});  // -10
  set.values.push_back(IdValue{4, 7});           // mode 7 is above its maximum 3
  app->receive(tc_bytes(20, 3, set, 1, 0), 0);
  tm = drain(app->tm());
  ASSERT_EQ(kinds(tm), (Kinds{{1, 4}}));
  EXPECT_EQ(failure_of(tm[0]), std::make_pair(std::uint64_t{5}, std::uint32_t{4}));
  EXPECT_EQ(app->parameters().value(2), 20);  // nothing set

  set.values[1].value = 3;
  app->receive(tc_bytes(20, 3, set, 2, 0b1000), 0);
  EXPECT_EQ(kinds(drain(app->tm())), (Kinds{{1, 7}}));
  EXPECT_EQ(app->parameters().value(2), -10);
  EXPECT_EQ(app->parameters().value(4), 3);
  // A bool holds 0 or 1 only.
  ParameterValues bad_bool;
  bad_bool.values.push_back(IdValue{3, 2});
  app->receive(tc_bytes(20, 3, bad_bool, 3, 0), 0);
  EXPECT_EQ(kinds(drain(app->tm())), (Kinds{{1, 4}}));
}

}  // namespace
}  // namespace smcbip::pus::services
