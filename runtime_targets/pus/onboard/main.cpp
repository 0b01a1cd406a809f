// pus_onboard: the deployed on-board PUS application. It embeds the component generated from
// pus_onboard.bip (its atoms calling the services' C++), drives it in real time, and links it to
// the ground over UDP on the loopback: each datagram received is a TC put in the model's uplink,
// each TM the model's downlink flushes goes back to the latest TC's sender. It prints the
// identity of the model it runs, the port it listens on, and a summary when it stops.
//
// Exit codes: 0 stopped (its duration elapsed, or SIGINT/SIGTERM), 1 the component failed,
// 2 usage error or a refused mission.
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <iostream>
#include <string>

#include "bipc/options.h"
#include "model.h"
#include "onboard/onboard_externs.hpp"
#include "onboard/udp_endpoint.h"

namespace {

namespace engines = smcbip::engines;
namespace onboard = smcbip::pus::onboard;

struct Options {
  std::string mission;
  std::uint16_t port = 0;
  std::int64_t duration_ms = 0;  // 0: until a signal
  int cycle_ms = 1;
};

std::atomic<bool> stop_requested{false};

extern "C" void request_stop(int /*signal*/) { stop_requested = true; }

/// Runs the component until the duration elapses or a signal comes.
int fly(const Options& options, const smcbip::pus::mission::Mission& mission) {
  onboard::UdpEndpoint link(options.port);
  onboard::install_mission(&mission);
  onboard::set_link([&link](std::span<const std::uint8_t> bytes) { link.send(bytes); });
  pus_onboard::Component component;
  std::cout << "pus_onboard: running model " << pus_onboard::Component::model_hash() << "\n";
  const auto active = component.find_data("ROOT.ground", "active");
  const auto waiting = component.find_data("ROOT.uplink", "waiting");
  if (!active || !waiting) {
    std::cerr << "pus_onboard: the model lacks the ground's or the uplink's data\n";
    return 1;
  }
  if (!component.start() ||
      !component.write(active->atom, active->slot, engines::make_bool(false))) {
    std::cerr << "pus_onboard: cannot start: " << component.result().message << "\n";
    return 1;
  }
  std::cout << "pus_onboard: listening on udp 127.0.0.1:" << link.port() << std::endl;
  std::uint64_t received = 0, dropped = 0;
  const auto launch = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::steady_clock::now() - launch; };
  while (!stop_requested &&
         (options.duration_ms == 0 || elapsed() < std::chrono::milliseconds(options.duration_ms))) {
    // Wait for a TC at most one cycle; take every one that came.
    for (auto timeout = std::chrono::milliseconds(options.cycle_ms);
         auto tc = link.receive(timeout); timeout = std::chrono::milliseconds(0)) {
      ++received;
      const std::int64_t queued = component.read(waiting->atom, waiting->slot).i;
      if (!onboard::push_tc(*tc) ||
          !component.write(waiting->atom, waiting->slot, engines::make_int(queued + 1))) {
        ++dropped;
      }
    }
    const engines::TimeValue now =
        std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed()).count();
    const engines::StepOutcome outcome = component.run_until(now);
    if (outcome.ended && outcome.end == engines::RunEnd::Error) {
      std::cerr << "pus_onboard: the component failed: " << outcome.message << "\n";
      return 1;
    }
  }
  std::cout << "pus_onboard: stopped at " << component.now() / 1'000'000 << " ms: " << received
            << " TCs received (" << dropped << " dropped), " << onboard::tm_sent()
            << " TM packets sent\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pus_onboard: the on-board PUS application of pus_onboard.bip, linked over UDP"};
  Options options;
  app.add_option("--mission", options.mission, "the mission configuration (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--port", options.port, "the UDP port on 127.0.0.1 (0: the system chooses)");
  app.add_option("--duration-ms", options.duration_ms, "stop after this long (0: at a signal)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--cycle-ms", options.cycle_ms, "longest wait for a TC between two model runs")
      ->check(CLI::PositiveNumber);
  smcbip::cli::add_version_flags(app, "pus_onboard");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "pus_onboard: error: " << e.what() << "\n";
    return 2;
  }
  const auto loaded = smcbip::pus::mission::load_mission(options.mission);
  if (!loaded.mission) {
    std::cerr << smcbip::pus::mission::format_diagnostics(options.mission, loaded.diagnostics);
    return 2;
  }
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  try {
    return fly(options, *loaded.mission);
  } catch (const std::exception& e) {
    std::cerr << "pus_onboard: error: " << e.what() << "\n";
    return 1;
  }
}
