// Which configured width an ID list of a given service uses, and which ST01 fields a subtype has.
#pragma once

#include <cstddef>
#include <cstdint>

#include "../config.h"

namespace smcbip::pus::detail {

/// The width of the IDs in an ID list of `service`.
inline std::size_t id_width(std::uint8_t service, const Config& c) {
  switch (service) {
    case 3:
      return c.structure_id_bytes;
    case 5:
    case 19:
      return c.event_id_bytes;
    case 12:
      return c.pmon_id_bytes;
    default:
      return c.parameter_id_bytes;
  }
}

/// ST01 subtypes 5 and 6 carry a step ID.
inline bool has_step_id(std::uint8_t subtype) { return subtype == 5 || subtype == 6; }
/// ST01 even subtypes report failures and carry a failure notice.
inline bool has_failure_notice(std::uint8_t subtype) { return subtype % 2 == 0; }

}  // namespace smcbip::pus::detail
