// Where the on-board times sit in an encoded TM packet, for comparing two runs' packets apart
// from when they were made.
#pragma once

#include <cstddef>

#include "config.h"
#include "fixed.h"
#include "packet.h"

namespace smcbip::pus {

/// A field of an encoded packet: its first octet and its length.
struct FieldSpan {
  std::size_t offset = 0;
  std::size_t length = 0;
  friend bool operator==(const FieldSpan&, const FieldSpan&) = default;
};

/// The CUC times of the decoded TM `tm` as it encodes under `config`: the TM secondary
/// header's time (ECSS-E-ST-70-41C 7.4.3.2, after the fields before it), and for [9,2] the
/// time of the report's source data, after its rate exponent (P-field included when the
/// config has one).
FixedVector<FieldSpan, 2> tm_time_fields(const Telemetry& tm, const Config& config);

}  // namespace smcbip::pus
