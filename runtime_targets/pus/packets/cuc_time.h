// CCSDS Unsegmented time Code (CUC, CCSDS 301.0-B-4 section 3.2), as PUS-C carries it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "config.h"
#include "detail/byte_io.h"
#include "result.h"

namespace smcbip::pus {

/// A CUC time: whole seconds (`coarse`) and binary fractions of a second (`fine`, in units of
/// 2^-(8 * fine bytes) s), with the widths of the config.
struct CucTime {
  std::uint32_t coarse = 0;
  std::uint32_t fine = 0;
  friend bool operator==(const CucTime&, const CucTime&) = default;
};

/// The P-field of a CUC time with the config's time code and widths: bit 7 extension 0,
/// bits 6..4 time code ID, bits 3..2 coarse octets - 1, bits 1..0 fine octets.
std::uint8_t cuc_p_field(const Config& config);

/// Writes the time at the start of `out` (P-field first if the config asks for one); returns
/// the octets written.
Result<std::size_t> encode_cuc(const CucTime& time, const Config& config,
                               std::span<std::uint8_t> out);

/// Reads a time from the start of `bytes`; BadField if the P-field does not describe the
/// config's format, TooShort if the octets run out.
Result<CucTime> decode_cuc(const Config& config, std::span<const std::uint8_t> bytes);

/// Appends the time (P-field first if the config asks for one).
Result<Done> encode_cuc(const CucTime& time, const Config& config, detail::Writer& out);

/// Reads a time; BadField if the P-field does not describe the config's format.
Result<CucTime> decode_cuc(const Config& config, detail::Reader& in);

}  // namespace smcbip::pus
