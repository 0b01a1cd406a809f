// Tests of the AADL interface view reader on real TASTE views (read from ../shared when present)
// and on hostile input (garbage, deep nesting, NULs, truncations): bounded errors, no crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "taste2bip/interface_view/interface_view.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip {
namespace {

namespace fs = std::filesystem;

const fs::path kShared = test::shared_data_dir();
using test::file_text;

struct Read {
  InterfaceView view;
  bipc::Diagnostics diags;
  bipc::SourceFiles files;
};

/// Reads `path` into `r`; false when the file is not there (a user's clone has no ../shared).
bool read_file(const fs::path& path, Read& r) {
  if (!fs::exists(path)) return false;
  r.view = read_aadl_interface_view(file_text(path), r.files.add(path.string()), r.diags);
  return true;
}

const Function& function(const InterfaceView& view, const std::string& name) {
  for (const Function& f : view.functions) {
    if (f.name == name) return f;
  }
  ADD_FAILURE() << "no function " << name;
  static const Function kNone;
  return kNone;
}

const Interface& pi(const Function& f, const std::string& name) {
  for (const Interface& i : f.provided) {
    if (i.name == name) return i;
  }
  ADD_FAILURE() << "no provided interface " << f.name << "." << name;
  static const Interface kNone;
  return kNone;
}

std::string describe(const Connection& c) {
  return c.from.function + "." + c.from.interface + (c.from.provided ? "(PI)" : "(RI)") + " -> " +
         c.to.function + "." + c.to.interface + (c.to.provided ? "(PI)" : "(RI)");
}

TEST(AadlRealViews, EsrocosWatchdogExactly) {
  Read r;
  if (!read_file(kShared / "esrocos-mc_watchdog/TasteModel/InterfaceView.aadl", r))
    GTEST_SKIP() << "the ESROCOS watchdog view (../shared/data) is not here";
  ASSERT_FALSE(r.diags.has_errors()) << r.diags.format(r.files);
  const InterfaceView& v = r.view;
  ASSERT_EQ(v.functions.size(), 5u);
  const char* const names[] = {"JoystickDriver", "CmdDispatcher", "Watchdog", "Logger",
                               "BLSClient"};
  const char* const languages[] = {"SDL", "SDL", "CPP", "SDL", "SDL"};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(v.functions[i].name, names[i]);
    EXPECT_EQ(v.functions[i].language, languages[i]);
    EXPECT_FALSE(v.functions[i].parent.has_value());
    EXPECT_TRUE(v.functions[i].context.empty());
  }
  // Kind, period, deadline, queue size and WCET of each PI, as the file writes them.
  struct Expected {
    const char* function;
    const char* interface;
    InterfaceKind kind;
    double period;
    std::optional<std::uint32_t> queue;
  };
  const Expected expected[] = {
      {"JoystickDriver", "step", InterfaceKind::Cyclic, 100, 1},
      {"CmdDispatcher", "cmd", InterfaceKind::Sporadic, 10, 1},
      {"Watchdog", "test_cmd", InterfaceKind::Sporadic, 10, 1},
      {"Watchdog", "purge", InterfaceKind::Cyclic, 80, std::nullopt},  // SUBPROGRAM PI_purge: none
      {"Logger", "log_cmd", InterfaceKind::Sporadic, 10, 1},
      {"BLSClient", "mot_cmd", InterfaceKind::Sporadic, 10, 1},
  };
  std::size_t provided = 0;
  for (const Function& f : v.functions) provided += f.provided.size();
  EXPECT_EQ(provided, 6u);
  for (const Expected& e : expected) {
    const Interface& i = pi(function(v, e.function), e.interface);
    EXPECT_EQ(i.kind, e.kind) << e.interface;
    EXPECT_EQ(i.period, e.period) << e.interface;
    EXPECT_EQ(i.deadline, 10.0) << e.interface;
    EXPECT_EQ(i.queue_size, e.queue) << e.interface;
    EXPECT_EQ(i.wcet_low, 0.0) << e.interface;
    EXPECT_EQ(i.wcet_high, 10.0) << e.interface;
    EXPECT_FALSE(i.dispatch_offset.has_value());
    const bool has_command =
        std::string(e.interface) != "step" && e.interface != std::string("purge");
    ASSERT_EQ(i.parameters.size(), has_command ? 1u : 0u) << e.interface;
    if (has_command) {
      EXPECT_EQ(i.parameters[0].name, "cmd_val");
      EXPECT_EQ(i.parameters[0].direction, Parameter::Direction::In);
      EXPECT_EQ(i.parameters[0].type, "Base_commands_Motion2D");  // ASN.1: Base-commands-Motion2D
    }
  }
  const Function& dispatcher = function(v, "CmdDispatcher");
  ASSERT_EQ(dispatcher.required.size(), 2u);
  EXPECT_EQ(dispatcher.required[0].name, "log_cmd");
  EXPECT_EQ(dispatcher.required[0].kind, InterfaceKind::Any);
  EXPECT_EQ(dispatcher.required[1].name, "test_cmd");
  EXPECT_EQ(dispatcher.required[1].parameters.at(0).type, "Base_commands_Motion2D");
  ASSERT_EQ(v.connections.size(), 4u);
  EXPECT_EQ(describe(v.connections[0]), "JoystickDriver.cmd(RI) -> CmdDispatcher.cmd(PI)");
  EXPECT_EQ(describe(v.connections[1]), "CmdDispatcher.log_cmd(RI) -> Logger.log_cmd(PI)");
  EXPECT_EQ(describe(v.connections[2]), "CmdDispatcher.test_cmd(RI) -> Watchdog.test_cmd(PI)");
  EXPECT_EQ(describe(v.connections[3]), "Watchdog.mot_cmd(RI) -> BLSClient.mot_cmd(PI)");
  EXPECT_EQ(v.connections[0].at.line, 317u);
  EXPECT_EQ(v.connections[0].at.column, 3u);
  EXPECT_TRUE(v.assumptions.empty());
}

