// The XML interface view reader: each construct on a small inline view, located errors, and the
// real interfaceview.xml files of the shared data.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "taste2bip/interface_view/interface_view.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip {
namespace {

InterfaceView read(const std::string& text, bipc::Diagnostics& diags) {
  return read_xml_interface_view(text, 0, diags);
}

std::string messages(const bipc::Diagnostics& diags) {
  bipc::SourceFiles files;
  files.add("iv.xml");
  return diags.format(files);
}

const Function* find_function(const InterfaceView& view, const std::string& name) {
  for (const Function& f : view.functions) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

const Interface* find_interface(const std::vector<Interface>& list, const std::string& name) {
  for (const Interface& i : list) {
    if (i.name == name) return &i;
  }
  return nullptr;
}

TEST(XmlInterfaceView, FunctionsNestingAndLanguage) {
  bipc::Diagnostics diags;
  const InterfaceView view = read(R"(<InterfaceView version="1.1">
<Function id="{a}" name="Outer" is_type="NO" language="SDL" default_implementation="default">
    <Property name="Taste::coordinates" value="1 2 3 4"/>
    <Function name="Inner" is_type="NO" default_implementation="second">
        <Implementations>
            <Implementation name="default" language="C"/>
            <Implementation name="second" language="Ada"/>
        </Implementations>
    </Function>
</Function>
<Function name="Kind" is_type="YES"/>
</InterfaceView>)",
                                  diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  ASSERT_EQ(view.functions.size(), 3u);
  EXPECT_EQ(view.functions[0].name, "Outer");
  EXPECT_EQ(view.functions[0].language, "SDL");
  EXPECT_FALSE(view.functions[0].parent.has_value());
  EXPECT_FALSE(view.functions[0].is_type);
  EXPECT_EQ(view.functions[0].at.line, 2u);
  EXPECT_EQ(view.functions[0].at.column, 1u);
  EXPECT_EQ(view.functions[1].name, "Inner");
  EXPECT_EQ(view.functions[1].language, "Ada");  // the default implementation's
  EXPECT_EQ(view.functions[1].parent, std::optional<std::size_t>(0));
  EXPECT_EQ(view.functions[1].at.line, 4u);
  EXPECT_EQ(view.functions[1].at.column, 5u);
  EXPECT_EQ(view.functions[2].name, "Kind");
  EXPECT_TRUE(view.functions[2].is_type);
  EXPECT_EQ(view.functions[2].language, "");
}

TEST(XmlInterfaceView, InterfaceKindsAndTiming) {
  bipc::Diagnostics diags;
  const InterfaceView view = read(R"(<InterfaceView>
<Function name="F" language="C">
<Provided_Interface name="tick" kind="Cyclic" period="250" deadline="200" dispatch_offset="10" wcet="3.5"/>
<Provided_Interface name="cmd" kind="Sporadic" miat="40" queue_size="7" priority="1" stack_size="50"/>
<Provided_Interface name="get" kind="Protected" wcet="0"/>
<Provided_Interface name="put" kind="Unprotected"/>
<Required_Interface name="out" kind="Sporadic" miat="0" queue_size="1"/>
<Required_Interface name="any"/>
</Function>
</InterfaceView>)",
                                  diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  ASSERT_EQ(view.functions.size(), 1u);
  const Function& f = view.functions[0];
  ASSERT_EQ(f.provided.size(), 4u);
  ASSERT_EQ(f.required.size(), 2u);
  const Interface& tick = f.provided[0];
  EXPECT_EQ(tick.kind, InterfaceKind::Cyclic);
  EXPECT_EQ(tick.period, 250.0);
  EXPECT_EQ(tick.deadline, 200.0);
  EXPECT_EQ(tick.dispatch_offset, 10.0);
  EXPECT_EQ(tick.wcet_low, 3.5);
  EXPECT_EQ(tick.wcet_high, 3.5);
  EXPECT_EQ(tick.at.line, 3u);
  const Interface& cmd = f.provided[1];
  EXPECT_EQ(cmd.kind, InterfaceKind::Sporadic);
  EXPECT_EQ(cmd.period, 40.0);  // the MIAT
  EXPECT_EQ(cmd.queue_size, 7u);
  EXPECT_FALSE(cmd.deadline.has_value());
  EXPECT_FALSE(cmd.wcet_low.has_value());
  EXPECT_EQ(f.provided[2].kind, InterfaceKind::Protected);
  EXPECT_EQ(f.provided[2].wcet_low, 0.0);
  EXPECT_EQ(f.provided[3].kind, InterfaceKind::Unprotected);
  EXPECT_FALSE(f.provided[3].period.has_value());
  EXPECT_EQ(f.required[0].name, "out");
  EXPECT_EQ(f.required[0].kind, InterfaceKind::Sporadic);
  EXPECT_EQ(f.required[0].period, 0.0);
  EXPECT_EQ(f.required[0].queue_size, 1u);
  EXPECT_EQ(f.required[1].kind, InterfaceKind::Any);
  EXPECT_TRUE(view.assumptions.empty());
}

TEST(XmlInterfaceView, CyclicWithoutPeriodAssumesTheEditorDefault) {
  bipc::Diagnostics diags;
  const InterfaceView view = read(R"(<InterfaceView>
<Function name="Ctrl" language="C">
  <Provided_Interface name="pulse" kind="Cyclic" dispatch_offset="150"/>
</Function>
</InterfaceView>)",
                                  diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  const Interface& pulse = view.functions.at(0).provided.at(0);
  EXPECT_EQ(pulse.period, 1000.0);
  EXPECT_EQ(pulse.dispatch_offset, 150.0);
  ASSERT_EQ(view.assumptions.size(), 1u);
  EXPECT_EQ(view.assumptions[0].text, "cyclic interface Ctrl.pulse has no period: 1000 ms");
  EXPECT_EQ(view.assumptions[0].at.line, 3u);
  EXPECT_EQ(view.assumptions[0].at.column, 3u);
}

TEST(XmlInterfaceView, ParametersAndContextParameters) {
  bipc::Diagnostics diags;
  const InterfaceView view = read(R"(<InterfaceView>
<Function name="F" language="SDL">
    <ContextParameter name="t" type="Timer" value=""/>
    <ContextParameter name="gain" type="T-INTEGER" value="42"/>
<Provided_Interface name="exec" kind="Unprotected">
    <Input_Parameter name="inp" type="T-SEQUENCE" encoding="NATIVE"/>
    <Output_Parameter name="outp" type="T-INTEGER" encoding="ACN"/>
</Provided_Interface>
</Function>
</InterfaceView>)",
                                  diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  const Function& f = view.functions.at(0);
  ASSERT_EQ(f.context.size(), 2u);
  EXPECT_EQ(f.context[0].name, "t");
  EXPECT_EQ(f.context[0].type, "Timer");
  EXPECT_EQ(f.context[0].value, "");
  EXPECT_EQ(f.context[1].name, "gain");
  EXPECT_EQ(f.context[1].type, "T-INTEGER");
  EXPECT_EQ(f.context[1].value, "42");
  EXPECT_EQ(f.context[1].at.line, 4u);
  EXPECT_EQ(f.context[1].at.column, 5u);
  const Interface& exec = f.provided.at(0);
  ASSERT_EQ(exec.parameters.size(), 2u);
  EXPECT_EQ(exec.parameters[0].direction, Parameter::Direction::In);
  EXPECT_EQ(exec.parameters[0].name, "inp");
  EXPECT_EQ(exec.parameters[0].type, "T-SEQUENCE");
  EXPECT_EQ(exec.parameters[1].direction, Parameter::Direction::Out);
  EXPECT_EQ(exec.parameters[1].name, "outp");
  EXPECT_EQ(exec.parameters[1].type, "T-INTEGER");
  EXPECT_EQ(exec.parameters[1].at.line, 7u);
}

TEST(XmlInterfaceView, ConnectionsAtEveryLevel) {
  bipc::Diagnostics diags;
  const InterfaceView view = read(R"(<InterfaceView version="1.3">
<Function name="P" language="C">
<Connection id="{1}">
    <Source iface_id="{x}" func_name="P" pi_name="go"/>
    <Target iface_id="{y}" func_name="C" pi_name="go"/>
</Connection>
</Function>
<Connection >
    <Source func_name="A" ri_name="go"/>
    <Target func_name="P" pi_name="go"/>
    <Property name="Taste::coordinates" value="1 2 3 4"/>
</Connection>
</InterfaceView>)",
                                  diags);
  ASSERT_FALSE(diags.has_errors()) << messages(diags);
  ASSERT_EQ(view.connections.size(), 2u);
  const Connection& inner = view.connections[0];
  EXPECT_EQ(inner.from.function, "P");
  EXPECT_EQ(inner.from.interface, "go");
  EXPECT_TRUE(inner.from.provided);
  EXPECT_EQ(inner.to.function, "C");
  EXPECT_TRUE(inner.to.provided);
  EXPECT_EQ(inner.at.line, 3u);
  const Connection& outer = view.connections[1];
  EXPECT_EQ(outer.from.function, "A");
  EXPECT_FALSE(outer.from.provided);
  EXPECT_EQ(outer.to.function, "P");
  EXPECT_TRUE(outer.to.provided);
  EXPECT_EQ(outer.at.line, 8u);
  EXPECT_EQ(outer.at.column, 1u);
}

// Each bad input yields exactly this located error (first line of the output).
struct BadCase {
  const char* what;
  const char* text;
  const char* error;
};

class XmlInterfaceViewErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(XmlInterfaceViewErrors, AreLocated) {
  bipc::Diagnostics diags;
  (void)read(GetParam().text, diags);
  ASSERT_TRUE(diags.has_errors()) << GetParam().what;
  EXPECT_EQ(messages(diags), GetParam().error) << GetParam().what;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, XmlInterfaceViewErrors,
    ::testing::Values(
        BadCase{"function without a name",
                "<InterfaceView>\n  <Function language=\"C\"/>\n</InterfaceView>",
                "iv.xml:2:3: error: function without name: expected attribute `name=\"...\"`\n"},
        BadCase{"interface without kind",
                "<InterfaceView>\n<Function name=\"F\">\n    <Provided_Interface name=\"p\"/>\n"
                "</Function>\n</InterfaceView>",
                "iv.xml:3:5: error: provided interface without kind: expected attribute "
                "`kind=\"Cyclic|Sporadic|Protected|Unprotected\"`\n"},
        BadCase{"unknown kind",
                "<InterfaceView>\n<Function name=\"F\">\n<Provided_Interface name=\"p\" "
                "kind=\"Periodic\"/>\n</Function>\n</InterfaceView>",
                "iv.xml:3:1: error: expected kind Cyclic, Sporadic, Protected or Unprotected, "
                "got \"Periodic\"\n"},
        BadCase{"period not a number",
                "<InterfaceView>\n<Function name=\"F\">\n<Provided_Interface name=\"p\" "
                "kind=\"Cyclic\" period=\"10 ms\"/>\n</Function>\n</InterfaceView>",
                "iv.xml:3:1: error: expected `period` to be a non-negative number of ms, got "
                "\"10 ms\"\n"},
        BadCase{"negative queue size",
                "<InterfaceView>\n<Function name=\"F\">\n<Provided_Interface name=\"p\" "
                "kind=\"Sporadic\" queue_size=\"-1\"/>\n</Function>\n</InterfaceView>",
                "iv.xml:3:1: error: expected `queue_size` to be a non-negative integer, got "
                "\"-1\"\n"},
        BadCase{"parameter without type",
                "<InterfaceView>\n<Function name=\"F\">\n<Provided_Interface name=\"p\" "
                "kind=\"Sporadic\">\n  <Input_Parameter name=\"x\"/>\n</Provided_Interface>\n"
                "</Function>\n</InterfaceView>",
                "iv.xml:4:3: error: parameter without type: expected attribute `type=\"...\"`\n"},
        BadCase{"context parameter without type",
                "<InterfaceView>\n<Function name=\"F\">\n <ContextParameter name=\"t\"/>\n"
                "</Function>\n</InterfaceView>",
                "iv.xml:3:2: error: context parameter without type: expected attribute "
                "`type=\"...\"`\n"},
        BadCase{"is_type neither YES nor NO",
                "<InterfaceView>\n<Function name=\"F\" is_type=\"maybe\"/>\n</InterfaceView>",
                "iv.xml:2:1: error: expected `is_type` to be YES or NO, got \"maybe\"\n"},
        BadCase{"connection without a target",
                "<InterfaceView>\n<Connection>\n<Source func_name=\"A\" ri_name=\"r\"/>\n"
                "</Connection>\n</InterfaceView>",
                "iv.xml:2:1: error: connection without <Target>: expected <Target "
                "func_name=\"...\" ri_name|pi_name=\"...\"/>\n"},
        BadCase{"endpoint with neither ri_name nor pi_name",
                "<InterfaceView>\n<Connection>\n<Source func_name=\"A\" ri_name=\"r\"/>\n"
                "   <Target func_name=\"B\"/>\n</Connection>\n</InterfaceView>",
                "iv.xml:4:4: error: connection Target without ri_name and pi_name: expected "
                "exactly one of them\n"},
        BadCase{"mismatched closing tag",
                "<InterfaceView>\n<Function name=\"F\">\n</Funtion>\n</InterfaceView>",
                "iv.xml:3:3: error: malformed XML: expected the closing tag of the open "
                "element\n"},
        BadCase{"unclosed root", "<InterfaceView>\n<Function name=\"F\"/>\n",
                "iv.xml:3:1: error: malformed XML: the text ends inside an element: expected its "
                "closing tag\n"},
        BadCase{"empty text", "",
                "iv.xml:1:1: error: expected an <InterfaceView> element, got no element\n"},
        BadCase{"another root", "<?xml version=\"1.0\"?>\n<DeploymentView/>",
                "iv.xml:2:1: error: expected an <InterfaceView> element, got <DeploymentView>\n"}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
      return "Case" + std::to_string(info.index);
    });

TEST(XmlInterfaceView, BinaryGarbageDoesNotCrash) {
  std::string text = "<InterfaceView><Function name=\"\xff\xfe\0\x01\"";
  text.push_back('\0');
  text += "</InterfaceView>";
  bipc::Diagnostics diags;
  (void)read(text, diags);
  EXPECT_TRUE(diags.has_errors());
}

TEST(XmlInterfaceView, DeepNestingIsAnErrorNotACrash) {
  std::string text = "<InterfaceView>\n";
  for (int i = 0; i < 100000; ++i) text += "<Function name=\"f\">";
  for (int i = 0; i < 100000; ++i) text += "</Function>";
  text += "\n</InterfaceView>";
  bipc::Diagnostics diags;
  const InterfaceView view = read(text, diags);
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.all()[0].location.line, 2u);
  EXPECT_EQ(diags.all()[0].location.column, 200u * 19u + 1u);
  EXPECT_EQ(diags.all()[0].message, "function nested 201 levels deep: expected at most 200");
  EXPECT_EQ(view.functions.size(), 200u);
}

