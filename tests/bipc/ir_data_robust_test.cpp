// The IR data decoder on malformed input: clear errors naming the field, and never a crash on
// truncated, corrupted or hostile bytes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "bipc/ir/ir_data.h"
#include "bipc/ir/ir_text.h"
#include "ir_data_test_util.h"

namespace smcbip::bipc {
namespace {

using ir_data_test::sample_system;
using nlohmann::json;

/// The message from_data gives for `data`, or "(accepted)".
std::string error_of(const json& data) {
  try {
    ir::from_data(data);
  } catch (const ir::IrDataError& e) {
    return e.message;
  }
  return "(accepted)";
}

/// The sample's data with one change.
json changed(const std::function<void(json&)>& change) {
  json data = ir::to_data(sample_system());
  change(data);
  return data;
}

TEST(IrDataErrors, MessagesNameTheField) {
  const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
      {[](json& d) { d = json::array(); }, "(top): expected an object, got array"},
      {[](json& d) { d.erase("strings"); }, "(top): missing field 'strings'"},
      {[](json& d) { d["format"] = "other"; }, "format: not \"smcbip-ir\""},
      {[](json& d) { d["version"] = 1; }, "version: version 1 is not the supported 2"},
      {[](json& d) { d["atom_types"][0]["name"] = 3; },
       "atom_types[0].name: expected a string, got number"},
      {[](json& d) { d["atoms"][0]["extra"] = 1; }, "atoms[0]: unknown field 'extra'"},
      {[](json& d) { d["atom_types"][0]["clocks"][0]["unit"] = "fortnight"; },
       "atom_types[0].clocks[0].unit: unknown name 'fortnight'"},
      {[](json& d) { d["atom_types"][0]["transitions"][0]["to"][0] = 9; },
       "atom_types[0].transitions[0].to[0]: index 9 out of range (2 places)"},
      {[](json& d) { d["atom_types"][0]["transitions"][0]["to"][0] = -1; },
       "atom_types[0].transitions[0].to[0]: -1 out of range"},
      {[](json& d) { d["atom_types"][0]["transitions"][0]["to"][0] = nullptr; },
       "atom_types[0].transitions[0].to[0]: null where one of the places is required"},
      {[](json& d) { d["atom_types"][0]["transitions"][0]["to"][0] = 4294967295u; },
       "atom_types[0].transitions[0].to[0]: kNone is written null"},
      {[](json& d) { d["atom_types"][0]["transitions"][1]["action"]["instrs"][1][4] = 5; },
       "atom_types[0].transitions[1].action.instrs[1][4]: index 5 out of range (2 clocks)"},
      {[](json& d) { d["atom_types"][0]["transitions"][1]["guard"]["instrs"][3][4] = 7; },
       "atom_types[0].transitions[1].guard.instrs[3][4]: index 7 out of range (7 instructions"
       " and the end)"},
      {[](json& d) { d["atom_types"][0]["transitions"][1]["guard"]["instrs"][0][4] = 3; },
       "atom_types[0].transitions[1].guard.instrs[0][4]: index 3 out of range (3 strings)"},
      {[](json& d) { d["connector_types"][0]["interactions"][0]["up"]["instrs"][0][2] = "clock"; },
       "connector_types[0].interactions[0].up.instrs[0][2]: scope clock is not available in "
       "this code"},
      {[](json& d) { d["connector_types"][0]["interactions"][0]["up"]["instrs"][0][3] = 1; },
       "connector_types[0].interactions[0].up.instrs[0][3]: index 1 out of range (1 parameters "
       "of the port type)"},
      {[](json& d) { d["atom_types"][0]["transitions"][0]["guard"]["instrs"][0][3] = 70000; },
       "atom_types[0].transitions[0].guard.instrs[0][3]: 70000 out of range"},
      {[](json& d) { d["atom_types"][0]["transitions"][0]["guard"]["instrs"][0].erase(6); },
       "atom_types[0].transitions[0].guard.instrs[0]: expected 7 elements, got 6"},
      {[](json& d) { d["atom_types"][0]["transitions"][1]["action"]["instrs"][3][6] = 2; },
       "atom_types[0].transitions[1].action.instrs[3][6]: index 2 out of range (2 sites)"},
      {[](json& d) { d["atom_types"][0]["transitions"][0]["guard"]["instrs"][1][5] = 1.5; },
       "atom_types[0].transitions[0].guard.instrs[1][5]: expected an integer, got number"},
      {[](json& d) { d["atom_types"][0]["transitions"][0]["guard"]["id"] = 1000; },
       "atom_types[0].transitions[0].guard.id: code id 1000 not below code_count"},
      {[](json& d) { d["atoms"][0]["params"][0]["f"] = std::nan(""); },
       "atoms[0].params[0].f: a non-finite number must be written \"f64:...\""},
      {[](json& d) { d["atoms"][0]["params"][0]["f"] = "f64:3ff0000000000000"; },
       "atoms[0].params[0].f: a finite number must be written as a number"},
      {[](json& d) { d["atoms"][0]["params"][0]["f"] = "f64:zz"; },
       "atoms[0].params[0].f: expected a floating-point number or \"f64:\" and 16 hex digits"},
      {[](json& d) { d["atoms"][0]["params"].erase(1); },
       "atoms[0].params: 1 elements where the atom type's parameter list has 2"},
      {[](json& d) { d["atoms"][0]["type"] = 5; },
       "atoms[0].type: index 5 out of range (2 atom types)"},
      {[](json& d) { d["compounds"][1]["parent"] = 2; },
       "compounds[1].parent: index 2 out of range (1 compounds before this one)"},
      {[](json& d) { d["compounds"][0]["parent"] = 1; },
       "compounds[0].parent: the root has a parent"},
      {[](json& d) { d["compounds"][1]["exported_data"]["xx"][1] = 2; },
       "compounds[1].exported_data.xx[1]: index 2 out of range (2 data of the atom's type)"},
      {[](json& d) { d["compounds"][1]["exported_ports"]["in"][0]["kind"] = "port"; },
       "compounds[1].exported_ports.in[0].kind: unknown name 'port'"},
      {[](json& d) {
         d["connectors"][0]["bound"][0][0] = {{"kind", "connector"}, {"instance", 1}, {"port", 0}};
       },
       "connectors[1].bound: connectors bind each other's exports in a cycle"},
      {[](json& d) { d["functions"][0]["params"][0]["extern_type"] = nullptr; },
       "functions[0].params[0].extern_type: null where one of the extern types is required"},
      {[](json& d) { d["functions"][0]["result"]["extern_type"] = 0; },
       "functions[0].result.extern_type: set on a data type of kind float"},
      {[](json& d) { d["atom_types"][0]["ports"][0]["data"] = json::array(); },
       "atom_types[0].ports[0].data: 0 elements where the port type's parameter list has 1"},
      {[](json& d) { d["connector_types"][0]["define"][1]["children"][0]["port"] = 2; },
       "connector_types[0].define[1].children[0].port: index 2 out of range (2 ports of the "
       "connector type)"},
  };
  for (const auto& [change, expected] : cases) {
    const std::string message = error_of(changed(change));
    EXPECT_TRUE(message.starts_with(expected)) << "expected: " << expected << "\ngot: " << message;
  }
}

/// A connector type's define list nested `depth` levels deep.
std::vector<ir::DefineNode> nested_define(std::size_t depth) {
  ir::DefineNode node{0, {}, false};
  for (std::size_t level = 1; level < depth; ++level) {
    ir::DefineNode parent{ir::kNone, {}, false};
    parent.children.push_back(std::move(node));
    node = std::move(parent);
  }
  return {node};
}

TEST(IrDataErrors, DefineTreesUpToTheLimitRoundTrip) {
  ir::System s = sample_system();
  s.connector_types[1].define = nested_define(ir::kMaxDefineDepth);
  const ir::System back = ir::from_bytes(ir::to_bytes(s));
  EXPECT_EQ(ir::to_bytes(back), ir::to_bytes(s));
  s.connector_types[1].define = nested_define(ir::kMaxDefineDepth + 1);
  EXPECT_NE(error_of(ir::to_data(s)).find("define tree deeper than"), std::string::npos);
}

/// What from_bytes does with `bytes`: "" when it returns a System, else its message.
std::string bytes_error(std::span<const std::uint8_t> bytes) {
  try {
    ir::from_bytes(bytes);
  } catch (const ir::IrDataError& e) {
    return e.message.empty() ? "(empty message)" : e.message;
  }
  return "";
}

TEST(IrDataBytes, HostileCborIsRejected) {
  // A million nested arrays, definite and indefinite: nlohmann's reader would recurse a million
  // times.
  for (std::uint8_t opener : {std::uint8_t{0x81}, std::uint8_t{0x9f}}) {
    std::vector<std::uint8_t> deep(1'000'000, opener);
    deep.push_back(0xf6);
    EXPECT_NE(bytes_error(deep).find("nested more than"), std::string::npos);
  }
  // Lengths far beyond the input.
  const std::vector<std::uint8_t> huge_array = {0x9b, 0xff, 0xff, 0xff, 0xff,
                                                0xff, 0xff, 0xff, 0xff};
  EXPECT_NE(bytes_error(huge_array), "");
  const std::vector<std::uint8_t> huge_string = {0x7b, 0x7f, 0xff, 0xff, 0xff,
                                                 0xff, 0xff, 0xff, 0xff, 0x61};
  EXPECT_NE(bytes_error(huge_string), "");
  EXPECT_NE(bytes_error({}), "");
  // A CBOR tag, and well-formed CBOR that is not an IR.
  EXPECT_NE(bytes_error(std::vector<std::uint8_t>{0xc1, 0x00}), "");
  EXPECT_NE(bytes_error(json::to_cbor(json{{"format", "smcbip-ir"}})), "");
  // Trailing bytes after a valid System.
  std::vector<std::uint8_t> bytes = ir::to_bytes(sample_system());
  EXPECT_EQ(bytes_error(bytes), "");
  bytes.push_back(0xf6);
  EXPECT_NE(bytes_error(bytes), "");
}

/// The bytes of a small real model (a rendezvous family member, with priorities in others).
std::vector<std::uint8_t> real_model_bytes() {
  const std::optional<ir::System> system = ir_data_test::load_system(
      ir_data_test::source_dir() / "models/families/priorities_10.bip", "", {});
  return system ? ir::to_bytes(*system) : std::vector<std::uint8_t>{};
}

TEST(IrDataBytes, EveryProperPrefixIsRejected) {
  for (const std::vector<std::uint8_t>& bytes :
       {real_model_bytes(), ir::to_bytes(sample_system())}) {
    ASSERT_FALSE(bytes.empty());
    ASSERT_EQ(bytes_error(bytes), "");
    std::size_t accepted = 0;
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      // A CBOR item with definite lengths is complete only at its last byte.
      if (bytes_error(std::span(bytes).first(n)).empty()) ++accepted;
    }
    EXPECT_EQ(accepted, 0u) << "of " << bytes.size() << " prefixes";
  }
}

