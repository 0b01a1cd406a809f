// Encoding of the application data of each supported message type.
#include "detail/widths.h"
#include "messages.h"
#include "packet.h"

namespace smcbip::pus {
namespace {

using detail::Writer;

Result<Done> write_count(std::size_t count, const Config& c, Writer& out) {
  return out.uint(count, c.count_bytes);
}

Result<Done> write_verification(const MessageType& t, const Verification& v, const Config& c,
                                Writer& out) {
  const RequestId& r = v.request;
  if (r.version > 7 || r.apid > kMaxApid || r.sequence_count > kMaxSequenceCount) {
    return fail(Reason::BadField, "request ID field exceeds its width", out.written());
  }
  SMCBIP_PUS_TRY(out.bytes(encode_request_id(r)));
  if (detail::has_step_id(t.subtype)) SMCBIP_PUS_TRY(out.uint(v.step_id, c.step_id_bytes));
  if (!detail::has_failure_notice(t.subtype)) return Done{};
  SMCBIP_PUS_TRY(out.uint(v.failure_code, c.failure_code_bytes));
  return out.bytes(v.failure_data.span());
}

Result<Done> write_ids(const MessageType& t, const IdList& l, const Config& c, Writer& out) {
  SMCBIP_PUS_TRY(write_count(l.ids.size(), c, out));
  for (std::uint64_t id : l.ids) SMCBIP_PUS_TRY(out.uint(id, detail::id_width(t.service, c)));
  return Done{};
}

Result<Done> write_id_values(std::span<const IdValue> items, std::size_t id_bytes, const Config& c,
                             Writer& out) {
  SMCBIP_PUS_TRY(write_count(items.size(), c, out));
  for (const IdValue& item : items) {
    SMCBIP_PUS_TRY(out.uint(item.id, id_bytes));
    SMCBIP_PUS_TRY(out.uint(item.value, c.value_bytes));
  }
  return Done{};
}

Result<Done> write_activities(const MessageType& t, const Activities& a, const Config& c,
                              Writer& out) {
  SMCBIP_PUS_TRY(write_count(a.items.size(), c, out));
  for (const Activity& item : a.items) {
    if (t.service == 11) {
      SMCBIP_PUS_TRY(encode_cuc(item.release_time, c, out));
    } else {
      SMCBIP_PUS_TRY(out.uint(item.event_id, c.event_id_bytes));
    }
    auto length = embedded_tc_length(item.request.span(), c);
    if (!length) return length.error();
    if (length.value() != item.request.size()) {
      return fail(Reason::TrailingBytes, "bytes after the embedded TC", out.written());
    }
    SMCBIP_PUS_TRY(out.bytes(item.request.span()));
  }
  return Done{};
}

Result<Done> write_string(const FixedBytes<kMaxFileString>& text, Writer& out) {
  SMCBIP_PUS_TRY(out.uint(text.size(), kFileStringLengthBytes));
  return out.bytes(text.span());
}

/// ECSS-E-ST-70-41C 8.23.2: the fields of each ST23 subtype, in order.
Result<Done> write_file_request(const MessageType& t, const FileRequest& f, Writer& out) {
  if (t.subtype == 14) SMCBIP_PUS_TRY(out.uint(f.operation_id, kFileOperationIdBytes));
  SMCBIP_PUS_TRY(write_string(f.repository, out));
  SMCBIP_PUS_TRY(write_string(f.file, out));
  if (t.subtype == 14) {
    SMCBIP_PUS_TRY(write_string(f.target_repository, out));
    return write_string(f.target_file, out);
  }
  if (t.subtype == 1 || t.subtype == 4) return out.uint(f.max_size, kFileSizeBytes);
  return Done{};
}

Result<Done> write_alternative(const MessageType& t, const Message& m, const Config& c,
                               Writer& out) {
  switch (t.shape) {
    case Shape::NoData:
      return Done{};
    case Shape::Verification:
      return write_verification(t, std::get<Verification>(m), c, out);
    case Shape::IdList:
      return write_ids(t, std::get<IdList>(m), c, out);
    case Shape::HousekeepingReport: {
      const auto& hk = std::get<HousekeepingReport>(m);
      SMCBIP_PUS_TRY(out.uint(hk.structure_id, c.structure_id_bytes));
      for (std::uint64_t value : hk.values) SMCBIP_PUS_TRY(out.uint(value, c.value_bytes));
      return Done{};
    }
    case Shape::EventReport: {
      const auto& event = std::get<EventReport>(m);
      SMCBIP_PUS_TRY(out.uint(event.event_id, c.event_id_bytes));
      return out.bytes(event.aux_data.span());
    }
    case Shape::FunctionCall: {
      const auto& call = std::get<FunctionCall>(m);
      SMCBIP_PUS_TRY(out.uint(call.function_id, c.function_id_bytes));
      return write_id_values(call.arguments.span(), c.argument_id_bytes, c, out);
    }
    case Shape::ParameterValues:
      return write_id_values(std::get<ParameterValues>(m).values.span(), c.parameter_id_bytes, c,
                             out);
    case Shape::TimeReportRate:
      return out.uint(std::get<TimeReportRate>(m).rate_exponent, 1);
    case Shape::TimeReport:
      SMCBIP_PUS_TRY(out.uint(std::get<TimeReport>(m).rate_exponent, 1));
      return encode_cuc(std::get<TimeReport>(m).time, c, out);
    case Shape::Activities:
      return write_activities(t, std::get<Activities>(m), c, out);
    case Shape::FileRequest:
      return write_file_request(t, std::get<FileRequest>(m), out);
  }
  return fail(Reason::BadField, "unknown shape");
}

}  // namespace

Result<Done> encode_app_data(const MessageType& type, const Message& message, const Config& config,
                             detail::Writer& out) {
  if (message.index() != static_cast<std::size_t>(type.shape)) {
    return fail(Reason::BadField, "application data does not match the message type");
  }
  return write_alternative(type, message, config, out);
}

}  // namespace smcbip::pus