// ---- The real views of ../shared/data/taste (absent from a user's clone) ----

std::string data_path(const std::string& relative) {
  return (test::shared_data_dir() / "taste" / relative).string();
}

/// Reads a real view; sets `skipped` when the shared data is not there.
InterfaceView read_real(const std::string& relative, bool& skipped) {
  const std::string path = data_path(relative);
  skipped = !std::filesystem::exists(path);
  if (skipped) return {};
  bipc::Diagnostics diags;
  InterfaceView view = read_xml_interface_view(test::file_text(path), 0, diags);
  EXPECT_EQ(diags.all().size(), 0u) << relative << "\n" << messages(diags);
  return view;
}

#define READ_REAL_OR_SKIP(view, relative)                   \
  bool skipped_ = false;                                    \
  const InterfaceView view = read_real(relative, skipped_); \
  if (skipped_) GTEST_SKIP() << "no ../shared/data/taste next to the source tree"

TEST(XmlInterfaceViewReal, EveryTruncationIsAnErrorNotACrash) {
  const std::string path = data_path("esa-spacecreator/iv_remote_control/interfaceview.xml");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no ../shared/data/taste";
  const std::string text = test::file_text(path);
  for (std::size_t size = 0; size + 2 < text.size(); size += 7) {
    bipc::Diagnostics diags;
    (void)read(text.substr(0, size), diags);
    EXPECT_TRUE(diags.has_errors()) << "truncated at " << size;
    for (const bipc::Diagnostic& d : diags.all()) {
      EXPECT_GE(d.location.line, 1u);
      EXPECT_GE(d.location.column, 1u);
    }
  }
}

