// Mission-specific field widths of the packet library (what ECSS-E-ST-70-41C leaves open).
#pragma once

#include <cstddef>
#include <cstdint>

#include "result.h"

namespace smcbip::pus {

/// Widths in bytes of the fields the standard declares mission-specific, with this project's
/// defaults. The fixed fields (primary header, PUS-C secondary headers, request ID) are not here.
struct Config {
  /// CUC time: octets of coarse time (1..4) and of fine time (0..3), CCSDS 301.0-B-4 section 3.2.
  std::uint8_t cuc_coarse_bytes = 4;
  std::uint8_t cuc_fine_bytes = 2;
  /// Whether each CUC time is preceded by its one-octet P-field, and the time code ID that
  /// P-field declares: 0b010 agency-defined epoch (the default), 0b001 CCSDS epoch (1958).
  bool cuc_p_field = false;
  std::uint8_t cuc_time_code = 0b010;
  /// The field "N" that counts repeated items in a request or report (1 or 2 bytes).
  std::uint8_t count_bytes = 1;
  /// ST01 failure code and step ID (enumerated).
  std::uint8_t failure_code_bytes = 2;
  std::uint8_t step_id_bytes = 2;
  /// ST03 housekeeping parameter report structure ID.
  std::uint8_t structure_id_bytes = 2;
  /// ST05 event definition ID (also the key of an ST19 event-action definition).
  std::uint8_t event_id_bytes = 2;
  /// ST08 function ID and argument ID.
  std::uint8_t function_id_bytes = 2;
  std::uint8_t argument_id_bytes = 2;
  /// ST20/ST03 parameter ID, and the width of every parameter or argument value.
  std::uint8_t parameter_id_bytes = 2;
  std::uint8_t value_bytes = 4;
  /// ST12 parameter monitoring definition ID.
  std::uint8_t pmon_id_bytes = 2;
};

/// The encoded length of one CUC time under this config (P-field included).
std::size_t cuc_length(const Config& config);

/// Checks every width against its range (IDs and values 1..8 bytes, count 1..2, CUC as above).
Result<Done> validate(const Config& config);

}  // namespace smcbip::pus
