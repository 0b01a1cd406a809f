// The original translator's watchdog BIP, adapted (watchdog_model.h), runs in this project's
// engines with its default timed semantics: the cyclic joystick command reaches BLSClient each
// 100 ms period, and a lost heartbeat makes the watchdog send a stop command.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "engines/engines.h"
#include "tests/taste2bip/shared_data.h"
#include "tests/taste2bip/watchdog_model.h"

namespace smcbip::taste2bip::test {
namespace {

constexpr engines::TimeValue kMs = 1'000'000;  // engine time is in nanoseconds

/// What BLSClient received (date in ms, record) and the run's end.
struct Deliveries {
  std::vector<std::pair<double, Motion2D>> received;
  std::uint64_t steps = 0;
};

class DeliveryRecorder final : public engines::RunObserver {
 public:
  explicit DeliveryRecorder(Deliveries& out) : out_(out) {}
  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    const bipc::ir::System& system = state.system();
    out_.steps = step.step;
    if (step.fired != engines::StepInfo::Fired::Interaction ||
        system.connectors[step.connector].path != "BLSClient_mot_cmd2BLSClient") {
      return true;
    }
    for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
      if (system.atoms[a].path != "BLSClient") continue;
      const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
      for (bipc::ir::Index slot = 0; slot < type.data.size(); ++slot) {
        if (type.data[slot].name != "BLSClient_mot_cmd_cmd_val") continue;
        out_.received.emplace_back(static_cast<double>(step.time) / kMs,
                                   motion2d_value(state.data(a, slot).i));
      }
    }
    return true;
  }

 private:
  Deliveries& out_;
};

/// `steps` steps of the adapted original (without its fault transitions when `nominal`).
Deliveries run_original(bool nominal, std::uint64_t steps, std::uint64_t seed,
                        std::string& output) {
  Deliveries deliveries;
  std::string why;
  std::optional<bipc::ir::System> system = load_watchdog_original(why);
  EXPECT_TRUE(system) << why;
  if (!system) return deliveries;
  if (nominal) remove_fault_transitions(*system);
  engines::SimulateOptions options;
  options.seed = seed;
  options.limit = steps;
  const engines::Externs externs = watchdog_externs();  // the simulator refers to it
  engines::Simulator simulator(*system, options, externs);
  EXPECT_EQ(simulator.problem(), "");
  std::ostringstream trace, model;
  DeliveryRecorder recorder(deliveries);
  const engines::RunResult result = simulator.run(0, engines::RunStreams{trace, model}, &recorder);
  EXPECT_EQ(result.code, engines::kRunOk) << result.message;
  EXPECT_EQ(result.end, engines::RunEnd::Limit) << result.message;
  output = model.str();
  return deliveries;
}

TEST(WatchdogOriginal, AdaptationAppliesExactlyAndLoads) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  std::string why;
  const std::optional<std::string> text =
      watchdog_adapted_text(file_text(watchdog_original_file()), why);
  ASSERT_TRUE(text) << why;
  EXPECT_NE(text->find("v = set_translation(v,2.0);"), std::string::npos);
  EXPECT_NE(text->find("r.v = front(s.q); s.q = pop_front(s.q);"), std::string::npos);
  EXPECT_FALSE(watchdog_adapted_text("package P end", why)) << "an adaptation that matches "
                                                               "nothing must be refused";
  EXPECT_TRUE(load_watchdog_original(why)) << why;
}

TEST(WatchdogOriginal, TheJoystickCommandReachesBlsClientEachPeriod) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  std::string output;
  const Deliveries d = run_original(/*nominal=*/true, 400, 7, output);
  ASSERT_EQ(d.steps, 400u);
  // Each period's computation takes no model time: the command arrives at the step's date.
  ASSERT_GE(d.received.size(), 15u) << "fewer periods than expected in 400 steps";
  for (std::size_t k = 0; k < d.received.size(); ++k) {
    EXPECT_DOUBLE_EQ(d.received[k].first, 100.0 * static_cast<double>(k)) << "period " << k;
    EXPECT_EQ(d.received[k].second, (Motion2D{2.0, 3.0, 0.5})) << "period " << k;
  }
  EXPECT_NE(output.find("Logging 2 3 0.5\n"), std::string::npos) << output;
  EXPECT_NE(output.find("Command received\n"), std::string::npos);
  EXPECT_EQ(output.find("Stop command received"), std::string::npos) << "no heartbeat is lost";
}

TEST(WatchdogOriginal, ALostHeartbeatMakesTheWatchdogSendStop) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  std::string output;
  const Deliveries d = run_original(/*nominal=*/false, 400, 7, output);
  // fault1 is enabled while JoystickDriver's clock is below 100 ms and is lazy: the engines
  // plan it in its window cut to the date of the urgent steps, so it fires in the first
  // period (at 0 ms, among its instantaneous steps). The last command reached the watchdog at
  // 0 ms: it times out 110 ms later and sends the stop.
  bool stopped = false;
  for (const auto& [date, record] : d.received) {
    if (record != Motion2D{}) continue;
    EXPECT_NEAR(date, 110.0, 1e-3) << "the first stop comes 110 ms after the last command";
    stopped = true;
    break;
  }
  EXPECT_TRUE(stopped) << "no stop command reached BLSClient";
  EXPECT_NE(output.find("Stop command received\n"), std::string::npos) << output;
}

}  // namespace
}  // namespace smcbip::taste2bip::test
