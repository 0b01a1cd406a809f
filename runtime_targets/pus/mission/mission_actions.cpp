// The sections of a mission configuration that act: functions, monitoring definitions and
// event-action definitions.
#include <vector>

#include "detail/field_reader.h"
#include "detail/mission_sections.h"
#include "packets/packets.h"

namespace smcbip::pus::mission::detail {
namespace {

/// Hex digits (either case) to octets; false on anything else or an odd count.
bool hex_octets(const std::string& text, std::vector<std::uint8_t>& out) {
  const auto digit = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  if (text.size() % 2 != 0) return false;
  for (std::size_t i = 0; i < text.size(); i += 2) {
    const int high = digit(text[i]);
    const int low = digit(text[i + 1]);
    if (high < 0 || low < 0) return false;
    out.push_back(static_cast<std::uint8_t>(high * 16 + low));
  }
  return true;
}

}  // namespace

void MissionReader::read_functions() {
  const auto count = reader_.array_size("", "functions", false);
  std::set<std::uint64_t> seen;
  for (std::size_t i = 0; count && i < *count; ++i) {
    const std::string at = FieldReader::element("/functions", i);
    auto function = read_function(at);
    if (function && fresh(seen, function->id, FieldReader::member(at, "id"), "function")) {
      mission_.functions.push_back(std::move(*function));
    }
  }
}

std::optional<Function> MissionReader::read_function(const std::string& at) {
  if (!reader_.object_with(at, {"id", "name", "arguments", "effects"})) return std::nullopt;
  Function f;
  const auto id = reader_.id(at, "id", config_.function_id_bytes);
  const auto name = reader_.string(at, "name");
  const auto arguments = reader_.array_size(at, "arguments", false);
  const auto effects = reader_.array_size(at, "effects", false);
  if (!id || !name || !arguments || !effects) return std::nullopt;
  f.id = *id;
  f.name = *name;
  std::set<std::uint64_t> seen;
  bool ok = true;
  for (std::size_t k = 0; k < *arguments; ++k) {
    const std::string arg = FieldReader::element(FieldReader::member(at, "arguments"), k);
    if (!reader_.object_with(arg, {"id", "name", "type"})) continue;
    const auto arg_id = reader_.id(arg, "id", config_.argument_id_bytes);
    const auto arg_name = reader_.string(arg, "name");
    const auto type = reader_.value_type(arg, "type");
    ok = ok && arg_id && arg_name && type &&
         fresh(seen, *arg_id, FieldReader::member(arg, "id"), "argument");
    if (ok) f.arguments.push_back(Argument{*arg_id, *arg_name, *type});
  }
  for (std::size_t k = 0; ok && k < *effects; ++k) {
    auto effect = read_effect(FieldReader::element(FieldReader::member(at, "effects"), k), f);
    ok = effect.has_value();
    if (ok) f.effects.push_back(*effect);
  }
  if (!ok) return std::nullopt;
  return f;
}

std::optional<Effect> MissionReader::read_effect(const std::string& at, const Function& function) {
  if (!reader_.object_with(at, {"parameter", "value", "argument"})) return std::nullopt;
  const Parameter* parameter = parameter_ref(at, "parameter");
  if (parameter == nullptr) return std::nullopt;
  Effect effect{parameter->id, {}, {}};
  if (has(at, "value") == has(at, "argument")) {
    reader_.error(at, "an effect sets either a constant \"value\" or an \"argument\"");
    return std::nullopt;
  }
  if (has(at, "value")) {
    effect.value = reader_.number(at, "value");
    if (!effect.value ||
        !value_in_limits(*parameter, *effect.value, FieldReader::member(at, "value"))) {
      return std::nullopt;
    }
    return effect;
  }
  effect.argument = reader_.id(at, "argument", config_.argument_id_bytes);
  if (!effect.argument) return std::nullopt;
  for (const Argument& argument : function.arguments) {
    if (argument.id != *effect.argument) continue;
    if (argument.type != parameter->type) {
      reader_.error(FieldReader::member(at, "argument"),
                    "argument type differs from the parameter's");
      return std::nullopt;
    }
    return effect;
  }
  reader_.error(FieldReader::member(at, "argument"),
                "undefined argument " + std::to_string(*effect.argument));
  return std::nullopt;
}

void MissionReader::read_monitoring() {
  const auto count = reader_.array_size("", "monitoring", false);
  std::set<std::uint64_t> seen;
  for (std::size_t i = 0; count && i < *count; ++i) {
    const std::string at = FieldReader::element("/monitoring", i);
    if (!reader_.object_with(at, {"id", "parameter", "limit", "expected", "interval_ms",
                                  "repetitions", "event", "enabled"})) {
      continue;
    }
    MonitoringDefinition d;
    const auto id = reader_.id(at, "id", config_.pmon_id_bytes);
    const Parameter* parameter = parameter_ref(at, "parameter");
    const auto interval = reader_.unsigned_in(at, "interval_ms", 1, kMaxPeriodMs);
    const auto repetitions =
        has(at, "repetitions") ? reader_.unsigned_in(at, "repetitions", 1, 255) : 1;
    const auto event = event_ref(at, "event");
    const auto enabled = has(at, "enabled") ? reader_.boolean(at, "enabled") : true;
    if (!id || parameter == nullptr || !interval || !repetitions || !event || !enabled) continue;
    if (!read_check(at, d, *parameter)) continue;
    if (!fresh(seen, *id, FieldReader::member(at, "id"), "monitoring definition")) continue;
    d.id = *id;
    d.parameter = parameter->id;
    d.interval_ms = static_cast<std::uint32_t>(*interval);
    d.repetitions = static_cast<std::uint32_t>(*repetitions);
    d.event = *event;
    d.enabled = *enabled;
    mission_.monitoring.push_back(d);
  }
}

bool MissionReader::read_check(const std::string& at, MonitoringDefinition& d,
                               const Parameter& parameter) {
  if (has(at, "limit") == has(at, "expected")) {
    reader_.error(at, "a monitoring definition has either a \"limit\" or an \"expected\" check");
    return false;
  }
  if (has(at, "limit")) {
    const std::string limit = FieldReader::member(at, "limit");
    if (!reader_.object_with(limit, {"low", "high"})) return false;
    const auto low = reader_.number(limit, "low");
    const auto high = reader_.number(limit, "high");
    if (!low || !high) return false;
    if (*low > *high) {
      reader_.error(FieldReader::member(limit, "low"), "low limit above the high limit");
      return false;
    }
    d.kind = MonitoringDefinition::Kind::Limit;
    d.low = *low;
    d.high = *high;
    return true;
  }
  const std::string expected = FieldReader::member(at, "expected");
  if (!reader_.object_with(expected, {"value", "mask"})) return false;
  const auto value = reader_.id(expected, "value", config_.value_bytes);
  const auto mask = has(expected, "mask") ? reader_.id(expected, "mask", config_.value_bytes)
                                          : max_of_width(config_.value_bytes);
  if (!value || !mask) return false;
  if (parameter.type == ValueType::Float32) {
    reader_.error(expected, "an expected-value check needs an integer or bool parameter");
    return false;
  }
  d.kind = MonitoringDefinition::Kind::ExpectedValue;
  d.expected = *value;
  d.mask = *mask;
  return true;
}

void MissionReader::read_event_actions() {
  const auto count = reader_.array_size("", "event_actions", false);
  if (count && *count > kMaxEventActions) {
    reader_.error("/event_actions",
                  "at most " + std::to_string(kMaxEventActions) + " event-action definitions");
    return;
  }
  std::set<std::uint64_t> seen;
  for (std::size_t i = 0; count && i < *count; ++i) {
    const std::string at = FieldReader::element("/event_actions", i);
    if (!reader_.object_with(at, {"event", "request", "enabled"})) continue;
    const auto event = event_ref(at, "event");
    const auto request = reader_.string(at, "request");
    const auto enabled = has(at, "enabled") ? reader_.boolean(at, "enabled") : true;
    if (!event || !request || !enabled) continue;
    EventAction action{*event, {}, *enabled};
    const std::string where = FieldReader::member(at, "request");
    if (!hex_octets(*request, action.request)) {
      reader_.error(where, "\"request\" must be a TC as an even number of hex digits");
      continue;
    }
    const auto tc = decode_tc(action.request, config_);
    if (!tc) {
      reader_.error(where, std::string("the request is not a valid TC: ") +
                               std::string(reason_name(tc.reason())) + " at octet " +
                               std::to_string(tc.error().offset) + ": " + tc.error().message);
      continue;
    }
    if (action.request.size() > kMaxEmbeddedTc) {
      reader_.error(where, "the request exceeds " + std::to_string(kMaxEmbeddedTc) + " octets");
      continue;
    }
    if (!fresh(seen, *event, FieldReader::member(at, "event"),
               "event-action definition for event")) {
      continue;
    }
    mission_.event_actions.push_back(std::move(action));
  }
}

}  // namespace smcbip::pus::mission::detail
