// The application data of each supported message type, in words.
#include <array>
#include <type_traits>

#include "console/hex.h"
#include "console/table.h"

namespace smcbip::pus::console {
namespace {

std::string hex_id(std::uint64_t value) {
  constexpr char kDigits[] = "0123456789abcdef";
  std::string text;
  do {
    text.insert(text.begin(), kDigits[value & 0xF]);
    value >>= 4;
  } while (value != 0);
  return "0x" + text;
}

template <class Items, class Show>
std::string joined(const Items& items, Show show) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + show(item);
  return text.empty() ? "none" : text;
}

std::string ids_text(const IdList& list) {
  return joined(list.ids, [](std::uint64_t id) { return std::to_string(id); });
}

std::string pairs_text(std::span<const IdValue> pairs) {
  return joined(
      pairs, [](const IdValue& p) { return std::to_string(p.id) + "=" + std::to_string(p.value); });
}

std::string tc_brief(const Telecommand& tc) {
  return "TC[" + std::to_string(tc.header.service) + "," + std::to_string(tc.header.subtype) +
         "] apid " + hex_id(tc.primary.apid) + " seq " + std::to_string(tc.primary.sequence_count);
}

std::string verification_text(std::uint8_t subtype, const Verification& v) {
  static constexpr std::array<const char*, 4> kStages{"acceptance", "start", "progress",
                                                      "completion"};
  const bool failed = subtype % 2 == 0;
  std::string text = std::string(kStages[(subtype - 1) / 2 % 4]) +
                     (failed ? " failure" : " success") + " of TC apid " + hex_id(v.request.apid) +
                     " seq " + std::to_string(v.request.sequence_count);
  if (subtype == 5 || subtype == 6) text += ", step " + std::to_string(v.step_id);
  if (failed) text += ", code " + std::to_string(v.failure_code);
  if (failed && !v.failure_data.empty()) text += ", data " + to_spaced_hex(v.failure_data.span());
  return text;
}

std::string id_list_text(std::uint8_t service, const IdList& list) {
  switch (service) {
    case 3:
      return "structures " + ids_text(list);
    case 12:
      return "monitoring definitions " + ids_text(list);
    case 20:
      return "parameters " + ids_text(list);
    default:
      return "events " + ids_text(list);
  }
}

std::string activities_text(std::uint8_t service, const Activities& a, const Config& config) {
  return joined(a.items, [&](const Activity& item) {
    std::string key = service == 11 ? "at " + format_time(item.release_time, config)
                                    : "on event " + std::to_string(item.event_id);
    auto tc = decode_tc(item.request.span(), config);
    return key + " " + (tc ? tc_brief(tc.value()) : "(" + refusal_text(tc.error()) + ")");
  });
}

/// A path or file name as text, octets outside printable ASCII in hex.
std::string file_string(const FixedBytes<kMaxFileString>& text) {
  std::string out = "'";
  for (std::uint8_t c : text) {
    out += c >= 0x20 && c < 0x7F && c != '\\' ? std::string(1, static_cast<char>(c))
                                              : "\\x" + to_hex(std::span(&c, 1));
  }
  return out + "'";
}

std::string file_text(std::uint8_t subtype, const FileRequest& f) {
  std::string text = subtype == 14 ? "operation " + std::to_string(f.operation_id) + ", " : "";
  text += "repository " + file_string(f.repository) + ", file " + file_string(f.file);
  if (subtype == 14) {
    text += " to repository " + file_string(f.target_repository) + ", file " +
            file_string(f.target_file);
  }
  if (subtype == 1 || subtype == 4) text += ", maximum size " + std::to_string(f.max_size);
  return text;
}

std::string data_text(std::uint8_t service, std::uint8_t subtype, const Message& message,
                      const Config& config) {
  return std::visit(
      [&](const auto& m) -> std::string {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, Verification>) {
          return verification_text(subtype, m);
        } else if constexpr (std::is_same_v<M, IdList>) {
          return id_list_text(service, m);
        } else if constexpr (std::is_same_v<M, HousekeepingReport>) {
          return "structure " + std::to_string(m.structure_id) + ", values " +
                 joined(m.values, [](std::uint64_t v) { return std::to_string(v); });
        } else if constexpr (std::is_same_v<M, EventReport>) {
          return "event " + std::to_string(m.event_id) +
                 (m.aux_data.empty() ? "" : ", data " + to_spaced_hex(m.aux_data.span()));
        } else if constexpr (std::is_same_v<M, FunctionCall>) {
          return "function " + std::to_string(m.function_id) + ", arguments " +
                 pairs_text(m.arguments.span());
        } else if constexpr (std::is_same_v<M, ParameterValues>) {
          return "values " + pairs_text(m.values.span());
        } else if constexpr (std::is_same_v<M, TimeReportRate>) {
          return "rate exponent " + std::to_string(m.rate_exponent);
        } else if constexpr (std::is_same_v<M, TimeReport>) {
          return "rate exponent " + std::to_string(m.rate_exponent) + ", time " +
                 format_time(m.time, config);
        } else if constexpr (std::is_same_v<M, Activities>) {
          return activities_text(service, m, config);
        } else if constexpr (std::is_same_v<M, FileRequest>) {
          return file_text(subtype, m);
        } else {
          return "";
        }
      },
      message);
}

/// "KIND[s,t] " then either the data in words (ST01, whose name is in the words) or the
/// message type's name and the data.
template <class P>
std::string describe_packet(const char* kind, const P& packet, const Config& config) {
  const auto& h = packet.header;
  std::string text =
      std::string(kind) + "[" + std::to_string(h.service) + "," + std::to_string(h.subtype) + "] ";
  const std::string data = data_text(h.service, h.subtype, packet.data, config);
  if (h.service == 1) return text + data;
  auto type = message_type_of(packet);
  text += type ? type.value()->name : "unknown message type";
  return data.empty() ? text : text + ": " + data;
}

}  // namespace

std::string describe(const Telecommand& tc, const Config& config) {
  return describe_packet("TC", tc, config);
}

std::string describe(const Telemetry& tm, const Config& config) {
  return describe_packet("TM", tm, config);
}

}  // namespace smcbip::pus::console
