// Encoding and decoding of the PUS-C secondary headers.
#include "pus_headers.h"

namespace smcbip::pus {
namespace {

Result<Done> write_nibbles(std::uint8_t high, std::uint8_t low, detail::Writer& out) {
  if (high > 0xF || low > 0xF) return fail(Reason::BadField, "4-bit field exceeds its width");
  return out.uint(static_cast<std::uint8_t>(high << 4 | low), 1);
}

}  // namespace

std::size_t tm_secondary_header_length(const Config& config) { return 7 + cuc_length(config); }

Result<Done> encode_tc_secondary_header(const TcSecondaryHeader& h, detail::Writer& out) {
  SMCBIP_PUS_TRY(write_nibbles(h.pus_version, h.ack_flags, out));
  SMCBIP_PUS_TRY(out.uint(h.service, 1));
  SMCBIP_PUS_TRY(out.uint(h.subtype, 1));
  return out.uint(h.source_id, 2);
}

Result<Done> encode_tm_secondary_header(const TmSecondaryHeader& h, const Config& config,
                                        detail::Writer& out) {
  SMCBIP_PUS_TRY(write_nibbles(h.pus_version, h.time_reference_status, out));
  SMCBIP_PUS_TRY(out.uint(h.service, 1));
  SMCBIP_PUS_TRY(out.uint(h.subtype, 1));
  SMCBIP_PUS_TRY(out.uint(h.message_type_counter, 2));
  SMCBIP_PUS_TRY(out.uint(h.destination_id, 2));
  return encode_cuc(h.time, config, out);
}

Result<TcSecondaryHeader> decode_tc_secondary_header(detail::Reader& in) {
  auto fields = in.take(kTcSecondaryHeaderLength);
  if (!fields) return fields.error();
  const auto b = fields.value();
  TcSecondaryHeader h;
  h.pus_version = static_cast<std::uint8_t>(b[0] >> 4);
  h.ack_flags = static_cast<std::uint8_t>(b[0] & 0xF);
  h.service = b[1];
  h.subtype = b[2];
  h.source_id = static_cast<std::uint16_t>(b[3] << 8 | b[4]);
  return h;
}

Result<TmSecondaryHeader> decode_tm_secondary_header(const Config& config, detail::Reader& in) {
  auto fields = in.take(7);
  if (!fields) return fields.error();
  const auto b = fields.value();
  TmSecondaryHeader h;
  h.pus_version = static_cast<std::uint8_t>(b[0] >> 4);
  h.time_reference_status = static_cast<std::uint8_t>(b[0] & 0xF);
  h.service = b[1];
  h.subtype = b[2];
  h.message_type_counter = static_cast<std::uint16_t>(b[3] << 8 | b[4]);
  h.destination_id = static_cast<std::uint16_t>(b[5] << 8 | b[6]);
  auto time = decode_cuc(config, in);
  if (!time) return time.error();
  h.time = time.value();
  return h;
}

}  // namespace smcbip::pus
