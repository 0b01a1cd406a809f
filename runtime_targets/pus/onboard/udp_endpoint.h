// The on-board end of the UDP link: a socket bound on the loopback that answers whoever sent
// the latest TC.
#pragma once

#include <netinet/in.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>

namespace smcbip::pus::onboard {

/// A UDP socket bound to 127.0.0.1:port (0: a port of the system's choosing); one packet per
/// datagram. TM goes to the address the latest TC came from (nowhere before the first).
class UdpEndpoint {
 public:
  /// Throws std::system_error when the socket cannot be made or bound.
  explicit UdpEndpoint(std::uint16_t port);
  ~UdpEndpoint();
  UdpEndpoint(const UdpEndpoint&) = delete;
  UdpEndpoint& operator=(const UdpEndpoint&) = delete;

  /// The port bound.
  std::uint16_t port() const { return port_; }
  /// The next datagram, waiting at most `timeout`; its octets stay valid until the next call.
  std::optional<std::span<const std::uint8_t>> receive(std::chrono::milliseconds timeout);
  /// Sends one packet to the latest TC's sender; false if there is none yet or sending failed.
  bool send(std::span<const std::uint8_t> bytes);

 private:
  int socket_ = -1;
  std::uint16_t port_ = 0;
  std::optional<sockaddr_in> peer_;
  std::array<std::uint8_t, 65536> buffer_{};
};

}  // namespace smcbip::pus::onboard
