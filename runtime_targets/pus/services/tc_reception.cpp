// TC reception: decode, check the destination, report acceptance.
#include "tc_reception.h"

namespace smcbip::pus::services {

std::optional<Route> TcReception::route(const Telecommand& tc) {
  switch (tc.header.service) {
    case 3:
    case 5:
    case 8:
    case 9:
    case 11:
    case 12:
    case 17:
    case 19:
    case 20:
    case 23:
      return static_cast<Route>(tc.header.service);
    default:
      return std::nullopt;
  }
}

std::optional<Telecommand> TcReception::receive(std::span<const std::uint8_t> bytes, Millis now) {
  auto decoded = decode_tc(bytes, config_);
  if (!decoded) {
    // The request ID is whatever the first four octets hold: the ground matches it to its TC.
    RequestId request{};
    if (bytes.size() >= 4) request = decode_request_id(bytes.first<4>());
    const Error& error = decoded.error();
    const auto datum = static_cast<std::uint32_t>((static_cast<std::uint32_t>(error.reason) << 16) |
                                                  (error.offset & 0xFFFF));
    verification_.rejected(request, 0, Failure{FailureCode::Malformed, datum}, now);
    ++rejected_;
    return std::nullopt;
  }
  Telecommand& tc = decoded.value();
  std::optional<Failure> failure;
  if (tc.primary.apid != apid_) {
    failure = Failure{FailureCode::WrongApid, tc.primary.apid};
  } else if (!route(tc)) {
    failure = Failure{FailureCode::NotRouted, tc.header.service};
  }
  if (failure) {
    verification_.rejected(RequestId::of(tc.primary), tc.header.source_id, *failure, now);
    ++rejected_;
    return std::nullopt;
  }
  verification_.accepted(tc, now);
  ++accepted_;
  return std::move(tc);
}

}  // namespace smcbip::pus::services
