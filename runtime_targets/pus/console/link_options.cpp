// Registering the link options and opening the link they name.
#include "console/link_options.h"

#include "bipc/options.h"

namespace smcbip::pus::console {

void register_link_options(CLI::App& command, LinkOptions& options, bool port_required) {
  command.add_option("--port", options.port, "the UDP port of the on-board program")
      ->required(port_required)
      ->check(cli::integer_in(1, 65535))
      ->type_name("N");
  command.add_option("--host", options.host, "its IPv4 address")
      ->capture_default_str()
      ->type_name("ADDR");
  command
      .add_option(
          "--wait", options.wait_ms,
          "how long to receive TMs after the last TC of a script, after each TC interactively (ms)")
      ->capture_default_str()
      ->check(cli::integer_in(0, 3600000))
      ->type_name("MS");
  command.add_option("--log", options.log, "write the table to this file as well")
      ->type_name("FILE");
  command
      .add_option("--packet-log", options.packet_log,
                  "write every packet received to this file, as hex, one a line")
      ->type_name("FILE");
}

std::unique_ptr<Link> open_link(const LinkOptions& options) {
  if (options.port == 0) return nullptr;
  return std::make_unique<UdpLink>(options.host, options.port);
}

}  // namespace smcbip::pus::console
