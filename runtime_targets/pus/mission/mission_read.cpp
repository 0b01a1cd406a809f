// Reads the sections of a mission configuration in dependency order (parameters and events
// before what refers to them), checking every ID, reference and limit.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "detail/field_reader.h"
#include "detail/mission_sections.h"
#include "packets/packets.h"

namespace smcbip::pus::mission {
namespace detail {

bool MissionReader::has(const std::string& object, std::string_view key) const {
  return reader_.at(FieldReader::member(object, key)) != nullptr;
}

bool MissionReader::fresh(std::set<std::uint64_t>& seen, std::uint64_t id,
                          const std::string& pointer, std::string_view what) {
  if (seen.insert(id).second) return true;
  reader_.error(pointer, "duplicate " + std::string(what) + " " + std::to_string(id));
  return false;
}

bool MissionReader::value_in_limits(const Parameter& parameter, double value,
                                    const std::string& pointer) {
  if (!representable(parameter.type, value)) {
    reader_.error(pointer, "value not representable as " + std::string(type_name(parameter.type)));
    return false;
  }
  if (value < parameter.min || value > parameter.max) {
    reader_.error(pointer, "value outside the limits of parameter " + std::to_string(parameter.id) +
                               " (" + parameter.name + ")");
    return false;
  }
  return true;
}

const Parameter* MissionReader::parameter_ref(const std::string& object, std::string_view key) {
  const auto id = reader_.id(object, key, config_.parameter_id_bytes);
  if (!id) return nullptr;
  const Parameter* parameter = mission_.find_parameter(*id);
  if (parameter == nullptr) {
    reader_.error(FieldReader::member(object, key), "undefined parameter " + std::to_string(*id));
  }
  return parameter;
}

std::optional<std::uint64_t> MissionReader::event_ref(const std::string& object,
                                                      std::string_view key) {
  const auto id = reader_.id(object, key, config_.event_id_bytes);
  if (!id) return std::nullopt;
  if (mission_.find_event(*id) == nullptr) {
    reader_.error(FieldReader::member(object, key), "undefined event " + std::to_string(*id));
    return std::nullopt;
  }
  return id;
}

void MissionReader::read_top() {
  if (!reader_.object_with(
          "", {"apid", "time_report_period_ms", "file_repository", "parameters", "housekeeping",
               "events", "functions", "monitoring", "event_actions"})) {
    return;
  }
  if (const auto apid = reader_.unsigned_in("", "apid", 0, kMaxApid)) {
    mission_.apid = static_cast<std::uint16_t>(*apid);
  }
  if (has("", "time_report_period_ms")) {
    if (const auto period = reader_.unsigned_in("", "time_report_period_ms", 1, kMaxPeriodMs)) {
      mission_.time_report_period_ms = static_cast<std::uint32_t>(*period);
    }
  }
  if (has("", "file_repository")) {
    if (const auto root = reader_.string("", "file_repository")) {
      if (root->empty()) {
        reader_.error(FieldReader::member("", "file_repository"), "expected a folder, got \"\"");
      }
      mission_.file_repository = *root;
    }
  }
  read_parameters();
  read_events();
  read_functions();
  read_housekeeping();
  read_monitoring();
  read_event_actions();
}

void MissionReader::read_parameters() {
  const auto count = reader_.array_size("", "parameters", true);
  std::set<std::uint64_t> seen;
  for (std::size_t i = 0; count && i < *count; ++i) {
    const std::string at = FieldReader::element("/parameters", i);
    if (!reader_.object_with(at, {"id", "name", "type", "initial", "min", "max"})) continue;
    Parameter p;
    const auto id = reader_.id(at, "id", config_.parameter_id_bytes);
    const auto name = reader_.string(at, "name");
    const auto type = reader_.value_type(at, "type");
    const auto initial = reader_.number(at, "initial");
    const auto min = reader_.number(at, "min");
    const auto max = reader_.number(at, "max");
    if (!id || !name || !type || !initial || !min || !max) continue;
    if (!fresh(seen, *id, FieldReader::member(at, "id"), "parameter")) continue;
    p = Parameter{*id, *name, *type, *initial, *min, *max};
    if (!representable(p.type, p.min) || !representable(p.type, p.max) || p.min > p.max) {
      reader_.error(FieldReader::member(at, "min"),
                    "limits must be representable and ordered (min <= max)");
      continue;
    }
    if (!value_in_limits(p, p.initial, FieldReader::member(at, "initial"))) continue;
    mission_.parameters.push_back(std::move(p));
  }
}

void MissionReader::read_events() {
  const auto count = reader_.array_size("", "events", false);
  std::set<std::uint64_t> seen;
  for (std::size_t i = 0; count && i < *count; ++i) {
    const std::string at = FieldReader::element("/events", i);
    if (!reader_.object_with(at, {"id", "name", "severity", "enabled"})) continue;
    const auto id = reader_.id(at, "id", config_.event_id_bytes);
    const auto name = reader_.string(at, "name");
    const auto severity = reader_.severity(at, "severity");
    const auto enabled = has(at, "enabled") ? reader_.boolean(at, "enabled") : true;
    if (!id || !name || !severity || !enabled) continue;
    if (!fresh(seen, *id, FieldReader::member(at, "id"), "event")) continue;
    mission_.events.push_back(Event{*id, *name, *severity, *enabled});
  }
}

void MissionReader::read_housekeeping() {
  const auto count = reader_.array_size("", "housekeeping", false);
  std::set<std::uint64_t> seen;
  for (std::size_t i = 0; count && i < *count; ++i) {
    const std::string at = FieldReader::element("/housekeeping", i);
    if (!reader_.object_with(at, {"id", "parameters", "period_ms", "enabled"})) continue;
    HousekeepingStructure s;
    const auto id = reader_.id(at, "id", config_.structure_id_bytes);
    const auto period = reader_.unsigned_in(at, "period_ms", 1, kMaxPeriodMs);
    const auto enabled = has(at, "enabled") ? reader_.boolean(at, "enabled") : false;
    const auto size = reader_.array_size(at, "parameters", true);
    if (size && (*size == 0 || *size > kMaxItems)) {
      reader_.error(FieldReader::member(at, "parameters"),
                    "a structure holds 1.." + std::to_string(kMaxItems) + " parameters");
      continue;
    }
    bool ok = id && period && enabled && size;
    const std::string list = FieldReader::member(at, "parameters");
    for (std::size_t k = 0; size && k < *size; ++k) {
      const Parameter* p = parameter_ref(list, std::to_string(k));
      ok = ok && p != nullptr;
      if (p != nullptr) s.parameters.push_back(p->id);
    }
    if (!ok || !fresh(seen, *id, FieldReader::member(at, "id"), "housekeeping structure")) {
      continue;
    }
    s.id = *id;
    s.period_ms = static_cast<std::uint32_t>(*period);
    s.enabled = *enabled;
    mission_.housekeeping.push_back(std::move(s));
  }
}

}  // namespace detail

LoadResult parse_mission(std::string_view text, const Config& config) {
  LoadResult result;
  auto parsed = detail::parse_located(text);
  if (const auto* syntax = std::get_if<detail::JsonSyntaxError>(&parsed)) {
    const auto [line, column] = detail::line_column(text, syntax->offset);
    result.diagnostics.push_back(Diagnostic{line, column, syntax->message});
    return result;
  }
  const detail::LocatedJson& doc = std::get<detail::LocatedJson>(parsed);
  detail::MissionReader reader(text, doc, config);
  reader.read_top();
  result.diagnostics = reader.diagnostics();
  if (result.diagnostics.empty()) result.mission = reader.take();
  return result;
}

LoadResult load_mission(const std::string& path, const Config& config) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (!in || !(text << in.rdbuf())) {
    // An empty file is read as empty text, which the parser refuses with its own message.
    if (!in.is_open()) {
      LoadResult result;
      result.diagnostics.push_back(Diagnostic{1, 1, "cannot read the file"});
      return result;
    }
  }
  LoadResult result = parse_mission(text.str(), config);
  if (result.mission && !result.mission->file_repository.empty()) {
    const std::filesystem::path root(result.mission->file_repository);
    if (root.is_relative()) {
      result.mission->file_repository =
          (std::filesystem::path(path).parent_path() / root).lexically_normal().string();
    }
  }
  return result;
}

std::string format_diagnostics(const std::string& file,
                               const std::vector<Diagnostic>& diagnostics) {
  std::string out;
  for (const Diagnostic& d : diagnostics) {
    out += file + ":" + std::to_string(d.line) + ":" + std::to_string(d.column) +
           ": error: " + d.message + "\n";
  }
  return out;
}

}  // namespace smcbip::pus::mission
