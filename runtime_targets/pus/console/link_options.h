// The options of the commands that talk to the on-board program, declared once.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <string>

#include "console/link.h"

namespace smcbip::pus::console {

/// Where the on-board program listens, how long to receive after the last TC, where to log.
struct LinkOptions {
  std::uint16_t port = 0;  ///< 0: no link (a script's TCs are only listed)
  std::string host = "127.0.0.1";
  unsigned wait_ms = 1000;
  std::string log;
  std::string packet_log;  ///< every packet received, as hex, one a line
};

/// Registers --port (required or not), --host, --wait, --log and --packet-log on a (sub)command.
void register_link_options(CLI::App& command, LinkOptions& options, bool port_required);

/// The UDP link the options name, or none without a port.
std::unique_ptr<Link> open_link(const LinkOptions& options);

}  // namespace smcbip::pus::console
