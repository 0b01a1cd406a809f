// Converting the words of one telecommand into a packet, naming the word that does not fit.
#include <array>
#include <charconv>
#include <limits>

#include "console/detail/tc_fields.h"
#include "console/hex.h"
#include "console/tc_options.h"

namespace smcbip::pus::console {
namespace {

using Words = std::vector<std::string>;

std::uint64_t max_of_width(std::size_t bytes) {
  return bytes >= 8 ? std::numeric_limits<std::uint64_t>::max()
                    : (std::uint64_t{1} << 8 * bytes) - 1;
}

/// An unsigned integer in decimal or 0x hex, at most `max`.
std::uint64_t to_uint(const std::string& option, const std::string& word, std::string_view text,
                      std::uint64_t max, const std::string& what) {
  const bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
  const std::string_view digits = hex ? text.substr(2) : text;
  std::uint64_t value = 0;
  const auto [stop, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), value, hex ? 16 : 10);
  if (digits.empty() || error != std::errc() || stop != digits.data() + digits.size() ||
      value > max) {
    throw TcSyntaxError(option, word,
                        option + ": expected " + what + " (an integer from 0 to " +
                            std::to_string(max) + ", decimal or 0x hex), got '" +
                            std::string(text) + "'");
  }
  return value;
}

/// The two sides of LEFT=RIGHT.
std::pair<std::string_view, std::string_view> split_pair(const std::string& option,
                                                         const std::string& word,
                                                         const std::string& form) {
  const auto equal = word.find('=');
  if (equal == std::string::npos) {
    throw TcSyntaxError(option, word, option + ": expected " + form + ", got '" + word + "'");
  }
  const std::string_view view(word);
  return {view.substr(0, equal), view.substr(equal + 1)};
}

void check_capacity(const std::string& option, const Words& words, std::size_t capacity) {
  if (words.size() > capacity) {
    throw TcSyntaxError(option, words[capacity],
                        option + ": expected at most " + std::to_string(capacity) +
                            " items in one TC, got more from '" + words[capacity] + "' on");
  }
}

IdList id_list(const std::string& option, const Words& words, std::size_t width,
               const std::string& what) {
  check_capacity(option, words, kMaxItems);
  IdList list;
  for (const std::string& w : words)
    list.ids.push_back(to_uint(option, w, w, max_of_width(width), what));
  return list;
}

IdValue id_value(const std::string& option, const std::string& word, std::size_t id_width,
                 const Config& config) {
  const auto [id, value] = split_pair(option, word, "ID=VALUE");
  return {to_uint(option, word, id, max_of_width(id_width), "an ID"),
          to_uint(option, word, value, max_of_width(config.value_bytes), "a value")};
}

/// A whole TC given as hex after '=' in --release and --action.
FixedBytes<kMaxEmbeddedTc> embedded_tc(const std::string& option, const std::string& word,
                                       std::string_view hex, const Config& config) {
  std::vector<std::uint8_t> bytes;
  HexError hex_error;
  std::string problem;
  if (!parse_hex(hex, bytes, hex_error)) {
    problem =
        "expected " + hex_error.expected + " at character " + std::to_string(hex_error.offset);
  } else if (auto tc = decode_tc(bytes, config); !tc) {
    problem = std::string(reason_name(tc.reason())) + " at byte " +
              std::to_string(tc.error().offset) + ": " + tc.error().message;
  } else if (bytes.size() > kMaxEmbeddedTc) {
    problem = "longer than " + std::to_string(kMaxEmbeddedTc) + " octets";
  }
  if (!problem.empty()) {
    throw TcSyntaxError(option, word,
                        option +
                            ": expected a whole TC in hex after '=' (as pus-console encode "
                            "prints it), got '" +
                            word + "': " + problem);
  }
  FixedBytes<kMaxEmbeddedTc> out;
  out.assign(bytes);
  return out;
}

CucTime release_time(const std::string& option, const std::string& word, std::string_view text,
                     const Config& config) {
  const auto colon = text.find(':');
  CucTime time;
  time.coarse = static_cast<std::uint32_t>(to_uint(
      option, word, text.substr(0, colon), max_of_width(config.cuc_coarse_bytes), "CUC seconds"));
  if (colon != std::string_view::npos) {
    time.fine = static_cast<std::uint32_t>(to_uint(
        option, word, text.substr(colon + 1),
        config.cuc_fine_bytes == 0 ? 0 : max_of_width(config.cuc_fine_bytes), "CUC fine time"));
  }
  return time;
}

Activities activities(const std::string& option, const Words& words, const Config& config) {
  check_capacity(option, words, kMaxRequests);
  Activities out;
  for (const std::string& w : words) {
    const bool timed = option == "--release";
    const auto [key, hex] = split_pair(option, w, timed ? "TIME=HEX" : "EVENT=HEX");
    Activity a;
    if (timed) {
      a.release_time = release_time(option, w, key, config);
    } else {
      a.event_id = to_uint(option, w, key, max_of_width(config.event_id_bytes), "an event ID");
    }
    a.request = embedded_tc(option, w, hex, config);
    out.items.push_back(a);
  }
  return out;
}

Message id_list_message(const MessageType& type, const TcWords& w, const Config& c) {
  switch (type.service) {
    case 3:
      return id_list("--sid", w.sids, c.structure_id_bytes, "a structure ID");
    case 12:
      return id_list("--pmon", w.pmons, c.pmon_id_bytes, "a monitoring definition ID");
    case 20:
      return id_list("--param", w.params, c.parameter_id_bytes, "a parameter ID");
    default:
      return id_list("--event", w.events, c.event_id_bytes, "an event definition ID");
  }
}

Message function_call(const TcWords& w, const Config& c) {
  FunctionCall call;
  call.function_id = to_uint("--function", *w.function, *w.function,
                             max_of_width(c.function_id_bytes), "a function ID");
  check_capacity("--arg", w.args, kMaxItems);
  for (const std::string& a : w.args)
    call.arguments.push_back(id_value("--arg", a, c.argument_id_bytes, c));
  return call;
}

Message parameter_values(const TcWords& w, const Config& c) {
  check_capacity("--param", w.params, kMaxItems);
  ParameterValues values;
  for (const std::string& p : w.params)
    values.values.push_back(id_value("--param", p, c.parameter_id_bytes, c));
  return values;
}

FixedBytes<kMaxFileString> file_string(const std::string& option,
                                       const std::optional<std::string>& word) {
  FixedBytes<kMaxFileString> out;
  if (!word) return out;
  if (!out.assign(std::span(reinterpret_cast<const std::uint8_t*>(word->data()), word->size()))) {
    throw TcSyntaxError(option, *word,
                        option + ": expected at most " + std::to_string(kMaxFileString) +
                            " octets, got " + std::to_string(word->size()));
  }
  return out;
}

Message file_request(const MessageType& type, const TcWords& w) {
  FileRequest f;
  f.repository = file_string("--repo", w.repo);
  f.file = file_string("--file", w.file);
  if (type.subtype == 1) {
    f.max_size = to_uint("--size", *w.size, *w.size, max_of_width(kFileSizeBytes), "a size");
  }
  if (type.subtype == 14) {
    f.operation_id = to_uint("--operation", *w.operation, *w.operation,
                             max_of_width(kFileOperationIdBytes), "an operation ID");
    f.target_repository = file_string("--to-repo", w.to_repo);
    f.target_file = file_string("--to-file", w.to_file);
  }
  return f;
}

Message app_data(const MessageType& type, const TcWords& w, const Config& c) {
  switch (type.shape) {
    case Shape::IdList:
      return id_list_message(type, w, c);
    case Shape::FunctionCall:
      return function_call(w, c);
    case Shape::ParameterValues:
      return parameter_values(w, c);
    case Shape::TimeReportRate:
      return TimeReportRate{
          static_cast<std::uint8_t>(to_uint("--rate", *w.rate, *w.rate, 255, "a rate exponent"))};
    case Shape::Activities:
      return type.service == 11 ? activities("--release", w.releases, c)
                                : activities("--action", w.actions, c);
    case Shape::FileRequest:
      return file_request(type, w);
    default:
      return NoData{};
  }
}

std::uint8_t ack_flags(const std::string& text) {
  const std::string expected =
      "--ack: expected distinct letters of a, s, p, c, 'none', or a number 0..15, got '" + text +
      "'";
  if (text == "none") return 0;
  if (!text.empty() && text[0] >= '0' && text[0] <= '9') {
    return static_cast<std::uint8_t>(to_uint("--ack", text, text, 15, "acknowledgement flags"));
  }
  // Bits 0..3: acceptance, start, progress, completion (ECSS-E-ST-70-41C 7.4.3.1).
  constexpr std::string_view kLetters = "aspc";
  std::uint8_t flags = 0;
  for (char letter : text) {
    const auto bit = kLetters.find(letter);
    if (bit == std::string_view::npos || (flags >> bit & 1) != 0) {
      throw TcSyntaxError("--ack", text, expected);
    }
    flags = static_cast<std::uint8_t>(flags | 1u << bit);
  }
  if (flags == 0) throw TcSyntaxError("--ack", text, expected);
  return flags;
}

}  // namespace

