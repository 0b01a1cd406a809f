// Big-endian readers and writers over spans, refusing overruns with an error value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "../result.h"

namespace smcbip::pus::detail {

/// Reads big-endian unsigned fields from a span; every read is bounds-checked.
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> bytes, std::size_t base_offset = 0)
      : bytes_(bytes), base_(base_offset) {}

  /// An unsigned integer of `width` bytes (1..8), or TooShort.
  Result<std::uint64_t> uint(std::size_t width) {
    if (remaining() < width) return fail(Reason::TooShort, "field runs past the end", offset());
    std::uint64_t value = 0;
    for (std::size_t i = 0; i < width; ++i) value = (value << 8) | bytes_[pos_ + i];
    pos_ += width;
    return value;
  }
  /// The next `count` bytes, or TooShort.
  Result<std::span<const std::uint8_t>> take(std::size_t count) {
    if (remaining() < count) return fail(Reason::TooShort, "data runs past the end", offset());
    auto out = bytes_.subspan(pos_, count);
    pos_ += count;
    return out;
  }
  /// Everything not read yet.
  std::span<const std::uint8_t> rest() {
    auto out = bytes_.subspan(pos_);
    pos_ = bytes_.size();
    return out;
  }
  std::span<const std::uint8_t> peek_rest() const { return bytes_.subspan(pos_); }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  /// The offset of the next byte, counted from the start of the packet.
  std::size_t offset() const { return base_ + pos_; }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t base_;
  std::size_t pos_ = 0;
};

/// Writes big-endian unsigned fields into a span; every write is bounds-checked.
class Writer {
 public:
  explicit Writer(std::span<std::uint8_t> out) : out_(out) {}

  /// Writes the low `width` bytes of `value`; BadField if it does not fit in them.
  Result<Done> uint(std::uint64_t value, std::size_t width) {
    if (width < 8 && (value >> (8 * width)) != 0) {
      return fail(Reason::BadField, "value does not fit its field", pos_);
    }
    if (out_.size() - pos_ < width) return fail(Reason::BufferTooSmall, "output full", pos_);
    for (std::size_t i = 0; i < width; ++i) {
      out_[pos_ + i] = static_cast<std::uint8_t>(value >> (8 * (width - 1 - i)));
    }
    pos_ += width;
    return Done{};
  }
  /// Copies bytes.
  Result<Done> bytes(std::span<const std::uint8_t> data) {
    if (out_.size() - pos_ < data.size()) {
      return fail(Reason::BufferTooSmall, "output full", pos_);
    }
    for (std::size_t i = 0; i < data.size(); ++i) out_[pos_ + i] = data[i];
    pos_ += data.size();
    return Done{};
  }
  std::size_t written() const { return pos_; }
  std::span<std::uint8_t> rest() { return out_.subspan(pos_); }
  void advance(std::size_t count) { pos_ += count; }

 private:
  std::span<std::uint8_t> out_;
  std::size_t pos_ = 0;
};

}  // namespace smcbip::pus::detail

/// Returns the error of a Result expression from the enclosing function.
#define SMCBIP_PUS_TRY(expr)                                   \
  do {                                                         \
    auto pus_try_result_ = (expr);                             \
    if (!pus_try_result_.ok()) return pus_try_result_.error(); \
  } while (false)
