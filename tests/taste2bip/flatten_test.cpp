// Flattening nested functions: delegations in and out, two levels, multicast, dangling chains,
// and the nested real views of the shared data.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "taste2bip/interface_view/interface_view.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip {
namespace {

std::string messages(const bipc::Diagnostics& diags) {
  bipc::SourceFiles files;
  files.add("iv.xml");
  return diags.format(files);
}

/// The flat view of an XML text, checked to read without errors.
InterfaceView flat_of(const std::string& text, bipc::Diagnostics& diags) {
  bipc::Diagnostics read_diags;
  const InterfaceView view = read_xml_interface_view(text, 0, read_diags);
  EXPECT_FALSE(read_diags.has_errors()) << messages(read_diags);
  return flatten(view, diags);
}

std::vector<std::string> names(const InterfaceView& view) {
  std::vector<std::string> out;
  for (const Function& f : view.functions) out.push_back(f.name);
  return out;
}

/// Connections as sorted `F.ri -> G.pi` lines.
std::vector<std::string> calls(const InterfaceView& view) {
  std::vector<std::string> out;
  for (const Connection& c : view.connections) {
    out.push_back(c.from.function + "." + c.from.interface + " -> " + c.to.function + "." +
                  c.to.interface);
  }
  std::sort(out.begin(), out.end());
  return out;
}

using Lines = std::vector<std::string>;

TEST(Flatten, ViewWithoutNestingIsUnchanged) {
  bipc::Diagnostics diags;
  const InterfaceView flat = flat_of(R"(<InterfaceView>
<Function name="A"><Required_Interface name="go" kind="Sporadic"/></Function>
<Function name="B"><Provided_Interface name="go" kind="Sporadic" miat="5"/></Function>
<Connection><Source func_name="A" ri_name="go"/><Target func_name="B" pi_name="go"/></Connection>
</InterfaceView>)",
                                     diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  EXPECT_EQ(names(flat), (Lines{"A", "B"}));
  EXPECT_EQ(calls(flat), (Lines{"A.go -> B.go"}));
  ASSERT_EQ(flat.connections.size(), 1u);
  EXPECT_EQ(flat.connections[0].at.line, 4u);
  EXPECT_EQ(flat.functions[1].provided[0].period, 5.0);
}

// Manager -> Worker.doWork -> (in) Contractor.doWork; Contractor.inform -> (out) Worker.inform
// -> Logger.inform: the shape of spacecreator's iv_remote_control, with Contractor a leaf.
constexpr const char* kDelegations = R"(<InterfaceView>
<Function name="Worker">
<Provided_Interface name="doWork" kind="Sporadic"/>
<Required_Interface name="inform" kind="Sporadic"/>
<Function name="Contractor">
<Provided_Interface name="doWork" kind="Sporadic"/>
<Required_Interface name="inform" kind="Sporadic"/>
</Function>
<Function name="Dummy"/>
<Connection><Source func_name="Worker" pi_name="doWork"/><Target func_name="Contractor" pi_name="doWork"/></Connection>
<Connection><Source func_name="Contractor" ri_name="inform"/><Target func_name="Worker" ri_name="inform"/></Connection>
</Function>
<Function name="Logger"><Provided_Interface name="inform" kind="Sporadic"/></Function>
<Function name="Manager"><Required_Interface name="doWork" kind="Sporadic"/></Function>
<Connection><Source func_name="Worker" ri_name="inform"/><Target func_name="Logger" pi_name="inform"/></Connection>
<Connection><Source func_name="Manager" ri_name="doWork"/><Target func_name="Worker" pi_name="doWork"/></Connection>
</InterfaceView>)";

