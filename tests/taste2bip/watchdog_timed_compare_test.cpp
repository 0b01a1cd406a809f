// The translation of the watchdog design against the original translator's BIP in timed runs
// (default semantics): the SDL functions' calls that do not pass through the C++ function
// Watchdog happen at the same dates; what BLSClient gets through Watchdog is printed, since the
// translation's Watchdog is an abstract atom (it may skip a relay, or send on its cyclic purge,
// with its own data, which nothing sets) where the original's relays each command.
#include <gtest/gtest.h>

#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "engines/engines.h"
#include "tests/taste2bip/watchdog_model.h"
#include "tests/taste2bip/watchdog_translation.h"

namespace smcbip::taste2bip::test {
namespace {

constexpr engines::TimeValue kMs = 1'000'000;  // engine time is in nanoseconds
constexpr double kHorizon = 1000;              // ms: ten periods of the joystick

/// The dates (ms) of each observed call before kHorizon, and the model's output.
struct CallDates {
  std::map<std::string, std::vector<double>> dates;
  std::string output;
};

class CallRecorder final : public engines::RunObserver {
 public:
  CallRecorder(const WatchdogObservation& observation, CallDates& out)
      : observation_(observation), out_(out) {}
  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    const double date = static_cast<double>(step.time) / kMs;
    if (date >= kHorizon) return false;
    if (step.fired != engines::StepInfo::Fired::Interaction) return true;
    const bipc::ir::System& system = state.system();
    for (const std::vector<bipc::ir::PortRef>& bound : system.connectors[step.connector].bound) {
      for (const bipc::ir::PortRef& ref : bound) {
        if (ref.kind != bipc::ir::PortRef::Kind::Atom) continue;
        const bipc::ir::AtomInstance& atom = system.atoms[ref.instance];
        const std::string name =
            atom.path + "." + system.atom_types[atom.type].ports[ref.port].name;
        const auto it = observation_.ports.find(name);
        if (it != observation_.ports.end()) out_.dates[it->second].push_back(date);
      }
    }
    return true;
  }

 private:
  const WatchdogObservation& observation_;
  CallDates& out_;
};

CallDates timed_calls(const bipc::ir::System& system, const WatchdogObservation& observation) {
  CallDates calls;
  engines::SimulateOptions options;
  options.seed = 3;
  options.limit = 100'000;  // the recorder stops the run at kHorizon
  const engines::Externs externs = watchdog_externs();
  engines::Simulator simulator(system, options, externs);
  EXPECT_EQ(simulator.problem(), "");
  std::ostringstream trace, model;
  CallRecorder recorder(observation, calls);
  const engines::RunResult result = simulator.run(0, engines::RunStreams{trace, model}, &recorder);
  EXPECT_EQ(result.end, engines::RunEnd::Stopped) << result.message;
  calls.output = model.str();
  return calls;
}

std::string dates_text(const std::vector<double>& dates) {
  std::ostringstream out;
  for (const double d : dates) out << " " << d;
  return out.str();
}

std::size_t count(const std::string& text, const std::string& line) {
  std::size_t n = 0;
  for (std::size_t at = text.find(line); at != std::string::npos; at = text.find(line, at + 1)) {
    ++n;
  }
  return n;
}

TEST(WatchdogTimedCompare, TheSdlCallsHappenAtTheOriginalsDates) {
  WATCHDOG_SKIP_WITHOUT_DATA();
  const BothModels both = load_both();
  ASSERT_TRUE(both.original && both.translation);
  const CallDates original =
      timed_calls(*both.original, watchdog_observation(WatchdogNaming::Original, true, false));
  const CallDates translation = timed_calls(*both.translation, translation_observation(true));
  // Every call in the joystick's chain happens at its step's date: 0, 100, ..., 900 ms.
  std::vector<double> periods;
  for (int k = 0; k < 10; ++k) periods.push_back(100.0 * k);
  for (const char* label :
       {"JoystickDriver.step", "JoystickDriver.cmd", "CmdDispatcher.cmd", "CmdDispatcher.log_cmd",
        "CmdDispatcher.test_cmd", "Logger.log_cmd", "Watchdog.test_cmd"}) {
    EXPECT_EQ(original.dates.at(label), periods) << label;
    const auto it = translation.dates.find(label);
    ASSERT_NE(it, translation.dates.end()) << label;
    EXPECT_EQ(it->second, periods) << label;
  }
  EXPECT_EQ(original.dates.at("BLSClient.mot_cmd"), periods);
  EXPECT_EQ(count(original.output, "Command received\n"), 10u);
  EXPECT_EQ(count(original.output, "Stop command received\n"), 0u);
  // Through Watchdog: reported, not asserted (the translation's Watchdog has no body).
  std::cout << "[Watchdog differences, timed, seed 3, [0, 1000) ms]\n";
  for (const char* label : {"Watchdog.mot_cmd", "BLSClient.mot_cmd"}) {
    const auto it = translation.dates.find(label);
    std::cout << "  " << label << ": original" << dates_text(original.dates.at(label))
              << "; translation" << (it == translation.dates.end() ? "" : dates_text(it->second))
              << "\n";
  }
  std::cout << "  BLSClient's commands/stops received: original "
            << count(original.output, "Command received\n") << "/"
            << count(original.output, "Stop command received\n") << ", translation "
            << count(translation.output, "Command received\n") << "/"
            << count(translation.output, "Stop command received\n") << "\n";
}

}  // namespace
}  // namespace smcbip::taste2bip::test
