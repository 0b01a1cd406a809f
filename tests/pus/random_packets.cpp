// Random valid PUS packets: every field drawn within the width the config gives it.
#include "random_packets.h"

#include <array>

#include "packets/detail/widths.h"

namespace smcbip::pus::testing {

std::uint64_t RandomPackets::bits(std::size_t bytes) {
  const std::uint64_t value = rng_();
  return bytes >= 8 ? value : value & ((std::uint64_t{1} << (8 * bytes)) - 1);
}

std::size_t RandomPackets::below(std::size_t bound) {
  return static_cast<std::size_t>(rng_() % bound);
}

PrimaryHeader RandomPackets::primary(PacketType type) {
  PrimaryHeader p;
  p.type = type;
  p.apid = static_cast<std::uint16_t>(bits(2) & kMaxApid);
  p.sequence_flags = static_cast<SequenceFlags>(below(4));
  p.sequence_count = static_cast<std::uint16_t>(bits(2) & kMaxSequenceCount);
  return p;
}

CucTime RandomPackets::time() {
  return CucTime{static_cast<std::uint32_t>(bits(config_.cuc_coarse_bytes)),
                 static_cast<std::uint32_t>(bits(config_.cuc_fine_bytes))};
}

FixedBytes<kMaxEmbeddedTc> RandomPackets::embedded_tc() {
  // A request the schedule or an event-action would carry: a ping, a function call or a
  // parameter setting, small enough for the embedded capacity.
  static constexpr std::array<std::array<std::uint8_t, 2>, 3> kRequests{{{17, 1}, {8, 1}, {20, 3}}};
  const auto& pick = kRequests[below(kRequests.size())];
  const MessageType* type = find_message_type(PacketType::Tc, pick[0], pick[1]).value();
  for (;;) {
    Telecommand tc = telecommand(*type);
    std::array<std::uint8_t, kMaxEmbeddedTc> buffer{};
    auto length = encode(tc, config_, buffer);
    if (!length) continue;  // too long for the embedded capacity: draw again
    FixedBytes<kMaxEmbeddedTc> out;
    out.assign(std::span<const std::uint8_t>(buffer.data(), length.value()));
    return out;
  }
}

Verification RandomPackets::verification(const MessageType& type) {
  Verification v;
  PrimaryHeader tc = primary(PacketType::Tc);
  v.request = RequestId::of(tc);
  if (detail::has_step_id(type.subtype)) v.step_id = bits(config_.step_id_bytes);
  if (detail::has_failure_notice(type.subtype)) {
    v.failure_code = bits(config_.failure_code_bytes);
    const std::size_t n = below(kMaxFailureData + 1);
    for (std::size_t i = 0; i < n; ++i)
      v.failure_data.push_back(static_cast<std::uint8_t>(bits(1)));
  }
  return v;
}

FixedBytes<kMaxFileString> RandomPackets::file_string() {
  FixedBytes<kMaxFileString> text;
  const std::size_t n = below(kMaxFileString + 1);
  for (std::size_t i = 0; i < n; ++i) text.push_back(static_cast<std::uint8_t>(bits(1)));
  return text;
}

/// Only the fields the subtype carries are set, so that a round trip gives the same value.
FileRequest RandomPackets::file_request(const MessageType& type) {
  FileRequest f;
  if (type.subtype == 14) f.operation_id = bits(kFileOperationIdBytes);
  f.repository = file_string();
  f.file = file_string();
  if (type.subtype == 14) {
    f.target_repository = file_string();
    f.target_file = file_string();
  }
  if (type.subtype == 1 || type.subtype == 4) f.max_size = bits(kFileSizeBytes);
  return f;
}

Activities RandomPackets::activities(const MessageType& type) {
  Activities a;
  const std::size_t n = below(kMaxRequests + 1);
  for (std::size_t i = 0; i < n; ++i) {
    Activity item;
    if (type.service == 11) {
      item.release_time = time();
    } else {
      item.event_id = bits(config_.event_id_bytes);
    }
    item.request = embedded_tc();
    a.items.push_back(item);
  }
  return a;
}

Message RandomPackets::message(const MessageType& type) {
  const std::size_t n = below(kMaxItems + 1);
  switch (type.shape) {
    case Shape::NoData:
      return NoData{};
    case Shape::Verification:
      return verification(type);
    case Shape::IdList: {
      IdList list;
      for (std::size_t i = 0; i < n; ++i)
        list.ids.push_back(bits(detail::id_width(type.service, config_)));
      return list;
    }
    case Shape::HousekeepingReport: {
      HousekeepingReport hk{bits(config_.structure_id_bytes), {}};
      for (std::size_t i = 0; i < n; ++i) hk.values.push_back(bits(config_.value_bytes));
      return hk;
    }
    case Shape::EventReport: {
      EventReport event{bits(config_.event_id_bytes), {}};
      const std::size_t aux = below(kMaxAuxData + 1);
      for (std::size_t i = 0; i < aux; ++i)
        event.aux_data.push_back(static_cast<std::uint8_t>(bits(1)));
      return event;
    }
    case Shape::FunctionCall: {
      FunctionCall call{bits(config_.function_id_bytes), {}};
      for (std::size_t i = 0; i < n; ++i) {
        call.arguments.push_back({bits(config_.argument_id_bytes), bits(config_.value_bytes)});
      }
      return call;
    }
    case Shape::ParameterValues: {
      ParameterValues values;
      for (std::size_t i = 0; i < n; ++i) {
        values.values.push_back({bits(config_.parameter_id_bytes), bits(config_.value_bytes)});
      }
      return values;
    }
    case Shape::TimeReportRate:
      return TimeReportRate{static_cast<std::uint8_t>(bits(1))};
    case Shape::TimeReport:
      return TimeReport{static_cast<std::uint8_t>(bits(1)), time()};
    case Shape::Activities:
      return activities(type);
    case Shape::FileRequest:
      return file_request(type);
  }
  return NoData{};
}

Telecommand RandomPackets::telecommand(const MessageType& type) {
  Telecommand tc;
  tc.primary = primary(PacketType::Tc);
  tc.header.ack_flags = static_cast<std::uint8_t>(below(16));
  tc.header.service = type.service;
  tc.header.subtype = type.subtype;
  tc.header.source_id = static_cast<std::uint16_t>(bits(2));
  tc.data = message(type);
  return tc;
}

Telemetry RandomPackets::telemetry(const MessageType& type) {
  Telemetry tm;
  tm.primary = primary(PacketType::Tm);
  tm.header.time_reference_status = static_cast<std::uint8_t>(below(16));
  tm.header.service = type.service;
  tm.header.subtype = type.subtype;
  tm.header.message_type_counter = static_cast<std::uint16_t>(bits(2));
  tm.header.destination_id = static_cast<std::uint16_t>(bits(2));
  tm.header.time = time();
  tm.data = message(type);
  return tm;
}

}  // namespace smcbip::pus::testing