TEST(IrDataBytes, RandomByteMutationsNeverCrash) {
  const std::vector<std::uint8_t> original = real_model_bytes();
  ASSERT_FALSE(original.empty());
  std::mt19937_64 random(20240611);  // fixed, so that a failure reproduces
  std::uniform_int_distribution<std::size_t> position(0, original.size() - 1);
  std::uniform_int_distribution<int> flip(1, 255);
  std::size_t rejected = 0, accepted = 0;
  for (int round = 0; round < 3000; ++round) {
    std::vector<std::uint8_t> bytes = original;
    bytes[position(random)] ^= static_cast<std::uint8_t>(flip(random));
    std::optional<ir::System> decoded;
    try {
      decoded = ir::from_bytes(bytes);
    } catch (const ir::IrDataError& e) {
      EXPECT_FALSE(e.message.empty());
      ++rejected;
      continue;
    }
    ++accepted;
    // What is accepted is a System the encoder and the outline can walk, and it re-encodes to
    // itself.
    // Compared as bytes: a flipped string byte may leave text that is not UTF-8, which
    // nlohmann refuses to dump as JSON text.
    const std::vector<std::uint8_t> again = ir::to_bytes(*decoded);
    EXPECT_TRUE(ir::to_bytes(ir::from_bytes(again)) == again) << "round " << round;
    EXPECT_FALSE(ir::to_text(*decoded).empty());
  }
  RecordProperty("rejected", std::to_string(rejected));
  RecordProperty("accepted", std::to_string(accepted));
  // Most flips break the structure; some only change a name or a number.
  EXPECT_GT(rejected, 1000u);
  EXPECT_GT(accepted, 0u);
}

}  // namespace
}  // namespace smcbip::bipc