TEST(AadlRealViews, EveryKazooViewReadsWithoutErrors) {
  const fs::path root = kShared / "taste" / "esa-kazoo";
  if (!fs::exists(root)) GTEST_SKIP() << "the kazoo views (../shared/data/taste) are not here";
  std::size_t views = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().filename() != "InterfaceView.aadl") continue;
    ++views;
    Read r;
    ASSERT_TRUE(read_file(entry.path(), r));
    EXPECT_FALSE(r.diags.has_errors()) << r.diags.format(r.files);
    EXPECT_GE(r.view.functions.size(), 2u) << entry.path();
    EXPECT_GE(r.view.connections.size(), 1u) << entry.path();
    for (const Function& f : r.view.functions) {
      for (const Interface& i : f.provided) {
        EXPECT_NE(i.kind, InterfaceKind::Any) << entry.path() << ": " << f.name << "." << i.name;
        EXPECT_TRUE(i.wcet_high.has_value()) << entry.path() << ": " << f.name << "." << i.name;
      }
    }
  }
  EXPECT_EQ(views, 18u);
}

/// Reads the kazoo view `folder`, or skips the test.
#define READ_KAZOO(folder, r)                                                     \
  Read r;                                                                         \
  if (!read_file(kShared / "taste/esa-kazoo" / folder / "InterfaceView.aadl", r)) \
    GTEST_SKIP() << "the kazoo views (../shared/data/taste) are not here";        \
  ASSERT_FALSE(r.diags.has_errors()) << r.diags.format(r.files)

TEST(AadlRealViews, DemoTimersTaste13) {
  READ_KAZOO("Demo_Timers", r);
  ASSERT_EQ(r.view.functions.size(), 4u);
  const Function& sdl = function(r.view, "sdl_fct");
  ASSERT_EQ(sdl.context.size(), 2u);
  EXPECT_EQ(sdl.context[0].name, "sdl_timer");
  EXPECT_EQ(sdl.context[0].type, "Timer");
  EXPECT_EQ(sdl.context[1].name, "fast_timer");
  const Interface& start = pi(sdl, "start_sdl_timer");
  EXPECT_EQ(start.kind, InterfaceKind::Sporadic);
  EXPECT_EQ(start.queue_size, 1u);
  EXPECT_EQ(start.wcet_high, 0.0);  // from the `start_sdl_timer_impl` subcomponent
  EXPECT_EQ(function(r.view, "gui").language, "GUI");
  ASSERT_EQ(r.view.connections.size(), 3u);  // the OpToPICnx_* are not function connections
  EXPECT_EQ(describe(r.view.connections[2]),
            "gui.start_sdl_timer(RI) -> sdl_fct.start_sdl_timer(PI)");
}

