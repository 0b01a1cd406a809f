// CUC time encoding, and the config checks that bound its widths.
#include "cuc_time.h"

namespace smcbip::pus {

std::size_t cuc_length(const Config& config) {
  return (config.cuc_p_field ? 1u : 0u) + config.cuc_coarse_bytes + config.cuc_fine_bytes;
}

Result<Done> validate(const Config& c) {
  if (c.cuc_coarse_bytes < 1 || c.cuc_coarse_bytes > 4) {
    return fail(Reason::BadConfig, "CUC coarse time takes 1 to 4 octets");
  }
  if (c.cuc_time_code != 0b001 && c.cuc_time_code != 0b010) {
    return fail(Reason::BadConfig, "CUC time code ID is 0b001 or 0b010");
  }
  if (c.cuc_fine_bytes > 3) return fail(Reason::BadConfig, "CUC fine time takes 0 to 3 octets");
  if (c.count_bytes < 1 || c.count_bytes > 2) {
    return fail(Reason::BadConfig, "the count field N takes 1 or 2 octets");
  }
  for (std::uint8_t width : {c.failure_code_bytes, c.step_id_bytes, c.structure_id_bytes,
                             c.event_id_bytes, c.function_id_bytes, c.argument_id_bytes,
                             c.parameter_id_bytes, c.value_bytes, c.pmon_id_bytes}) {
    if (width < 1 || width > 8) return fail(Reason::BadConfig, "field widths are 1 to 8 octets");
  }
  return Done{};
}

std::uint8_t cuc_p_field(const Config& config) {
  return static_cast<std::uint8_t>(config.cuc_time_code << 4 | (config.cuc_coarse_bytes - 1) << 2 |
                                   config.cuc_fine_bytes);
}

Result<Done> encode_cuc(const CucTime& time, const Config& config, detail::Writer& out) {
  if (config.cuc_p_field) SMCBIP_PUS_TRY(out.uint(cuc_p_field(config), 1));
  SMCBIP_PUS_TRY(out.uint(time.coarse, config.cuc_coarse_bytes));
  if (config.cuc_fine_bytes == 0) {
    if (time.fine != 0) return fail(Reason::BadField, "fine time without fine octets");
    return Done{};
  }
  return out.uint(time.fine, config.cuc_fine_bytes);
}

Result<CucTime> decode_cuc(const Config& config, detail::Reader& in) {
  if (config.cuc_p_field) {
    const std::size_t at = in.offset();
    auto p = in.uint(1);
    if (!p) return p.error();
    if (p.value() != cuc_p_field(config)) {
      return fail(Reason::BadField, "CUC P-field does not match the configured format", at);
    }
  }
  CucTime time;
  auto coarse = in.uint(config.cuc_coarse_bytes);
  if (!coarse) return coarse.error();
  time.coarse = static_cast<std::uint32_t>(coarse.value());
  if (config.cuc_fine_bytes > 0) {
    auto fine = in.uint(config.cuc_fine_bytes);
    if (!fine) return fine.error();
    time.fine = static_cast<std::uint32_t>(fine.value());
  }
  return time;
}

Result<std::size_t> encode_cuc(const CucTime& time, const Config& config,
                               std::span<std::uint8_t> out) {
  SMCBIP_PUS_TRY(validate(config));
  detail::Writer writer(out);
  SMCBIP_PUS_TRY(encode_cuc(time, config, writer));
  return writer.written();
}

Result<CucTime> decode_cuc(const Config& config, std::span<const std::uint8_t> bytes) {
  SMCBIP_PUS_TRY(validate(config));
  detail::Reader reader(bytes);
  return decode_cuc(config, reader);
}

}  // namespace smcbip::pus
