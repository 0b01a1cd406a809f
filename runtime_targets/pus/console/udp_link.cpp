// The UDP link on POSIX sockets.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "bipc/errors.h"
#include "console/link.h"

namespace smcbip::pus::console {
namespace {

[[noreturn]] void fail_with_errno(const std::string& what) {
  throw std::system_error(errno, std::generic_category(), what);
}

/// The largest UDP payload; a PUS packet is at most 65542 octets, which UDP cannot carry whole.
constexpr std::size_t kMaxDatagram = 65507;

}  // namespace

UdpLink::UdpLink(const std::string& host, std::uint16_t port)
    : peer_(host + ":" + std::to_string(port)) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  if (inet_pton(AF_INET, host.c_str(), &address.sin_addr) != 1) {
    throw UsageError("--host: expected an IPv4 address such as 127.0.0.1, got '" + host + "'");
  }
  socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (socket_ < 0) fail_with_errno("cannot open a UDP socket");
  if (::connect(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const int error = errno;
    ::close(socket_);
    throw std::system_error(error, std::generic_category(), "cannot connect to " + peer_);
  }
}

UdpLink::~UdpLink() {
  if (socket_ >= 0) ::close(socket_);
}

void UdpLink::send(std::span<const std::uint8_t> bytes) {
  const ssize_t sent = ::send(socket_, bytes.data(), bytes.size(), 0);
  if (sent < 0 && errno == ECONNREFUSED) {
    throw InputError("nothing listens on " + peer_ + " (connection refused)");
  }
  if (sent < 0) fail_with_errno("cannot send to " + peer_);
}

std::optional<std::vector<std::uint8_t>> UdpLink::receive(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd ready{socket_, POLLIN, 0};
    const int count = ::poll(&ready, 1, static_cast<int>(std::max<long long>(0, left.count())));
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) fail_with_errno("cannot wait for " + peer_);
    if (count == 0) return std::nullopt;
    std::vector<std::uint8_t> bytes(kMaxDatagram);
    const ssize_t got = ::recv(socket_, bytes.data(), bytes.size(), 0);
    if (got < 0 && errno == ECONNREFUSED) {
      throw InputError("nothing listens on " + peer_ + " (connection refused)");
    }
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail_with_errno("cannot receive from " + peer_);
    bytes.resize(static_cast<std::size_t>(got));
    return bytes;
  }
}

}  // namespace smcbip::pus::console