BuiltTc build_tc(const TcWords& w, const Config& config) {
  BuiltTc built;
  Telecommand& tc = built.tc;
  tc.header.service =
      static_cast<std::uint8_t>(to_uint("SERVICE", w.service, w.service, 255, "a service type"));
  tc.header.subtype =
      static_cast<std::uint8_t>(to_uint("SUBTYPE", w.subtype, w.subtype, 255, "a message subtype"));
  auto type = find_message_type(PacketType::Tc, tc.header.service, tc.header.subtype);
  if (!type) {
    const bool service = type.reason() == Reason::UnknownService;
    throw TcSyntaxError(service ? "SERVICE" : "SUBTYPE", service ? w.service : w.subtype,
                        std::string(service ? "SERVICE" : "SUBTYPE") +
                            ": expected a TC the console "
                            "knows (see --help), got TC[" +
                            w.service + "," + w.subtype + "]");
  }
  detail::check_fields(*type.value(), w);
  tc.data = app_data(*type.value(), w, config);
  if (w.apid)
    tc.primary.apid =
        static_cast<std::uint16_t>(to_uint("--apid", *w.apid, *w.apid, kMaxApid, "an APID"));
  if (w.seq)
    tc.primary.sequence_count = static_cast<std::uint16_t>(
        to_uint("--seq", *w.seq, *w.seq, kMaxSequenceCount, "a sequence count"));
  if (w.source)
    tc.header.source_id = static_cast<std::uint16_t>(
        to_uint("--source", *w.source, *w.source, 0xFFFF, "a source ID"));
  if (w.ack) tc.header.ack_flags = ack_flags(*w.ack);
  built.seq_given = w.seq.has_value();
  return built;
}

std::vector<std::uint8_t> encode_tc(const Telecommand& tc, const Config& config) {
  std::vector<std::uint8_t> bytes(65542);
  auto length = encode(tc, config, bytes);
  if (!length) {
    throw TcSyntaxError("TC", "",
                        std::string("the packet library refuses this TC: ") +
                            std::string(reason_name(length.reason())) + ": " +
                            length.error().message);
  }
  bytes.resize(length.value());
  return bytes;
}

}  // namespace smcbip::pus::console