TEST(XmlInterfaceViewReal, FreertosExample) {
  READ_REAL_OR_SKIP(view, "n7space-TASTE-SAMV71-Demo/freertos-example/interfaceview.xml");
  EXPECT_EQ(view.functions.size(), 4u);
  EXPECT_EQ(view.connections.size(), 5u);
  EXPECT_TRUE(view.assumptions.empty());
  const Function* clock = find_function(view, "Clock");
  ASSERT_NE(clock, nullptr);
  EXPECT_EQ(clock->language, "C");
  const Interface* clk = find_interface(clock->provided, "ClkInterface");
  ASSERT_NE(clk, nullptr);
  EXPECT_EQ(clk->kind, InterfaceKind::Cyclic);
  EXPECT_EQ(clk->period, 1000.0);
  EXPECT_EQ(clk->dispatch_offset, 0.0);
  const Function* buzzer = find_function(view, "Buzzer");
  ASSERT_NE(buzzer, nullptr);
  const Interface* result = find_interface(buzzer->provided, "Result");
  ASSERT_NE(result, nullptr);
  EXPECT_EQ(result->kind, InterfaceKind::Unprotected);
  ASSERT_EQ(result->parameters.size(), 1u);
  EXPECT_EQ(result->parameters[0].name, "ResultArg");
  EXPECT_EQ(result->parameters[0].type, "MyInteger");
  const Interface* fizzing = find_interface(buzzer->provided, "Fizzing");
  ASSERT_NE(fizzing, nullptr);
  EXPECT_EQ(fizzing->kind, InterfaceKind::Sporadic);
  EXPECT_EQ(fizzing->queue_size, 1u);
  EXPECT_EQ(fizzing->period, 0.0);
  EXPECT_EQ(buzzer->required.size(), 2u);
}

