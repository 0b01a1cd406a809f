// The mission configuration: the bundled mission, value encodings, and located refusals (the
// expected line:column are counted by hand in each test's text).
#include "mission/mission.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

namespace smcbip::pus::mission {
namespace {

/// A minimal valid mission the refusal tests alter one line of.
std::string with(const std::string& extra_sections) {
  return "{\n"
         "  \"apid\": 18,\n"
         "  \"parameters\": [\n"
         "    {\"id\": 1, \"name\": \"t\", \"type\": \"int32\", \"initial\": 0, \"min\": -5, "
         "\"max\": 5}\n"
         "  ],\n"
         "  \"events\": [{\"id\": 7, \"name\": \"hot\", \"severity\": \"high\"}]" +
         extra_sections + "\n}\n";
}

// Positions: the extra sections of with() start on line 7; columns count octets from 1 to the
// offending key (or value, or object), as located by hand in each text.

/// The single diagnostic of a refused text, as "line:column: message".
std::string refusal(const std::string& text) {
  const LoadResult result = parse_mission(text);
  EXPECT_FALSE(result.mission.has_value());
  if (result.diagnostics.empty()) return "accepted";
  const Diagnostic& d = result.diagnostics.front();
  return std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message;
}

TEST(PusMission, BundledMissionLoads) {
  const LoadResult result = load_mission(PUS_MISSION_PATH);
  ASSERT_TRUE(result.diagnostics.empty()) << format_diagnostics("mission.json", result.diagnostics);
  const Mission& m = *result.mission;
  EXPECT_EQ(m.apid, 18);
  EXPECT_EQ(m.parameters.size(), 4U);
  EXPECT_EQ(m.housekeeping.size(), 2U);
  EXPECT_EQ(m.housekeeping[0].parameters, (std::vector<std::uint64_t>{1, 2, 3}));
  EXPECT_EQ(m.events.size(), 2U);
  EXPECT_EQ(m.find_event(100)->severity, Severity::Medium);
  EXPECT_EQ(m.find_function(2)->effects[0].argument, 1U);
  EXPECT_EQ(m.monitoring[0].kind, MonitoringDefinition::Kind::Limit);
  EXPECT_EQ(m.monitoring[1].kind, MonitoringDefinition::Kind::ExpectedValue);
  EXPECT_EQ(m.monitoring[1].mask, 3U);
  ASSERT_EQ(m.event_actions.size(), 1U);
  EXPECT_EQ(m.event_actions[0].request.size(), 16U);
}

TEST(PusMission, MinimalMissionLoads) {
  const LoadResult result = parse_mission(with(""));
  ASSERT_TRUE(result.mission.has_value()) << format_diagnostics("-", result.diagnostics);
  EXPECT_EQ(result.mission->parameters[0].min, -5);
  EXPECT_EQ(result.mission->time_report_period_ms, 1000U);
}

TEST(PusMission, RawValues) {
  // IEEE 754 binary32 of 28.0: sign 0, exponent 4 + 127 = 0x83, fraction 0.75 -> 0x41E00000.
  EXPECT_EQ(to_raw(ValueType::Float32, 28.0), 0x41E00000U);
  EXPECT_EQ(from_raw(ValueType::Float32, 0x41E00000U), 28.0);
  EXPECT_EQ(to_raw(ValueType::Int32, -1), 0xFFFFFFFFU);
  EXPECT_EQ(from_raw(ValueType::Int32, 0xFFFFFFFEU), -2);
  EXPECT_EQ(to_raw(ValueType::Bool, 1), 1U);
  EXPECT_TRUE(representable(ValueType::Uint32, 4294967295.0));
  EXPECT_FALSE(representable(ValueType::Uint32, -1));
  EXPECT_FALSE(representable(ValueType::Int32, 0.5));
  EXPECT_FALSE(representable(ValueType::Bool, 2));
}

TEST(PusMission, SyntaxErrorAtTheOffendingToken) {
  // "tru" then "]": nlohmann fails on the ']' (line 2, column 21).
  EXPECT_EQ(refusal("{\"apid\": 1,\n  \"parameters\": [tru]}").substr(0, 5), "2:21:");
  EXPECT_EQ(refusal("{\"apid\": 1, \"apid\": 2, \"parameters\": []}"),
            "1:13: duplicate key \"apid\"");
}

TEST(PusMission, MissingAndUnknownKeys) {
  EXPECT_EQ(refusal("{\n  \"parameters\": []\n}"), "1:1: missing \"apid\"");
  // The key "colour" starts at line 3 column 3.
  EXPECT_EQ(refusal("{\n  \"apid\": 1, \"parameters\": [],\n  \"colour\": 3\n}"),
            "3:3: unknown key \"colour\"");
  EXPECT_EQ(refusal("{\"apid\": 4096, \"parameters\": []}"),
            "1:2: \"apid\" must be an integer in 0..2047");
}

TEST(PusMission, ParameterRefusals) {
  EXPECT_EQ(refusal("{\"apid\": 1, \"parameters\": [{\"id\": 1, \"name\": \"x\", \"type\": "
                    "\"int32\", \"initial\": 9, \"min\": 0, \"max\": 5}]}"),
            "1:68: value outside the limits of parameter 1 (x)");
  EXPECT_EQ(refusal("{\"apid\": 1, \"parameters\": [{\"id\": 1, \"name\": \"x\", \"type\": "
                    "\"int64\", \"initial\": 0, \"min\": 0, \"max\": 5}]}"),
            "1:51: unknown type \"int64\" (uint32, int32, float32, bool)");
  // Both parameters have ID 65536, over the default two-octet width.
  EXPECT_EQ(refusal("{\"apid\": 1, \"parameters\": [{\"id\": 65536, \"name\": \"x\", \"type\": "
                    "\"int32\", \"initial\": 0, \"min\": 0, \"max\": 5}]}"),
            "1:29: \"id\" must be an integer in 0..65535");
}

TEST(PusMission, DuplicateIdAtTheSecondDefinition) {
  const std::string text = with(
      ",\n  \"housekeeping\": [{\"id\": 3, \"parameters\": [1], \"period_ms\": 10},\n"
      "                   {\"id\": 3, \"parameters\": [1], \"period_ms\": 20}]");
  EXPECT_EQ(refusal(text), "8:21: duplicate housekeeping structure 3");
}

TEST(PusMission, UndefinedReferencesAtTheReference) {
  // The second element of "parameters" (the 9) is at line 7 column 48.
  EXPECT_EQ(refusal(with(",\n  \"housekeeping\": [{\"id\": 3, \"parameters\": [1, 9], "
                         "\"period_ms\": 10}]")),
            "7:48: undefined parameter 9");
  EXPECT_EQ(refusal(with(",\n  \"monitoring\": [{\"id\": 1, \"parameter\": 1, \"limit\": "
                         "{\"low\": 0, \"high\": 1}, \"interval_ms\": 10, \"event\": 8}]")),
            "7:95: undefined event 8");
  EXPECT_EQ(refusal(with(",\n  \"functions\": [{\"id\": 1, \"name\": \"f\", \"effects\": "
                         "[{\"parameter\": 1, \"argument\": 4}]}]")),
            "7:69: undefined argument 4");
}

TEST(PusMission, MonitoringRefusals) {
  EXPECT_EQ(refusal(with(",\n  \"monitoring\": [{\"id\": 1, \"parameter\": 1, \"limit\": "
                         "{\"low\": 2, \"high\": 1}, \"interval_ms\": 10, \"event\": 7}]")),
            "7:54: low limit above the high limit");
  EXPECT_EQ(refusal(with(",\n  \"monitoring\": [{\"id\": 1, \"parameter\": 1, \"interval_ms\": "
                         "10, \"event\": 7}]")),
            "7:18: a monitoring definition has either a \"limit\" or an \"expected\" check");
}

TEST(PusMission, EventActionRequestIsDecoded) {
  // The TC[17,1] of the console's README with its last CRC octet changed.
  EXPECT_EQ(refusal(with(",\n  \"event_actions\": [{\"event\": 7, \"request\": "
                         "\"1800c00000062f110100007959\"}]")),
            "7:34: the request is not a valid TC: bad-crc at octet 11: packet error control does "
            "not match");
  EXPECT_EQ(refusal(with(",\n  \"event_actions\": [{\"event\": 7, \"request\": \"xyz\"}]")),
            "7:34: \"request\" must be a TC as an even number of hex digits");
}

TEST(PusMission, EveryErrorIsReported) {
  const LoadResult result = parse_mission(
      "{\"apid\": 1, \"parameters\": [{\"id\": 1}], \"events\": [{\"id\": 1, \"name\": \"e\", "
      "\"severity\": \"dire\"}]}");
  // One missing member per absent key of the parameter (name, type, initial, min, max), then
  // the severity.
  ASSERT_EQ(result.diagnostics.size(), 6U);
  EXPECT_EQ(format_diagnostics("m.json", {result.diagnostics.back()}),
            "m.json:1:74: error: unknown severity \"dire\" (informative, low, medium, high)\n");
}

TEST(PusMission, FileRepositoryIsResolvedAgainstTheMissionsFolder) {
  EXPECT_TRUE(parse_mission(with("")).mission->file_repository.empty());
  // `  "file_repository": ""` on line 7: the key starts at column 3.
  EXPECT_EQ(refusal(with(",\n  \"file_repository\": \"\"")), "7:3: expected a folder, got \"\"");
  const auto folder = std::filesystem::temp_directory_path() / "pus_mission_repository_test";
  std::filesystem::create_directories(folder);
  for (const auto& [root, expected] : {std::pair{"files/a", (folder / "files/a").string()},
                                       std::pair{"/srv/x", std::string("/srv/x")}}) {
    std::ofstream(folder / "m.json")
        << with(",\n  \"file_repository\": \"" + std::string(root) + "\"");
    const LoadResult result = load_mission((folder / "m.json").string());
    ASSERT_TRUE(result.mission.has_value());
    EXPECT_EQ(result.mission->file_repository, expected);
  }
  std::filesystem::remove_all(folder);
}

TEST(PusMission, UnreadableFile) {
  const LoadResult result = load_mission("/nonexistent/mission.json");
  ASSERT_EQ(result.diagnostics.size(), 1U);
  EXPECT_EQ(result.diagnostics[0].message, "cannot read the file");
}

}  // namespace
}  // namespace smcbip::pus::mission