TEST(AadlRealViews, DemoUnprotectedTaste13) {
  READ_KAZOO("Demo_Unprotected", r);
  EXPECT_EQ(pi(function(r.view, "Function1"), "pulse").period, 1500.0);
  EXPECT_EQ(pi(function(r.view, "Function2"), "pulse").period, 1200.0);
  const Interface& unp = pi(function(r.view, "Function3"), "unp_pi");
  EXPECT_EQ(unp.kind, InterfaceKind::Unprotected);
  ASSERT_EQ(unp.parameters.size(), 2u);
  EXPECT_EQ(unp.parameters[1].name, "outp");
  EXPECT_EQ(unp.parameters[1].direction, Parameter::Direction::Out);
  EXPECT_EQ(r.view.connections.size(), 3u);
}

TEST(AadlRealViews, DemoContextParams) {
  READ_KAZOO("Demo_ContextParams", r);
  const Function& passive = function(r.view, "passive_function");
  ASSERT_EQ(passive.context.size(), 2u);
  EXPECT_EQ(passive.context[1].name, "test2");
  EXPECT_EQ(passive.context[1].type, "T_Int32");
  EXPECT_EQ(passive.context[1].value, "-42");
  EXPECT_EQ(function(r.view, "Function_in_Ada").context.at(1).value, "FALSE");
  EXPECT_EQ(pi(function(r.view, "cyclic_function"), "cyclic_activation").wcet_high, 500.0);
  EXPECT_EQ(pi(passive, "compute_data").deadline, 100.0);
  // An RI may state a kind of its own; it is kept as written.
  EXPECT_EQ(function(r.view, "cyclic_function").required.at(0).kind, InterfaceKind::Unprotected);
}

TEST(AadlRealViews, TrafficLightTimer) {
  READ_KAZOO("TrafficLight_Basic", r);
  const Function& controller = function(r.view, "Controller");
  ASSERT_EQ(controller.context.size(), 1u);
  EXPECT_EQ(controller.context[0].name, "clock");
  EXPECT_EQ(controller.context[0].type, "Timer");
  EXPECT_EQ(pi(controller, "Button").parameters.at(0).type, "Command");
  EXPECT_EQ(r.view.connections.size(), 4u);
}