TEST(Flatten, DelegationInAndOut) {
  bipc::Diagnostics diags;
  const InterfaceView flat = flat_of(kDelegations, diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  EXPECT_EQ(names(flat), (Lines{"Contractor", "Dummy", "Logger", "Manager"}));
  for (const Function& f : flat.functions) EXPECT_FALSE(f.parent.has_value()) << f.name;
  EXPECT_EQ(calls(flat),
            (Lines{"Contractor.inform -> Logger.inform", "Manager.doWork -> Contractor.doWork"}));
  // A flat connection is located at the connection leaving the caller.
  for (const Connection& c : flat.connections) {
    EXPECT_EQ(c.at.line, c.from.function == "Manager" ? 16u : 11u) << c.from.function;
  }
}

TEST(Flatten, EndpointsWrittenBackwardsAreTurnedRound) {
  std::string text = kDelegations;
  // The parent PI -> child PI delegation written child first, the call written PI first.
  const std::string in =
      R"(<Source func_name="Worker" pi_name="doWork"/><Target func_name="Contractor" pi_name="doWork"/>)";
  text.replace(
      text.find(in), in.size(),
      R"(<Source func_name="Contractor" pi_name="doWork"/><Target func_name="Worker" pi_name="doWork"/>)");
  const std::string call =
      R"(<Source func_name="Manager" ri_name="doWork"/><Target func_name="Worker" pi_name="doWork"/>)";
  text.replace(
      text.find(call), call.size(),
      R"(<Source func_name="Worker" pi_name="doWork"/><Target func_name="Manager" ri_name="doWork"/>)");
  bipc::Diagnostics diags;
  const InterfaceView flat = flat_of(text, diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  EXPECT_EQ(calls(flat),
            (Lines{"Contractor.inform -> Logger.inform", "Manager.doWork -> Contractor.doWork"}));
}

TEST(Flatten, TwoLevelsAndMulticast) {
  bipc::Diagnostics diags;
  const InterfaceView flat = flat_of(R"(<InterfaceView>
<Function name="Top">
<Provided_Interface name="cmd" kind="Sporadic"/>
<Required_Interface name="report" kind="Sporadic"/>
<Function name="Mid">
<Provided_Interface name="cmd" kind="Sporadic"/>
<Required_Interface name="report" kind="Sporadic"/>
<Function name="Leaf">
<Provided_Interface name="cmd" kind="Sporadic"/>
<Required_Interface name="report" kind="Sporadic"/>
</Function>
<Connection><Source func_name="Mid" pi_name="cmd"/><Target func_name="Leaf" pi_name="cmd"/></Connection>
<Connection><Source func_name="Leaf" ri_name="report"/><Target func_name="Mid" ri_name="report"/></Connection>
</Function>
<Connection><Source func_name="Top" pi_name="cmd"/><Target func_name="Mid" pi_name="cmd"/></Connection>
<Connection><Source func_name="Mid" ri_name="report"/><Target func_name="Top" ri_name="report"/></Connection>
</Function>
<Function name="Ground">
<Provided_Interface name="report" kind="Sporadic"/>
<Required_Interface name="cmd" kind="Sporadic"/>
</Function>
<Function name="Log"><Provided_Interface name="report" kind="Protected"/></Function>
<Connection><Source func_name="Ground" ri_name="cmd"/><Target func_name="Top" pi_name="cmd"/></Connection>
<Connection><Source func_name="Top" ri_name="report"/><Target func_name="Ground" pi_name="report"/></Connection>
<Connection><Source func_name="Top" ri_name="report"/><Target func_name="Log" pi_name="report"/></Connection>
</InterfaceView>)",
                                     diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  EXPECT_EQ(names(flat), (Lines{"Leaf", "Ground", "Log"}));
  EXPECT_EQ(calls(flat), (Lines{"Ground.cmd -> Leaf.cmd", "Leaf.report -> Ground.report",
                                "Leaf.report -> Log.report"}));
}

TEST(Flatten, DanglingDelegationIsAnErrorAtTheConnection) {
  bipc::Diagnostics diags;
  (void)flat_of(R"(<InterfaceView>
<Function name="P">
<Provided_Interface name="go" kind="Sporadic"/>
<Required_Interface name="out" kind="Sporadic"/>
<Function name="C"><Required_Interface name="out" kind="Sporadic"/></Function>
  <Connection><Source func_name="C" ri_name="out"/><Target func_name="P" ri_name="out"/></Connection>
</Function>
<Function name="U"><Required_Interface name="go" kind="Sporadic"/></Function>
 <Connection><Source func_name="U" ri_name="go"/><Target func_name="P" pi_name="go"/></Connection>
</InterfaceView>)",
                diags);
  EXPECT_EQ(messages(diags),
            "iv.xml:6:3: error: connection delegates to `P.out`, which is connected to nothing: "
            "expected a connection from it to a provided interface\n"
            "iv.xml:9:2: error: connection reaches `P.go`, which P delegates to none of its "
            "functions: expected a connection from it to a child's provided interface\n");
}

TEST(Flatten, UnknownEndpointsAndBadDelegationsAreErrors) {
  bipc::Diagnostics diags;
  const InterfaceView flat = flat_of(R"(<InterfaceView>
<Function name="A"><Required_Interface name="r" kind="Sporadic"/></Function>
<Function name="B"><Required_Interface name="r" kind="Sporadic"/></Function>
<Connection><Source func_name="A" ri_name="r"/><Target func_name="Nobody" pi_name="p"/></Connection>
<Connection><Source func_name="A" ri_name="r"/><Target func_name="B" pi_name="p"/></Connection>
<Connection><Source func_name="A" ri_name="r"/><Target func_name="B" ri_name="r"/></Connection>
<Function name="A"/>
</InterfaceView>)",
                                     diags);
  EXPECT_EQ(messages(diags),
            "iv.xml:7:1: error: function `A` is declared twice (first at 2:1): expected unique "
            "function names\n"
            "iv.xml:4:1: error: connection names function `Nobody`: expected the name of a "
            "function of the view\n"
            "iv.xml:5:1: error: connection names provided interface `B.p`: expected one of B's "
            "provided interfaces\n"
            "iv.xml:6:1: error: connection joins two required interfaces: expected a function's "
            "and one of its children's (a child RI delegated to a parent RI)\n");
  EXPECT_TRUE(flat.connections.empty());
}

