// Locating the CUC times of a TM.
#include "time_fields.h"

#include <variant>

#include "ccsds.h"
#include "pus_headers.h"

namespace smcbip::pus {

namespace {
/// The TM secondary header before its time: PUS version and time reference status (one
/// octet), service, subtype, message type counter (two octets), destination ID (two).
constexpr std::size_t kTmHeaderBeforeTime = 7;
/// [9,2]'s rate exponential value, before the time.
constexpr std::size_t kRateExponentLength = 1;
}  // namespace

FixedVector<FieldSpan, 2> tm_time_fields(const Telemetry& tm, const Config& config) {
  FixedVector<FieldSpan, 2> fields;
  const std::size_t time_length = cuc_length(config);
  fields.push_back({kPrimaryHeaderLength + kTmHeaderBeforeTime, time_length});
  if (std::holds_alternative<TimeReport>(tm.data)) {
    fields.push_back(
        {kPrimaryHeaderLength + tm_secondary_header_length(config) + kRateExponentLength,
         time_length});
  }
  return fields;
}

}  // namespace smcbip::pus
