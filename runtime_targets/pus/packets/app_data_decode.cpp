// Decoding of the application data of each supported message type, refusing what is malformed.
#include "detail/widths.h"
#include "messages.h"
#include "packet.h"

namespace smcbip::pus {
namespace {

using detail::Reader;

Result<std::size_t> read_count(std::size_t capacity, const Config& c, Reader& in) {
  const std::size_t at = in.offset();
  auto count = in.uint(c.count_bytes);
  if (!count) return count.error();
  if (count.value() > capacity) return fail(Reason::CapacityExceeded, "N exceeds capacity", at);
  return static_cast<std::size_t>(count.value());
}

template <std::size_t N>
Result<Done> read_bytes_to_end(FixedBytes<N>& out, Reader& in) {
  const std::size_t at = in.offset();
  if (!out.assign(in.rest())) return fail(Reason::CapacityExceeded, "data exceeds capacity", at);
  return Done{};
}

Result<Message> read_verification(const MessageType& t, const Config& c, Reader& in) {
  Verification v;
  auto id = in.take(4);
  if (!id) return id.error();
  v.request = decode_request_id(id.value().first<4>());
  if (detail::has_step_id(t.subtype)) {
    auto step = in.uint(c.step_id_bytes);
    if (!step) return step.error();
    v.step_id = step.value();
  }
  if (detail::has_failure_notice(t.subtype)) {
    auto code = in.uint(c.failure_code_bytes);
    if (!code) return code.error();
    v.failure_code = code.value();
    SMCBIP_PUS_TRY(read_bytes_to_end(v.failure_data, in));
  }
  return Message{v};
}

Result<Message> read_ids(const MessageType& t, const Config& c, Reader& in) {
  auto count = read_count(kMaxItems, c, in);
  if (!count) return count.error();
  IdList list;
  for (std::size_t i = 0; i < count.value(); ++i) {
    auto id = in.uint(detail::id_width(t.service, c));
    if (!id) return id.error();
    list.ids.push_back(id.value());
  }
  return Message{list};
}

Result<Message> read_housekeeping(const Config& c, Reader& in) {
  HousekeepingReport hk;
  auto id = in.uint(c.structure_id_bytes);
  if (!id) return id.error();
  hk.structure_id = id.value();
  while (in.remaining() > 0) {
    const std::size_t at = in.offset();
    auto value = in.uint(c.value_bytes);
    if (!value) return fail(Reason::TrailingBytes, "bytes after the last whole value", at);
    if (!hk.values.push_back(value.value())) {
      return fail(Reason::CapacityExceeded, "more values than capacity", at);
    }
  }
  return Message{hk};
}

Result<Message> read_event(const Config& c, Reader& in) {
  EventReport event;
  auto id = in.uint(c.event_id_bytes);
  if (!id) return id.error();
  event.event_id = id.value();
  SMCBIP_PUS_TRY(read_bytes_to_end(event.aux_data, in));
  return Message{event};
}

template <class Items>
Result<Done> read_id_values(Items& items, std::size_t id_bytes, const Config& c, Reader& in) {
  auto count = read_count(kMaxItems, c, in);
  if (!count) return count.error();
  for (std::size_t i = 0; i < count.value(); ++i) {
    auto id = in.uint(id_bytes);
    if (!id) return id.error();
    auto value = in.uint(c.value_bytes);
    if (!value) return value.error();
    items.push_back(IdValue{id.value(), value.value()});
  }
  return Done{};
}

Result<Message> read_time_report(const Config& c, Reader& in) {
  TimeReport report;
  auto rate = in.uint(1);
  if (!rate) return rate.error();
  report.rate_exponent = static_cast<std::uint8_t>(rate.value());
  auto time = decode_cuc(c, in);
  if (!time) return time.error();
  report.time = time.value();
  return Message{report};
}

Result<Done> read_activity(const MessageType& t, const Config& c, Reader& in, Activity& item) {
  if (t.service == 11) {
    auto time = decode_cuc(c, in);
    if (!time) return time.error();
    item.release_time = time.value();
  } else {
    auto id = in.uint(c.event_id_bytes);
    if (!id) return id.error();
    item.event_id = id.value();
  }
  const std::size_t at = in.offset();
  auto length = embedded_tc_length(in.peek_rest(), c);
  if (!length) return Error{length.reason(), length.error().message, at + length.error().offset};
  auto bytes = in.take(length.value());
  if (!bytes) return bytes.error();
  if (!item.request.assign(bytes.value())) {
    return fail(Reason::CapacityExceeded, "embedded TC exceeds capacity", at);
  }
  return Done{};
}

Result<Message> read_activities(const MessageType& t, const Config& c, Reader& in) {
  auto count = read_count(kMaxRequests, c, in);
  if (!count) return count.error();
  Activities activities;
  for (std::size_t i = 0; i < count.value(); ++i) {
    Activity item;
    SMCBIP_PUS_TRY(read_activity(t, c, in, item));
    activities.items.push_back(item);
  }
  return Message{activities};
}

Result<Done> read_string(FixedBytes<kMaxFileString>& out, Reader& in) {
  const std::size_t at = in.offset();
  auto length = in.uint(kFileStringLengthBytes);
  if (!length) return length.error();
  if (length.value() > kMaxFileString) {
    return fail(Reason::CapacityExceeded, "string exceeds capacity", at);
  }
  auto text = in.take(length.value());
  if (!text) return text.error();
  out.assign(text.value());
  return Done{};
}

/// ECSS-E-ST-70-41C 8.23.2: the fields of each ST23 subtype, in order.
Result<Message> read_file_request(const MessageType& t, Reader& in) {
  FileRequest f;
  if (t.subtype == 14) {
    auto id = in.uint(kFileOperationIdBytes);
    if (!id) return id.error();
    f.operation_id = id.value();
  }
  SMCBIP_PUS_TRY(read_string(f.repository, in));
  SMCBIP_PUS_TRY(read_string(f.file, in));
  if (t.subtype == 14) {
    SMCBIP_PUS_TRY(read_string(f.target_repository, in));
    SMCBIP_PUS_TRY(read_string(f.target_file, in));
  } else if (t.subtype == 1 || t.subtype == 4) {
    auto size = in.uint(kFileSizeBytes);
    if (!size) return size.error();
    f.max_size = size.value();
  }
  return Message{f};
}

Result<Message> read_alternative(const MessageType& t, const Config& c, Reader& in) {
  switch (t.shape) {
    case Shape::NoData:
      return Message{NoData{}};
    case Shape::Verification:
      return read_verification(t, c, in);
    case Shape::IdList:
      return read_ids(t, c, in);
    case Shape::HousekeepingReport:
      return read_housekeeping(c, in);
    case Shape::EventReport:
      return read_event(c, in);
    case Shape::FunctionCall: {
      FunctionCall call;
      auto id = in.uint(c.function_id_bytes);
      if (!id) return id.error();
      call.function_id = id.value();
      SMCBIP_PUS_TRY(read_id_values(call.arguments, c.argument_id_bytes, c, in));
      return Message{call};
    }
    case Shape::ParameterValues: {
      ParameterValues values;
      SMCBIP_PUS_TRY(read_id_values(values.values, c.parameter_id_bytes, c, in));
      return Message{values};
    }
    case Shape::TimeReportRate: {
      auto rate = in.uint(1);
      if (!rate) return rate.error();
      return Message{TimeReportRate{static_cast<std::uint8_t>(rate.value())}};
    }
    case Shape::TimeReport:
      return read_time_report(c, in);
    case Shape::Activities:
      return read_activities(t, c, in);
    case Shape::FileRequest:
      return read_file_request(t, in);
  }
  return fail(Reason::BadField, "unknown shape");
}

}  // namespace

Result<Message> decode_app_data(const MessageType& type, const Config& config, detail::Reader& in) {
  auto message = read_alternative(type, config, in);
  if (!message) return message;
  if (in.remaining() != 0) {
    return fail(Reason::TrailingBytes, "bytes after the application data", in.offset());
  }
  return message;
}

}  // namespace smcbip::pus
