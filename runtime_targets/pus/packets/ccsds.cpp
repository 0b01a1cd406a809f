// Encoding and decoding of the CCSDS primary header and of the ST01 request ID.
#include "ccsds.h"

namespace smcbip::pus {
namespace {

// Packet identification and sequence control, the first four octets.
std::array<std::uint8_t, 4> pack_id_and_control(std::uint8_t version, PacketType type,
                                                bool secondary, std::uint16_t apid,
                                                SequenceFlags flags, std::uint16_t count) {
  const auto id =
      static_cast<std::uint16_t>((version & 0x7) << 13 | static_cast<unsigned>(type) << 12 |
                                 (secondary ? 1u : 0u) << 11 | (apid & kMaxApid));
  const auto control =
      static_cast<std::uint16_t>(static_cast<unsigned>(flags) << 14 | (count & kMaxSequenceCount));
  return {static_cast<std::uint8_t>(id >> 8), static_cast<std::uint8_t>(id),
          static_cast<std::uint8_t>(control >> 8), static_cast<std::uint8_t>(control)};
}

RequestId unpack_id_and_control(std::span<const std::uint8_t, 4> b) {
  const auto id = static_cast<std::uint16_t>(b[0] << 8 | b[1]);
  const auto control = static_cast<std::uint16_t>(b[2] << 8 | b[3]);
  RequestId out;
  out.version = static_cast<std::uint8_t>(id >> 13);
  out.type = static_cast<PacketType>((id >> 12) & 1);
  out.secondary_header = ((id >> 11) & 1) != 0;
  out.apid = id & kMaxApid;
  out.sequence_flags = static_cast<SequenceFlags>(control >> 14);
  out.sequence_count = control & kMaxSequenceCount;
  return out;
}

}  // namespace

Result<Done> encode_primary_header(const PrimaryHeader& h, std::span<std::uint8_t> out) {
  if (out.size() < kPrimaryHeaderLength) return fail(Reason::BufferTooSmall, "output full");
  if (h.version > 7) return fail(Reason::BadField, "packet version exceeds 3 bits", 0);
  if (h.apid > kMaxApid) return fail(Reason::BadField, "APID exceeds 11 bits", 0);
  if (h.sequence_count > kMaxSequenceCount) {
    return fail(Reason::BadField, "sequence count exceeds 14 bits", 2);
  }
  const auto first = pack_id_and_control(h.version, h.type, h.secondary_header, h.apid,
                                         h.sequence_flags, h.sequence_count);
  for (std::size_t i = 0; i < 4; ++i) out[i] = first[i];
  out[4] = static_cast<std::uint8_t>(h.data_length >> 8);
  out[5] = static_cast<std::uint8_t>(h.data_length);
  return Done{};
}

Result<PrimaryHeader> decode_primary_header(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kPrimaryHeaderLength) {
    return fail(Reason::TooShort, "fewer than 6 octets for the primary header", bytes.size());
  }
  const RequestId first = unpack_id_and_control(bytes.first<4>());
  PrimaryHeader h;
  h.version = first.version;
  h.type = first.type;
  h.secondary_header = first.secondary_header;
  h.apid = first.apid;
  h.sequence_flags = first.sequence_flags;
  h.sequence_count = first.sequence_count;
  h.data_length = static_cast<std::uint16_t>(bytes[4] << 8 | bytes[5]);
  return h;
}

RequestId RequestId::of(const PrimaryHeader& tc) {
  return RequestId{tc.version, tc.type,           tc.secondary_header,
                   tc.apid,    tc.sequence_flags, tc.sequence_count};
}

std::array<std::uint8_t, 4> encode_request_id(const RequestId& id) {
  return pack_id_and_control(id.version, id.type, id.secondary_header, id.apid, id.sequence_flags,
                             id.sequence_count);
}

RequestId decode_request_id(std::span<const std::uint8_t, 4> bytes) {
  return unpack_id_and_control(bytes);
}

}  // namespace smcbip::pus