TEST(Flatten, HandMadeCyclesAndBadParentsTerminate) {
  // The XML reader cannot nest a function in itself; a view built by hand can.
  InterfaceView view;
  view.functions.resize(3);
  view.functions[0].name = "A";
  view.functions[0].parent = 1;
  view.functions[0].provided.resize(1);
  view.functions[0].provided[0].name = "p";
  view.functions[0].required.resize(1);
  view.functions[0].required[0].name = "r";
  view.functions[1].name = "B";
  view.functions[1].parent = 0;
  view.functions[1].provided.resize(1);
  view.functions[1].provided[0].name = "p";
  view.functions[2].name = "C";
  view.functions[2].parent = 99;
  view.connections.push_back({{"A", "p", true}, {"B", "p", true}, {}});
  view.connections.push_back({{"B", "p", true}, {"A", "p", true}, {}});
  view.connections.push_back({{"A", "r", false}, {"B", "p", true}, {}});
  bipc::Diagnostics diags;
  const InterfaceView flat = flatten(view, diags);
  EXPECT_EQ(names(flat), (Lines{"C"}));
  EXPECT_TRUE(flat.connections.empty());
}

// ---- The nested real views ----

InterfaceView read_real(const std::string& relative, bool& skipped) {
  const std::filesystem::path path = test::shared_data_dir() / "taste" / relative;
  skipped = !std::filesystem::exists(path);
  if (skipped) return {};
  bipc::Diagnostics diags;
  InterfaceView view = read_xml_interface_view(test::file_text(path), 0, diags);
  EXPECT_FALSE(diags.has_errors()) << messages(diags);
  return view;
}

TEST(FlattenReal, SpacecreatorRemoteControl) {
  bool skipped = false;
  const InterfaceView view =
      read_real("esa-spacecreator/iv_remote_control/interfaceview.xml", skipped);
  if (skipped) GTEST_SKIP() << "no ../shared/data/taste next to the source tree";
  bipc::Diagnostics diags;
  const InterfaceView flat = flatten(view, diags);
  // Contractor holds two functions but delegates doWork to neither: the editor example stops
  // there, so Manager's call reaches no leaf.
  EXPECT_EQ(messages(diags),
            "iv.xml:58:1: error: connection reaches `Contractor.doWork`, which Contractor "
            "delegates to none of its functions: expected a connection from it to a child's "
            "provided interface\n");
  EXPECT_EQ(names(flat),
            (Lines{"PowerGenerator", "PowerController", "Dummy", "Logger", "Manager"}));
  EXPECT_TRUE(flat.connections.empty());
}

TEST(FlattenReal, RtemsStress) {
  bool skipped = false;
  const InterfaceView view =
      read_real("n7space-TASTE-SAMV71-RTEMS-Tests/samv71-rtems-stress/interfaceview.xml", skipped);
  if (skipped) GTEST_SKIP() << "no ../shared/data/taste next to the source tree";
  bipc::Diagnostics diags;
  const InterfaceView flat = flatten(view, diags);
  EXPECT_EQ(diags.all().size(), 0u) << messages(diags);
  EXPECT_EQ(flat.functions.size(), 130u);  // Function_105 gives way to its 16 children
  for (const Function& f : flat.functions) EXPECT_NE(f.name, "Function_105");
  // 128 top-level connections, 16 of them at Function_105's border, re-routed one to one, plus
  // the 8 calls between its children.
  EXPECT_EQ(flat.connections.size(), 136u);
  const std::vector<std::string> all = calls(flat);
  for (const char* expected : {"Function_101.PI_4 -> Function_109.PI_1",     // delegated in
                               "Function_120.RI_1 -> Function_130.PI_1",     // delegated out
                               "Function_115.RI_1 -> Function_125.PI_1",     // out, renamed RI
                               "Function_106.PI_1 -> Function_115.PI_1"}) {  // inside
    EXPECT_TRUE(std::find(all.begin(), all.end(), expected) != all.end()) << expected;
  }
  for (const Connection& c : flat.connections) {
    EXPECT_NE(c.from.function, "Function_105");
    EXPECT_NE(c.to.function, "Function_105");
  }
}

}  // namespace
}  // namespace smcbip::taste2bip