TEST(XmlInterfaceViewReal, RtemsInterfaces) {
  READ_REAL_OR_SKIP(view,
                    "n7space-TASTE-SAMV71-RTEMS-Tests/samv71-rtems-interfaces/interfaceview.xml");
  ASSERT_EQ(view.functions.size(), 3u);
  const Function* test = find_function(view, "testfunction");
  ASSERT_NE(test, nullptr);
  const Interface* loop = find_interface(test->provided, "test_loop");
  ASSERT_NE(loop, nullptr);
  EXPECT_EQ(loop->kind, InterfaceKind::Cyclic);
  EXPECT_EQ(loop->period, 1000.0);  // no period attribute: the editor default
  EXPECT_EQ(loop->dispatch_offset, 150.0);
  const Interface* out = find_interface(test->provided, "protected_provided_if_with_params_out");
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(out->kind, InterfaceKind::Protected);
  ASSERT_EQ(out->parameters.size(), 5u);
  EXPECT_EQ(out->parameters[4].direction, Parameter::Direction::Out);
  EXPECT_EQ(out->parameters[1].type, "MySeq");
  bool assumed_loop = false;
  for (const Assumption& a : view.assumptions) {
    if (a.text == "cyclic interface testfunction.test_loop has no period: 1000 ms") {
      assumed_loop = true;
    }
  }
  EXPECT_TRUE(assumed_loop);
}

