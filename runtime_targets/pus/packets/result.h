// Errors as values for the packet library: a reason, a fixed message and where it was found.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <variant>

namespace smcbip::pus {

/// Why a packet or a field was refused. The names are stable: tests and tools print them.
enum class Reason : std::uint8_t {
  TooShort,           ///< fewer bytes than the structure needs
  LengthMismatch,     ///< the packet data length field disagrees with the bytes given
  BadCrc,             ///< the packet error control does not match
  WrongVersion,       ///< CCSDS packet version number other than 0
  WrongPusVersion,    ///< PUS version number other than 2 (PUS-C)
  WrongPacketType,    ///< a TM where a TC was expected, or the reverse
  NoSecondaryHeader,  ///< the secondary header flag is clear: not a PUS packet
  UnknownService,     ///< a service type this library does not implement
  UnknownSubtype,     ///< a message subtype of a known service this library does not implement
  TrailingBytes,      ///< bytes left after the packet or after its application data
  BadField,           ///< a field holds a value out of its range or not allowed by the config
  CapacityExceeded,   ///< more items or bytes than the fixed-capacity buffers hold
  BufferTooSmall,     ///< the output span cannot hold the encoded bytes
  BadConfig,          ///< a configuration field width out of range
};

/// The stable name of a reason, e.g. "bad-crc".
std::string_view reason_name(Reason reason);

/// A refusal: the reason, a static message, and the byte offset at which it was found.
struct Error {
  Reason reason{};
  const char* message = "";
  std::size_t offset = 0;
};

/// A value or an error; no exceptions and no heap on the packet path.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}  // NOLINT(google-explicit-constructor)
  Result(Error error) : state_(error) {}         // NOLINT(google-explicit-constructor)

  /// True when a value is held.
  bool ok() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return ok(); }
  /// The value; only when ok().
  const T& value() const& { return std::get<T>(state_); }
  T& value() & { return std::get<T>(state_); }
  /// The error; only when !ok().
  const Error& error() const { return std::get<Error>(state_); }
  /// The reason of the error; only when !ok().
  Reason reason() const { return error().reason; }

 private:
  std::variant<T, Error> state_;
};

/// The value of a Result<void>-like outcome.
struct Done {};

/// Shorthand for an error value.
inline Error fail(Reason reason, const char* message, std::size_t offset = 0) {
  return Error{reason, message, offset};
}

}  // namespace smcbip::pus
