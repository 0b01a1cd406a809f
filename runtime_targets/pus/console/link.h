// The transport between the console and the on-board program, and its UDP implementation.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace smcbip::pus::console {

/// Carries whole packets, one per datagram or frame.
class Link {
 public:
  virtual ~Link() = default;
  /// Sends one packet.
  virtual void send(std::span<const std::uint8_t> bytes) = 0;
  /// The next packet received within `timeout`, or nothing when the time runs out.
  virtual std::optional<std::vector<std::uint8_t>> receive(std::chrono::milliseconds timeout) = 0;
  /// The clock the session's pauses are measured on: the real one, unless the other end runs
  /// on a virtual clock that receive() advances (a simulation of the on-board program).
  virtual std::chrono::steady_clock::time_point now() const {
    return std::chrono::steady_clock::now();
  }
};

/// A UDP socket connected to HOST:PORT (an IPv4 address, e.g. the loopback), bound to a port of
/// the system's choosing: each packet is one datagram, and only datagrams from HOST:PORT are
/// received. Throws InputError for a host that is not an IPv4 address or a refused connection
/// (nothing listens on the port), std::system_error for other socket failures.
class UdpLink final : public Link {
 public:
  UdpLink(const std::string& host, std::uint16_t port);
  ~UdpLink() override;
  UdpLink(const UdpLink&) = delete;
  UdpLink& operator=(const UdpLink&) = delete;

  void send(std::span<const std::uint8_t> bytes) override;
  std::optional<std::vector<std::uint8_t>> receive(std::chrono::milliseconds timeout) override;

 private:
  int socket_ = -1;
  std::string peer_;
};

}  // namespace smcbip::pus::console
