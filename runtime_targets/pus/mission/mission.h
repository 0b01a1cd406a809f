// The mission configuration of the on-board PUS application: parameters, housekeeping
// structures, events, functions, monitoring and event-action definitions, read from JSON.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "packets/config.h"

namespace smcbip::pus::mission {

/// How the four octets of a parameter or argument value are read.
enum class ValueType : std::uint8_t { Uint32, Int32, Float32, Bool };

/// The raw bits of a value of a type (two's complement, IEEE 754 binary32, 0/1).
std::uint64_t to_raw(ValueType type, double value);
/// The value the raw bits of a type stand for.
double from_raw(ValueType type, std::uint64_t raw);
/// Whether `value` is representable in the type (integral and in range for the integers).
bool representable(ValueType type, double value);
/// "uint32", "int32", "float32", "bool".
std::string_view type_name(ValueType type);

/// An on-board parameter (ST20, reported by ST03, checked by ST12).
struct Parameter {
  std::uint64_t id = 0;
  std::string name;
  ValueType type = ValueType::Uint32;
  double initial = 0;
  /// The values ST20 [20,3] may set; a value outside is refused.
  double min = 0;
  double max = 0;
};

/// An ST03 housekeeping parameter report structure, reported every `period_ms` once enabled.
struct HousekeepingStructure {
  std::uint64_t id = 0;
  std::vector<std::uint64_t> parameters;
  std::uint32_t period_ms = 0;
  bool enabled = false;
};

/// ST05 severities; the report subtype is 1 + the enumerator.
enum class Severity : std::uint8_t { Informative, Low, Medium, High };

/// An ST05 event definition.
struct Event {
  std::uint64_t id = 0;
  std::string name;
  Severity severity = Severity::Informative;
  bool enabled = true;
};

/// An argument of an ST08 function.
struct Argument {
  std::uint64_t id = 0;
  std::string name;
  ValueType type = ValueType::Uint32;
};

/// What performing a function does to a parameter: it sets it to a constant, or to the value
/// of one of the call's arguments.
struct Effect {
  std::uint64_t parameter = 0;
  std::optional<double> value;
  std::optional<std::uint64_t> argument;
};

/// An ST08 function.
struct Function {
  std::uint64_t id = 0;
  std::string name;
  std::vector<Argument> arguments;
  std::vector<Effect> effects;
};

/// An ST12 check: a limit check (within [low, high]) or an expected-value check
/// (value & mask == expected).
struct MonitoringDefinition {
  enum class Kind : std::uint8_t { Limit, ExpectedValue };
  std::uint64_t id = 0;
  std::uint64_t parameter = 0;
  Kind kind = Kind::Limit;
  double low = 0;
  double high = 0;
  std::uint64_t mask = 0xFFFFFFFF;
  std::uint64_t expected = 0;
  /// Checked every interval; a violation is confirmed after `repetitions` checks in a row.
  std::uint32_t interval_ms = 0;
  std::uint32_t repetitions = 1;
  /// The ST05 event raised when the check goes out of limit (or unexpected).
  std::uint64_t event = 0;
  bool enabled = true;
};

/// The event-action definitions the on-board table holds (the mission's and those added by TC).
inline constexpr std::size_t kMaxEventActions = 16;

/// An ST19 event-action definition: the whole TC (octets) released when the event is raised.
struct EventAction {
  std::uint64_t event = 0;
  std::vector<std::uint8_t> request;
  bool enabled = true;
};

/// The whole mission configuration, checked: IDs unique and within their configured widths,
/// every reference defined, limits ordered, initial values within limits, requests decodable.
struct Mission {
  std::uint16_t apid = 0;
  /// The [9,2] time report base period; a report every 2^rate periods.
  std::uint32_t time_report_period_ms = 1000;
  /// The ST23 repository root folder (empty: no file management); load_mission() resolves a
  /// relative one against the mission file's folder.
  std::string file_repository;
  std::vector<Parameter> parameters;
  std::vector<HousekeepingStructure> housekeeping;
  std::vector<Event> events;
  std::vector<Function> functions;
  std::vector<MonitoringDefinition> monitoring;
  std::vector<EventAction> event_actions;

  const Parameter* find_parameter(std::uint64_t id) const;
  const Event* find_event(std::uint64_t id) const;
  const Function* find_function(std::uint64_t id) const;
  /// The index of a parameter in `parameters`, or `parameters.size()`.
  std::size_t parameter_index(std::uint64_t id) const;
};

/// A refusal of the configuration, located in its text (1-based line and column).
struct Diagnostic {
  std::size_t line = 0;
  std::size_t column = 0;
  std::string message;
};

/// A mission or the diagnostics of why there is none.
struct LoadResult {
  std::optional<Mission> mission;
  std::vector<Diagnostic> diagnostics;
};

/// Reads and checks a mission from JSON text; IDs are checked against the packet config's widths.
LoadResult parse_mission(std::string_view text, const Config& config = {});

/// Reads a file; an unreadable file is one diagnostic at 1:1.
LoadResult load_mission(const std::string& path, const Config& config = {});

/// "FILE:LINE:COLUMN: error: MESSAGE", one per line.
std::string format_diagnostics(const std::string& file, const std::vector<Diagnostic>& diagnostics);

}  // namespace smcbip::pus::mission
