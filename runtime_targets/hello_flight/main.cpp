// hello_flight: a flight loop that embeds the C++ bipc gen made of hello_flight.bip and drives it
// in real time. Every cycle it lets the model run up to the time elapsed on the platform clock;
// halfway through the mission it shortens the heart's period (a data write) and sends a
// telecommand (an event fed to an extern port). It prints the identity of the model it runs,
// each beat as it fires, and a summary; the template later runtime targets follow.
//
// Exit codes: 0 mission complete, 1 the component failed, 2 usage error.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <thread>

#include "bipc/options.h"
#include "model.h"

namespace {

using smcbip::engines::TimeValue;

struct Mission {
  int cycles = 40;             // flight-loop cycles
  int cycle_ms = 10;           // length of one cycle
  int fast_period_ms = 20;     // the heart's period after the halfway command
  int telecommand = 7;         // the code sent halfway
  bool virtual_clock = false;  // cycles follow one another without waiting (tests)
};

/// Prints the beats as they fire (the observer runs inside run_until).
class BeatLog final : public smcbip::engines::RunObserver {
 public:
  bool observe(const smcbip::engines::StepInfo& step,
               const smcbip::engines::StateView& state) override {
    if (step.fired == smcbip::engines::StepInfo::Fired::Interaction) {
      std::cout << "beat at " << step.time / 1'000'000 << " ms\n";
    } else if (step.fired == smcbip::engines::StepInfo::Fired::External) {
      std::cout << "telecommand taken at " << state.now() / 1'000'000 << " ms\n";
    }
    return true;
  }
};

int fly(const Mission& mission) {
  hello_flight::Component heart;
  std::cout << "hello_flight: running model " << hello_flight::Component::model_hash() << "\n";
  const auto period = heart.find_data("ROOT.heart", "period");
  const auto beats = heart.find_data("ROOT.heart", "beats");
  const auto command = heart.find_data("ROOT.heart", "last_command");
  const auto telecommand = heart.find_port("ROOT.heart", "command");
  if (!period || !beats || !command || !telecommand) {
    std::cerr << "hello_flight: the model lacks the heart's data or ports\n";
    return 1;
  }
  BeatLog log;
  heart.set_observer(&log);
  if (!heart.start()) {
    std::cerr << "hello_flight: cannot start: " << heart.result().message << "\n";
    return 1;
  }
  const auto launch = std::chrono::steady_clock::now();
  for (int cycle = 1; cycle <= mission.cycles; ++cycle) {
    const auto due = launch + std::chrono::milliseconds(cycle * mission.cycle_ms);
    if (!mission.virtual_clock) std::this_thread::sleep_until(due);
    const TimeValue now =
        std::chrono::duration_cast<std::chrono::nanoseconds>(due - launch).count();
    const smcbip::engines::StepOutcome outcome = heart.run_until(now);
    if (outcome.ended && outcome.end == smcbip::engines::RunEnd::Error) {
      std::cerr << "hello_flight: the component failed: " << outcome.message << "\n";
      return 1;
    }
    // Halfway, once the model has caught up with the clock: faster beats and a telecommand.
    if (cycle == mission.cycles / 2) {
      const smcbip::engines::Val code = smcbip::engines::make_int(mission.telecommand);
      if (!heart.write(period->atom, period->slot,
                       smcbip::engines::make_int(mission.fast_period_ms)) ||
          !heart.feed(telecommand->atom, telecommand->port, now, {&code, 1})) {
        std::cerr << "hello_flight: the component refused the halfway command\n";
        return 1;
      }
    }
  }
  std::cout << "mission complete at " << heart.now() / 1'000'000
            << " ms: " << heart.read(beats->atom, beats->slot).i << " beats, last telecommand "
            << heart.read(command->atom, command->slot).i << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hello_flight: a flight loop driving a generated BIP component in real time"};
  Mission mission;
  app.add_option("--cycles", mission.cycles, "flight-loop cycles")->check(CLI::PositiveNumber);
  app.add_option("--cycle-ms", mission.cycle_ms, "length of a cycle (ms)")
      ->check(CLI::PositiveNumber);
  app.add_option("--fast-period-ms", mission.fast_period_ms, "the heart's period after halfway")
      ->check(CLI::PositiveNumber);
  app.add_flag("--virtual-clock", mission.virtual_clock,
               "do not wait for the platform clock (cycles follow at once)");
  smcbip::cli::add_version_flags(app, "hello_flight");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "hello_flight: error: " << e.what() << "\n";
    return 2;
  }
  return fly(mission);
}