TEST(XmlInterfaceViewReal, RtemsSdlC) {
  READ_REAL_OR_SKIP(view, "n7space-TASTE-SAMV71-RTEMS-Tests/samv71-rtems-sdl-c/interfaceview.xml");
  ASSERT_EQ(view.functions.size(), 2u);
  const Function* trigger = find_function(view, "triggerfunction");
  ASSERT_NE(trigger, nullptr);
  const Interface* t = find_interface(trigger->provided, "trigger");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->period, 200.0);
  const Function* sdl = find_function(view, "testfunction");
  ASSERT_NE(sdl, nullptr);
  EXPECT_EQ(sdl->language, "SDL");
  EXPECT_EQ(find_interface(sdl->provided, "ping")->kind, InterfaceKind::Sporadic);
}

TEST(XmlInterfaceViewReal, RtemsSdlTimers) {
  READ_REAL_OR_SKIP(view,
                    "n7space-TASTE-SAMV71-RTEMS-Tests/samv71-rtems-sdl-timers/interfaceview.xml");
  ASSERT_EQ(view.functions.size(), 2u);
  const Function* sdl = find_function(view, "triggerfunction");
  ASSERT_NE(sdl, nullptr);
  ASSERT_EQ(sdl->context.size(), 1u);
  EXPECT_EQ(sdl->context[0].name, "test_timer");
  EXPECT_EQ(sdl->context[0].type, "Timer");
  const Function* checker = find_function(view, "testfunction");
  ASSERT_NE(checker, nullptr);
  bool has_700 = false;
  for (const Interface& i : checker->provided) has_700 |= i.period == 700.0;
  EXPECT_TRUE(has_700);
}

