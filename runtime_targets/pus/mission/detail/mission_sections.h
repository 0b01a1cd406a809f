// The reader of a mission configuration's sections (internal to the mission library).
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "detail/field_reader.h"
#include "detail/located_json.h"
#include "mission.h"
#include "packets/config.h"

namespace smcbip::pus::mission::detail {

/// The longest period or interval accepted (one hour), in milliseconds.
inline constexpr std::uint64_t kMaxPeriodMs = 3'600'000;

/// Builds a Mission section by section; each section may refer to the ones read before it.
class MissionReader {
 public:
  MissionReader(std::string_view text, const LocatedJson& doc, const Config& config)
      : reader_(text, doc), config_(config) {}

  void read_top();
  const std::vector<Diagnostic>& diagnostics() const { return reader_.diagnostics(); }
  Mission take() { return std::move(mission_); }

 private:
  void read_parameters();
  void read_events();
  void read_functions();
  void read_housekeeping();
  void read_monitoring();
  void read_event_actions();
  std::optional<Function> read_function(const std::string& at);
  std::optional<Effect> read_effect(const std::string& at, const Function& function);
  bool read_check(const std::string& at, MonitoringDefinition& definition,
                  const Parameter& parameter);

  bool has(const std::string& object, std::string_view key) const;
  bool fresh(std::set<std::uint64_t>& seen, std::uint64_t id, const std::string& pointer,
             std::string_view what);
  bool value_in_limits(const Parameter& parameter, double value, const std::string& pointer);
  const Parameter* parameter_ref(const std::string& object, std::string_view key);
  std::optional<std::uint64_t> event_ref(const std::string& object, std::string_view key);

  FieldReader reader_;
  Config config_;
  Mission mission_;
};

}  // namespace smcbip::pus::mission::detail
