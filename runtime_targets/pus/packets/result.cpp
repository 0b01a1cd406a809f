// The stable names of refusal reasons.
#include "result.h"

namespace smcbip::pus {

std::string_view reason_name(Reason reason) {
  switch (reason) {
    case Reason::TooShort:
      return "too-short";
    case Reason::LengthMismatch:
      return "length-mismatch";
    case Reason::BadCrc:
      return "bad-crc";
    case Reason::WrongVersion:
      return "wrong-version";
    case Reason::WrongPusVersion:
      return "wrong-pus-version";
    case Reason::WrongPacketType:
      return "wrong-packet-type";
    case Reason::NoSecondaryHeader:
      return "no-secondary-header";
    case Reason::UnknownService:
      return "unknown-service";
    case Reason::UnknownSubtype:
      return "unknown-subtype";
    case Reason::TrailingBytes:
      return "trailing-bytes";
    case Reason::BadField:
      return "bad-field";
    case Reason::CapacityExceeded:
      return "capacity-exceeded";
    case Reason::BufferTooSmall:
      return "buffer-too-small";
    case Reason::BadConfig:
      return "bad-config";
  }
  return "unknown-reason";
}

}  // namespace smcbip::pus