TEST(AadlRealViews, E2esNestedFunctions) {
  READ_KAZOO("e2es_complete", r);
  ASSERT_EQ(r.view.functions.size(), 11u);
  const Function& inner = function(r.view, "GeometryModule_Interface");
  ASSERT_TRUE(inner.parent.has_value());
  EXPECT_EQ(r.view.functions[*inner.parent].name, "Geometry_Module");
  EXPECT_EQ(function(r.view, "GeometryModule_Implementation").context.at(0).value, "1");
  ASSERT_EQ(r.view.connections.size(), 15u);
  std::string all;
  for (const Connection& c : r.view.connections) all += describe(c) + "\n";
  EXPECT_NE(all.find("Geometry_Module.Module_In(PI) -> GeometryModule_Interface.Module_In(PI)\n"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("GeometryModule_Interface.Module_Out(RI) -> Geometry_Module.Module_Out(RI)\n"),
            std::string::npos)
      << all;
}

TEST(AadlRealViews, Msp430SporadicCallsProtected) {
  READ_KAZOO("msp430_calls/msp430_sporadic_calls_protected", r);
  const Interface& sporadic = pi(function(r.view, "function2"), "sporadic_interface");
  EXPECT_EQ(sporadic.queue_size, 5u);
  EXPECT_EQ(sporadic.deadline, 40.0);
  EXPECT_EQ(sporadic.wcet_high, 30.0);
  const Interface& cyclic = pi(function(r.view, "function1"), "cyclic_interface");
  EXPECT_EQ(cyclic.period, 800.0);
  EXPECT_EQ(cyclic.deadline, 5000.0);
  EXPECT_EQ(pi(function(r.view, "function3"), "protected_interface").kind,
            InterfaceKind::Protected);
}

/// Reading `text` ends, with at most the cap of errors (20 plus the one saying so).
void expect_bounded(const std::string& text) {
  bipc::Diagnostics diags;
  (void)read_aadl_interface_view(text, 0, diags);
  EXPECT_LE(diags.error_count(), 21u);
}

TEST(AadlRobustness, GarbageNestingNulsAndTruncations) {
  expect_bounded(std::string(1 << 20, '\0'));
  expect_bounded("PACKAGE p PUBLIC SYSTEM s PROPERTIES a => " + std::string(100000, '(') + ";");
  expect_bounded("PACKAGE p PUBLIC SYSTEM s PROPERTIES a => " + std::string(100000, ')') + ";");
  expect_bounded(std::string(100000, '{') + std::string(100000, '}'));
  expect_bounded("PACKAGE PACKAGE PACKAGE END END ; ; :: => -> .. \"");
  std::string noise;
  std::uint32_t state = 12345;  // a fixed xorshift sequence: the same bytes on every run
  for (int i = 0; i < 200000; ++i) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    noise += static_cast<char>(state & 0xff);
  }
  expect_bounded(noise);
  // Words of the language in a random order.
  const char* const words[] = {"PACKAGE",  "END", "SYSTEM", "IMPLEMENTATION",
                               "FEATURES", ";",   ":",      "::",
                               "=>",       "->",  "{",      "}",
                               "(",        ")",   "x",      "1",
                               "ms",       ".."};
  std::string soup;
  for (int i = 0; i < 50000; ++i) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    soup += words[state % 18];
    soup += ' ';
  }
  expect_bounded(soup);
  // Every prefix of a real view ends with errors, never a crash or a hang.
  const fs::path watchdog = kShared / "esrocos-mc_watchdog/TasteModel/InterfaceView.aadl";
  if (fs::exists(watchdog)) {
    const std::string text = file_text(watchdog);
    for (std::size_t n = 0; n < text.size(); n += 97) expect_bounded(text.substr(0, n));
  }
}

TEST(AadlRobustness, FunctionsNestedTooDeep) {
  // Each F<i> contains F<i+1>: the reader stops at its nesting cap with an error.
  std::string text;
  for (int i = 0; i < 40; ++i) {
    const std::string name = "F" + std::to_string(i);
    text += "PACKAGE interfaceview::IV::" + name + " PUBLIC SYSTEM " + name + " END " + name +
            "; SYSTEM IMPLEMENTATION " + name + ".others SUBCOMPONENTS F" + std::to_string(i + 1) +
            " : SYSTEM interfaceview::IV::F" + std::to_string(i + 1) + "::F" +
            std::to_string(i + 1) + ".others; END " + name +
            ".others; END interfaceview::IV::" + name + ";\n";
  }
  text +=
      "PACKAGE interfaceview::IV PUBLIC SYSTEM IMPLEMENTATION interfaceview.others SUBCOMPONENTS "
      "F0 : SYSTEM interfaceview::IV::F0::F0.others; END interfaceview.others; END "
      "interfaceview::IV;\n";
  bipc::Diagnostics diags;
  const InterfaceView view = read_aadl_interface_view(text, 0, diags);
  EXPECT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(view.functions.size(), 16u);
}

TEST(AadlRobustness, FunctionContainingItself) {
  const std::string text =
      "PACKAGE interfaceview::IV PUBLIC SYSTEM F END F; SYSTEM IMPLEMENTATION F.others "
      "SUBCOMPONENTS F : SYSTEM F.others; END F.others; SYSTEM IMPLEMENTATION interfaceview.others "
      "SUBCOMPONENTS F : SYSTEM F.others; END interfaceview.others; END interfaceview::IV;";
  bipc::Diagnostics diags;
  const InterfaceView view = read_aadl_interface_view(text, 0, diags);
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.all()[0].message, "function F contains itself");
  EXPECT_EQ(view.functions.size(), 1u);
}

}  // namespace
}  // namespace smcbip::taste2bip
