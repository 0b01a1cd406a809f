// The on-board UDP endpoint (POSIX sockets).
#include "onboard/udp_endpoint.h"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace smcbip::pus::onboard {

UdpEndpoint::UdpEndpoint(std::uint16_t port) {
  socket_ = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (socket_ < 0) throw std::system_error(errno, std::generic_category(), "socket");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const int error = errno;
    ::close(socket_);
    throw std::system_error(error, std::generic_category(), "bind");
  }
  socklen_t length = sizeof address;
  ::getsockname(socket_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
}

UdpEndpoint::~UdpEndpoint() { ::close(socket_); }

std::optional<std::span<const std::uint8_t>> UdpEndpoint::receive(
    std::chrono::milliseconds timeout) {
  pollfd ready{socket_, POLLIN, 0};
  if (::poll(&ready, 1, static_cast<int>(timeout.count())) <= 0) return std::nullopt;
  sockaddr_in from{};
  socklen_t length = sizeof from;
  const ssize_t got = ::recvfrom(socket_, buffer_.data(), buffer_.size(), 0,
                                 reinterpret_cast<sockaddr*>(&from), &length);
  if (got < 0) return std::nullopt;
  peer_ = from;
  return std::span<const std::uint8_t>(buffer_.data(), static_cast<std::size_t>(got));
}

bool UdpEndpoint::send(std::span<const std::uint8_t> bytes) {
  if (!peer_) return false;
  return ::sendto(socket_, bytes.data(), bytes.size(), 0,
                  reinterpret_cast<const sockaddr*>(&*peer_),
                  sizeof *peer_) == static_cast<ssize_t>(bytes.size());
}

}  // namespace smcbip::pus::onboard
