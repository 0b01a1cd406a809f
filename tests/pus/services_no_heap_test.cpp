// The services' packet path allocates nothing once the application is built: a TC received,
// executed and answered, and the periodic work, under a counting global operator new.
#include <filesystem>

#include "counting_new.h"
#include "services_test_support.h"

namespace smcbip::pus::services {
namespace {

TEST(PusServicesNoHeap, ReceiveExecuteAndTickWithoutAllocating) {
  auto app = testing::application();
  ParameterValues hot;
  hot.values.push_back(IdValue{2, 80});
  const std::vector<std::vector<std::uint8_t>> requests{
      testing::tc_bytes(17, 1, NoData{}, 0), testing::tc_bytes(3, 5, testing::ids({1}), 1),
      testing::tc_bytes(20, 3, hot, 2), testing::tc_bytes(20, 1, testing::ids({1, 2, 3}), 3)};
  const std::size_t before = pus::testing::allocations.load();
  Millis now = 0;
  for (const auto& request : requests) {
    app->receive(request, now);
    // Monitoring, its event and action, housekeeping and time reports.
    now += 250;
    app->tick(now);
    while (app->tm().front() != nullptr) app->tm().pop();
  }
  EXPECT_EQ(pus::testing::allocations.load(), before);
  EXPECT_EQ(app->parameters().value(3), 0);  // the action ran
}

FixedBytes<kMaxFileString> text(const char* s) {
  FixedBytes<kMaxFileString> out;
  for (; *s != 0; ++s) out.push_back(static_cast<std::uint8_t>(*s));
  return out;
}

TEST(PusServicesNoHeap, FileManagementWithoutAllocating) {
  const auto root = std::filesystem::temp_directory_path() / "pus_no_heap_files";
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root);
  mission::Mission mission = testing::bundled_mission();
  mission.file_repository = root.string();
  Application app(mission, Config{}, 0);
  FileRequest create;
  create.file = text("a");
  create.max_size = 10;
  FileRequest copy = create;
  copy.max_size = 0;
  copy.target_file = text("b");
  FileRequest copied;
  copied.file = text("b");
  FileRequest outside = create;
  outside.repository = text("..");
  const std::vector<std::vector<std::uint8_t>> requests{
      testing::tc_bytes(23, 1, create, 0), testing::tc_bytes(23, 14, copy, 1),
      testing::tc_bytes(23, 3, copied, 2), testing::tc_bytes(23, 2, copied, 3),
      testing::tc_bytes(23, 2, copied, 4), testing::tc_bytes(23, 1, outside, 5)};
  const std::size_t before = pus::testing::allocations.load();
  for (const auto& request : requests) {
    app.receive(request, 0);
    while (app.tm().front() != nullptr) app.tm().pop();
  }
  EXPECT_EQ(pus::testing::allocations.load(), before);
  EXPECT_EQ(std::filesystem::file_size(root / "a"), 10U);
  EXPECT_FALSE(std::filesystem::exists(root / "b"));
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace smcbip::pus::services