TEST(XmlInterfaceViewReal, RtemsTimerResolution) {
  READ_REAL_OR_SKIP(
      view, "n7space-TASTE-SAMV71-RTEMS-Tests/samv71-rtems-timer-resolution/interfaceview.xml");
  ASSERT_EQ(view.functions.size(), 2u);
  EXPECT_EQ(view.connections.size(), 2u);
  const Function* sdl = find_function(view, "triggerfunction");
  ASSERT_NE(sdl, nullptr);
  ASSERT_EQ(sdl->context.size(), 2u);
  EXPECT_EQ(sdl->context[1].name, "timer2");
  EXPECT_EQ(sdl->context[1].type, "Timer");
  EXPECT_EQ(find_interface(sdl->provided, "trigger")->period, 1000.0);
  ASSERT_EQ(view.assumptions.size(), 1u);
  EXPECT_EQ(view.assumptions[0].text,
            "cyclic interface triggerfunction.trigger has no period: "
            "1000 ms");
  EXPECT_EQ(view.assumptions[0].at.line, 6u);
  EXPECT_EQ(find_interface(find_function(view, "testfunction")->provided, "trigger_check")->period,
            50.0);
}

TEST(XmlInterfaceViewReal, RtemsStress) {
  READ_REAL_OR_SKIP(view, "n7space-TASTE-SAMV71-RTEMS-Tests/samv71-rtems-stress/interfaceview.xml");
  EXPECT_EQ(view.functions.size(), 131u);
  EXPECT_EQ(view.connections.size(), 152u);
  const Function* parent = find_function(view, "Function_105");
  ASSERT_NE(parent, nullptr);
  EXPECT_EQ(parent->provided.size(), 8u);
  std::size_t parent_index = static_cast<std::size_t>(parent - view.functions.data());
  std::size_t children = 0;
  for (const Function& f : view.functions) children += f.parent == parent_index ? 1 : 0;
  EXPECT_EQ(children, 16u);
}

TEST(XmlInterfaceViewReal, SpacecreatorRemoteControl) {
  READ_REAL_OR_SKIP(view, "esa-spacecreator/iv_remote_control/interfaceview.xml");
  ASSERT_EQ(view.functions.size(), 7u);
  EXPECT_EQ(view.connections.size(), 4u);
  const Function* contractor = find_function(view, "Contractor");
  ASSERT_NE(contractor, nullptr);
  ASSERT_TRUE(contractor->parent.has_value());
  EXPECT_EQ(view.functions[*contractor->parent].name, "Worker");
  const Function* generator = find_function(view, "PowerGenerator");
  ASSERT_NE(generator, nullptr);
  ASSERT_TRUE(generator->parent.has_value());
  EXPECT_EQ(view.functions[*generator->parent].name, "Contractor");
  EXPECT_EQ(generator->language, "SDL");
  // Contractor's RI names no kind attributes beyond `kind`: no timing.
  const Interface* inform = find_interface(contractor->required, "inform");
  ASSERT_NE(inform, nullptr);
  EXPECT_EQ(inform->kind, InterfaceKind::Sporadic);
  EXPECT_FALSE(inform->queue_size.has_value());
}

}  // namespace
}  // namespace smcbip::taste2bip
