// pus_onboard_sim: the on-board application of pus_onboard.bip simulated on a virtual clock,
// with a pus-console script as its ground. The script's TCs reach the model's uplink at the
// model times their `wait` lines space them by, through the console's own session code over a
// link that runs the model (onboard/virtual_link.h) instead of UDP; what comes back is
// tabulated as pus-console tabulates it, and --packet-log keeps the TM octets. The same
// component, options and seed as pus_onboard, so the two can be compared packet by packet.
//
// Exit codes: 0 done, 1 the component failed, 2 usage error, a refused mission or script.
#include <CLI/CLI.hpp>
#include <chrono>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "bipc/errors.h"
#include "bipc/exit_codes.h"
#include "bipc/options.h"
#include "bipc/output_file.h"
#include "bipc/tool_main.h"
#include "console/console.h"
#include "model.h"
#include "onboard/onboard_externs.hpp"
#include "onboard/virtual_link.h"

namespace {

using namespace smcbip;
namespace onboard = smcbip::pus::onboard;

struct Options {
  std::string mission, script;
  pus::console::LinkOptions link;
  std::int64_t start_ms = 0;
  int cycle_ms = 1;
};

std::string read_text(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError("cannot read this file", ErrorLocation{path});
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void write_text(const std::string& path, const std::string& text) {
  std::string error;
  if (!path.empty() && !bipc::write_file_atomically(path, text, error)) throw InputError(error);
}

int simulate(const Options& options, const pus::console::ParsedScript& script) {
  const auto loaded = pus::mission::load_mission(options.mission);
  if (!loaded.mission) {
    std::cerr << pus::mission::format_diagnostics(options.mission, loaded.diagnostics);
    return exit_codes::kInputError;
  }
  onboard::install_mission(&*loaded.mission);
  pus_onboard::Component component(pus_onboard::component_options(), std::cerr);
  const auto active = component.find_data("ROOT.ground", "active");
  const auto waiting = component.find_data("ROOT.uplink", "waiting");
  if (!active || !waiting || !component.start() ||
      !component.write(active->atom, active->slot, engines::make_bool(false))) {
    std::cerr << "pus_onboard_sim: cannot start the model: " << component.result().message << "\n";
    return 1;
  }
  onboard::VirtualLink link(component, *waiting, std::chrono::milliseconds(options.cycle_ms));
  try {
    link.run_until(options.start_ms * 1'000'000);
    pus::console::Session session(pus::Config{}, std::cout, &link);
    run_script(script, session, std::chrono::milliseconds(options.link.wait_ms));
    write_text(options.link.log, session.table());
    write_text(options.link.packet_log, session.packets());
  } catch (const std::runtime_error& e) {
    std::cerr << "pus_onboard_sim: " << e.what() << "\n";
    onboard::install_mission(nullptr);
    return 1;
  }
  std::cout << "pus_onboard_sim: model " << pus_onboard::Component::model_hash() << " stopped at "
            << component.now() / 1'000'000 << " ms: " << link.received() << " TCs received ("
            << link.dropped() << " dropped), " << onboard::tm_sent() << " TM packets sent\n";
  onboard::install_mission(nullptr);
  return exit_codes::kSuccess;
}

int run(int argc, char** argv) {
  CLI::App app{"pus_onboard_sim: pus_onboard.bip on a virtual clock, driven by a console script"};
  Options options;
  app.add_option("--mission", options.mission, "the mission configuration (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--script", options.script, "the pus-console script of TCs")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--wait", options.link.wait_ms, "model time to run after the last line (ms)")
      ->capture_default_str()
      ->check(cli::integer_in(0, 3600000));
  app.add_option("--log", options.link.log, "write the console table to this file")
      ->type_name("FILE");
  app.add_option("--packet-log", options.link.packet_log,
                 "write every TM received to this file, as hex, one a line")
      ->type_name("FILE");
  app.add_option("--start-ms", options.start_ms, "model time the script starts at")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--cycle-ms", options.cycle_ms, "model time between two runs of the model")
      ->check(CLI::PositiveNumber);
  cli::add_version_flags(app, "pus_onboard_sim");
  if (const int code = cli::parse_command_line(app, argc, argv); code >= 0) return code;
  const pus::console::ParsedScript script =
      pus::console::parse_script(read_text(options.script), pus::Config{});
  for (const auto& e : script.errors) {
    std::cerr << pus::console::format_error(options.script, e) << "\n";
  }
  if (!script.errors.empty()) return exit_codes::kInputError;
  return simulate(options, script);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::guarded_main("pus_onboard_sim", exit_codes::kJudgingCodes,
                           [&] { return run(argc, argv); });
}
