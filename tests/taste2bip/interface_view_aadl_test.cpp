// Tests of the AADL interface view reader: each construct TASTE writes, located errors, robustness.
#include <gtest/gtest.h>

#include <string>

#include "taste2bip/interface_view/interface_view.h"

namespace smcbip::taste2bip {
namespace {

struct Read {
  InterfaceView view;
  bipc::Diagnostics diags;
  bipc::SourceFiles files;
  std::string messages() const { return diags.format(files); }
};

Read read(const std::string& text) {
  Read r;
  const std::uint32_t file = r.files.add("iv.aadl");
  r.view = read_aadl_interface_view(text, file, r.diags);
  return r;
}

/// A 2.x view with one function `F` (type body `f_body`, implementation body `impl_body`) and the
/// top level's extra text `top` (subcomponents and connections).
std::string view_of(const std::string& packages, const std::string& top) {
  return packages +
         "PACKAGE interfaceview::IV\nPUBLIC\nSYSTEM interfaceview\nEND interfaceview;\n"
         "SYSTEM IMPLEMENTATION interfaceview.others\n" +
         top +
         "END interfaceview.others;\n"
         "PROPERTIES\n  Taste::version => \"2.0\";\nEND interfaceview::IV;\n";
}

std::string function_package(const std::string& name, const std::string& decls,
                             const std::string& features, const std::string& impl = "") {
  return "PACKAGE interfaceview::IV::" + name + "\nPUBLIC\nWITH Taste;\n" + decls + "SYSTEM " +
         name + "\nFEATURES\n" + features + "PROPERTIES\n  Source_Language => (SDL);\nEND " + name +
         ";\nSYSTEM IMPLEMENTATION " + name + ".others\n" + impl + "END " + name +
         ".others;\nEND interfaceview::IV::" + name + ";\n";
}

std::string subcomponent(const std::string& name) {
  return "  " + name + " : SYSTEM interfaceview::IV::" + name + "::" + name + ".others;\n";
}

std::string provided(const std::string& name, const std::string& props) {
  return "  PI_" + name + " : PROVIDES SUBPROGRAM ACCESS interfaceview::IV::F::PI_" + name +
         ".others {\n" + props + "    Taste::InterfaceName => \"" + name + "\";\n  };\n";
}

const std::string kSubprograms =
    "SUBPROGRAM PI_go\nFEATURES\n"
    "  x : IN PARAMETER DataView::T_Int32 { Taste::encoding => NATIVE; };\n"
    "  y : OUT PARAMETER DataView::My_Seq_Type;\n"
    "PROPERTIES\n  Taste::Associated_Queue_Size => 4;\nEND PI_go;\n"
    "SUBPROGRAM IMPLEMENTATION PI_go.others\nPROPERTIES\n"
    "  Compute_Execution_Time => 1 ms .. 2.5 ms;\nEND PI_go.others;\n";

TEST(AadlInterfaceView, SporadicInterfaceWithItsSubprogram) {
  const Read r = read(view_of(function_package("F", kSubprograms,
                                               provided("go",
                                                        "    Taste::RCMoperationKind => sporadic;\n"
                                                        "    Taste::RCMperiod => 20 ms;\n"
                                                        "    Taste::Deadline => 1 sec;\n")),
                              "SUBCOMPONENTS\n" + subcomponent("F")));
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  ASSERT_EQ(r.view.functions.size(), 1u);
  const Function& f = r.view.functions[0];
  EXPECT_EQ(f.name, "F");
  EXPECT_EQ(f.language, "SDL");
  EXPECT_FALSE(f.parent.has_value());
  EXPECT_EQ(f.at.line, 15u);
  ASSERT_EQ(f.provided.size(), 1u);
  const Interface& go = f.provided[0];
  EXPECT_EQ(go.name, "go");
  EXPECT_EQ(go.kind, InterfaceKind::Sporadic);
  EXPECT_EQ(go.period, 20.0);
  EXPECT_EQ(go.deadline, 1000.0);
  EXPECT_EQ(go.queue_size, 4u);
  EXPECT_EQ(go.wcet_low, 1.0);
  EXPECT_EQ(go.wcet_high, 2.5);
  EXPECT_FALSE(go.dispatch_offset.has_value());
  EXPECT_EQ(go.at.line, 17u);
  EXPECT_EQ(go.at.column, 3u);
  ASSERT_EQ(go.parameters.size(), 2u);
  EXPECT_EQ(go.parameters[0].name, "x");
  EXPECT_EQ(go.parameters[0].direction, Parameter::Direction::In);
  EXPECT_EQ(go.parameters[0].type, "T_Int32");
  EXPECT_EQ(go.parameters[1].name, "y");
  EXPECT_EQ(go.parameters[1].direction, Parameter::Direction::Out);
  // DataView.aadl spells ASN.1's '-' as '_': the reader keeps the AADL spelling.
  EXPECT_EQ(go.parameters[1].type, "My_Seq_Type");
  EXPECT_TRUE(r.view.connections.empty());
  EXPECT_TRUE(r.view.assumptions.empty());
}

TEST(AadlInterfaceView, EveryKindAndDispatchOffset) {
  const Read r = read(
      view_of(function_package("F", "",
                               provided("a",
                                        "    Taste::RCMoperationKind => cyclic;\n"
                                        "    Taste::RCMperiod => 100 ms;\n"
                                        "    Taste::Dispatch_Offset => 5 ms;\n") +
                                   provided("b", "    Taste::RCMoperationKind => PROTECTED;\n") +
                                   provided("c", "    Taste::RCMoperationKind => Unprotected;\n") +
                                   provided("d", "    Taste::RCMoperationKind => any;\n")),
              "SUBCOMPONENTS\n" + subcomponent("F")));
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  const auto& pis = r.view.functions.at(0).provided;
  ASSERT_EQ(pis.size(), 4u);
  EXPECT_EQ(pis[0].kind, InterfaceKind::Cyclic);
  EXPECT_EQ(pis[0].period, 100.0);
  EXPECT_EQ(pis[0].dispatch_offset, 5.0);
  EXPECT_EQ(pis[1].kind, InterfaceKind::Protected);
  EXPECT_EQ(pis[2].kind, InterfaceKind::Unprotected);
  EXPECT_EQ(pis[3].kind, InterfaceKind::Any);
  EXPECT_FALSE(pis[1].queue_size.has_value());
  EXPECT_FALSE(pis[1].wcet_high.has_value());
}

TEST(AadlInterfaceView, CyclicWithoutPeriodTakesTasteDefault) {
  const Read r = read(view_of(
      function_package("F", "", provided("tick", "    Taste::RCMoperationKind => cyclic;\n")),
      "SUBCOMPONENTS\n" + subcomponent("F")));
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  EXPECT_EQ(r.view.functions.at(0).provided.at(0).period, 1000.0);
  ASSERT_EQ(r.view.assumptions.size(), 1u);
  EXPECT_EQ(r.view.assumptions[0].text, "cyclic interface F.tick has no period: 1000 ms");
  EXPECT_EQ(r.view.assumptions[0].at.line, 6u);
}

TEST(AadlInterfaceView, ConnectionsGoFromRequiredToProvided) {
  const std::string caller = function_package(
      "A", "SUBPROGRAM RI_go\nFEATURES\n  v : IN PARAMETER DataView::T_Int32;\nEND RI_go;\n",
      "  RI_go : REQUIRES SUBPROGRAM ACCESS interfaceview::IV::F::PI_go.others {\n"
      "    Taste::RCMoperationKind => any;\n    Taste::InterfaceName => \"go\";\n  };\n");
  const std::string callee = function_package(
      "F", kSubprograms, provided("go", "    Taste::RCMoperationKind => sporadic;\n"));
  const Read r = read(
      view_of(caller + callee, "SUBCOMPONENTS\n" + subcomponent("A") + subcomponent("F") +
                                   "CONNECTIONS\n  F_PI_go_A_RI_go : SUBPROGRAM ACCESS F.PI_go -> "
                                   "A.RI_go { Taste::coordinates => \"1 2 3 4\"; };\n"));
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  ASSERT_EQ(r.view.functions.size(), 2u);
  const Interface& ri = r.view.functions[0].required.at(0);
  EXPECT_EQ(ri.name, "go");
  EXPECT_EQ(ri.kind, InterfaceKind::Any);
  ASSERT_EQ(ri.parameters.size(), 1u);  // the caller's own SUBPROGRAM RI_go
  EXPECT_EQ(ri.parameters[0].name, "v");
  ASSERT_EQ(r.view.connections.size(), 1u);
  const Connection& c = r.view.connections[0];
  EXPECT_EQ(c.from.function, "A");
  EXPECT_EQ(c.from.interface, "go");
  EXPECT_FALSE(c.from.provided);
  EXPECT_EQ(c.to.function, "F");
  EXPECT_EQ(c.to.interface, "go");
  EXPECT_TRUE(c.to.provided);
  EXPECT_EQ(c.at.column, 3u);
}

TEST(AadlInterfaceView, ContextParametersAndTimers) {
  const Read r = read(
      view_of(function_package(
                  "F", "", "",
                  "SUBCOMPONENTS\n"
                  "  limit : DATA DataView::T_INTEGER { Taste::FS_Default_Value => \"-42\"; };\n"
                  "  clock : DATA DataView::Timer { Taste::FS_Default_Value => \"toto\"; };\n"),
              "SUBCOMPONENTS\n" + subcomponent("F")));
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  const auto& context = r.view.functions.at(0).context;
  ASSERT_EQ(context.size(), 2u);
  EXPECT_EQ(context[0].name, "limit");
  EXPECT_EQ(context[0].type, "T_INTEGER");
  EXPECT_EQ(context[0].value, "-42");
  EXPECT_EQ(context[1].name, "clock");
  EXPECT_EQ(context[1].type, "Timer");
  EXPECT_EQ(context[1].value, "");
  EXPECT_EQ(context[1].at.line, 12u);
}

TEST(AadlInterfaceView, NestedFunctionsAndDelegations) {
  const std::string child =
      "PACKAGE interfaceview::IV::F::Inner\nPUBLIC\nSYSTEM Inner\nFEATURES\n"
      "  PI_go : PROVIDES SUBPROGRAM ACCESS { Taste::RCMoperationKind => sporadic; };\n"
      "END Inner;\nSYSTEM IMPLEMENTATION Inner.others\nEND Inner.others;\n"
      "END interfaceview::IV::F::Inner;\n";
  std::string parent = function_package(
      "F", "", provided("go", "    Taste::RCMoperationKind => sporadic;\n"),
      "SUBCOMPONENTS\n  Inner : SYSTEM interfaceview::IV::F::Inner::Inner.others;\n"
      "CONNECTIONS\n  d : SUBPROGRAM ACCESS Inner.PI_go -> PI_go;\n");
  const Read r = read(view_of(child + parent, "SUBCOMPONENTS\n" + subcomponent("F")));
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  ASSERT_EQ(r.view.functions.size(), 2u);
  EXPECT_EQ(r.view.functions[0].name, "F");
  EXPECT_EQ(r.view.functions[1].name, "Inner");
  EXPECT_EQ(r.view.functions[1].parent, 0u);
  ASSERT_EQ(r.view.connections.size(), 1u);
  const Connection& c = r.view.connections[0];
  EXPECT_EQ(c.from.function, "F");
  EXPECT_TRUE(c.from.provided);
  EXPECT_EQ(c.to.function, "Inner");
  EXPECT_EQ(c.to.interface, "go");
  EXPECT_TRUE(c.to.provided);
}

TEST(AadlInterfaceView, Taste13LayoutWithOperationSubcomponents) {
  const std::string text =
      "-- AADL2.0\n"
      "PACKAGE interfaceview::FV::F\nPUBLIC\n"
      "SUBPROGRAM PI_go\nPROPERTIES\n  Taste::Associated_Queue_Size => 2;\nEND PI_go;\n"
      "SUBPROGRAM IMPLEMENTATION PI_go.others\nEND PI_go.others;\n"
      "END interfaceview::FV::F;\n"
      "PACKAGE interfaceview::IV\nPUBLIC\n"
      "SYSTEM F\nFEATURES\n"
      "  PI_go : PROVIDES SUBPROGRAM ACCESS interfaceview::FV::F::PI_go.others {\n"
      "    Taste::RCMoperationKind => sporadic;\n    Taste::RCMperiod => 0 ms;\n  };\n"
      "PROPERTIES\n  Source_Language => (C);\nEND F;\n"
      "SYSTEM IMPLEMENTATION F.others\nSUBCOMPONENTS\n"
      "  go_impl : SUBPROGRAM interfaceview::FV::F::PI_go.others {\n"
      "    Compute_Execution_Time => 0 ms .. 3 ms;\n  };\n"
      "CONNECTIONS\n  OpToPICnx_go_impl : SUBPROGRAM ACCESS go_impl -> PI_go;\n"
      "END F.others;\n"
      "SYSTEM interfaceview\nEND interfaceview;\n"
      "SYSTEM IMPLEMENTATION interfaceview.others\nSUBCOMPONENTS\n"
      "  F : SYSTEM interfaceview::IV::F.others;\nEND interfaceview.others;\n"
      "PROPERTIES\n  Taste::version => \"1.3.17\";\nEND interfaceview::IV;\n";
  const Read r = read(text);
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  ASSERT_EQ(r.view.functions.size(), 1u);
  const Interface& go = r.view.functions[0].provided.at(0);
  EXPECT_EQ(go.name, "go");  // no InterfaceName: the feature name without PI_
  EXPECT_EQ(go.queue_size, 2u);
  EXPECT_EQ(go.period, 0.0);
  EXPECT_EQ(go.wcet_low, 0.0);
  EXPECT_EQ(go.wcet_high, 3.0);
  EXPECT_EQ(r.view.functions[0].language, "C");
  EXPECT_TRUE(r.view.connections.empty());  // OpToPICnx joins a PI to its code, not functions
}

TEST(AadlInterfaceView, KeywordsAndNamesIgnoreCase) {
  const std::string text =
      "package InterfaceView::iv::F public\n"
      "system f features\n"
      "  pi_Go : provides subprogram access {\n"
      "    taste::rcmOperationKind => Sporadic;\n  };\n"
      "end F;\n"
      "system implementation F.Others end f.others;\n"
      "end interfaceview::IV::f;\n"
      "Package interfaceview::IV Public\n"
      "System Implementation InterfaceView.Others Subcomponents\n"
      "  F : system interfaceview::iv::f::F.OTHERS;\n"
      "End interfaceview.others;\nend interfaceview::iv;\n";
  const Read r = read(text);
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  ASSERT_EQ(r.view.functions.size(), 1u);
  EXPECT_EQ(r.view.functions[0].provided.at(0).name, "Go");
  EXPECT_EQ(r.view.functions[0].provided.at(0).kind, InterfaceKind::Sporadic);
}

TEST(AadlInterfaceView, PropertiesTheModelDoesNotKeepAreSkipped) {
  const Read r =
      read(view_of(function_package("F", "",
                                    provided("go",
                                             "    Taste::RCMoperationKind => sporadic;\n"
                                             "    Taste::coordinates => \"1 2\";\n"
                                             "    Taste::labelInheritance => \"true\";\n"
                                             "    Some::List => (a, (b, \"c\"), 1 ms .. 2 ms);\n"
                                             "    Some::Record => [x => 1; y => (2, 3);];\n"
                                             "    Some::Ref => reference (F) applies to x.y;\n"
                                             "    Other::Value +=> -3.5e2 us;\n")),
                   "SUBCOMPONENTS\n" + subcomponent("F")));
  ASSERT_FALSE(r.diags.has_errors()) << r.messages();
  EXPECT_EQ(r.view.functions.at(0).provided.at(0).kind, InterfaceKind::Sporadic);
}

/// The single error of `text`, as `line:col: message`.
std::string only_error(const std::string& text) {
  const Read r = read(text);
  std::string out;
  for (const auto& d : r.diags.all()) {
    if (d.severity != bipc::Severity::Error) continue;
    if (!out.empty()) out += " | ";
    out += std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " +
           d.message;
  }
  return out;
}

TEST(AadlInterfaceViewErrors, LocatedWithWhatWasExpected) {
  const std::string kinds =
      view_of(function_package("F", "", provided("go", "    Taste::RCMoperationKind => often;\n")),
              "SUBCOMPONENTS\n" + subcomponent("F"));
  EXPECT_EQ(only_error(kinds),
            "7:32: expected cyclic, sporadic, protected, unprotected or any in "
            "Taste::RCMoperationKind, got 'often'");

  const std::string unit =
      view_of(function_package("F", "",
                               provided("go",
                                        "    Taste::RCMoperationKind => cyclic;\n"
                                        "    Taste::RCMperiod => 100 days;\n")),
              "SUBCOMPONENTS\n" + subcomponent("F"));
  EXPECT_EQ(only_error(unit),
            "8:29: expected a time unit (ps, ns, us, ms, sec, min or hr) in Taste::RCMperiod, "
            "got 'days'");

  EXPECT_EQ(only_error("PACKAGE p PUBLIC\nSYSTEM s\nPROPERTIES\n  A => 1\nEND s;\nEND p;\n"),
            "5:1: expected ';' after the value of A, got 'END'");
  EXPECT_EQ(only_error("PACKAGE p PUBLIC\nSYSTEM s\nEND t;\nEND p;\n"),
            "3:5: expected 'END s;', got 'END t'");
  EXPECT_EQ(only_error("PACKAGE p PUBLIC\n  x 1;\nEND p;\n"),
            "2:3: expected 'WITH', a component declaration, 'PROPERTIES' or 'END', got 'x'");
  EXPECT_EQ(only_error("PACKAGE p PUBLIC\n  PROPERTIES a => \"open\n;\nEND p;\n"),
            "2:19: unterminated string: expected '\"' before the end of the line");
  EXPECT_EQ(only_error("-- nothing\n"),
            "1:1: expected a TASTE interface view: a SYSTEM IMPLEMENTATION interfaceview.others "
            "(in PACKAGE interfaceview::IV)");
  EXPECT_EQ(only_error("PACKAGE p PUBLIC\n  SYSTEM s @\nEND s;\nEND p;"),
            "2:12: unexpected character '@': expected an AADL identifier, number, string or "
            "symbol");
  EXPECT_EQ(only_error(view_of("", "CONNECTIONS\n  c : SUBPROGRAM ACCESS X.PI_a -> Y.RI_b;\n")),
            "7:35: expected a function of this level, got 'Y'");
  EXPECT_EQ(only_error(view_of("", "SUBCOMPONENTS\n  G : SYSTEM nowhere::G.others;\n")),
            "7:14: expected the SYSTEM 'nowhere::G.others' of function G to be declared in this "
            "view");
}

TEST(AadlInterfaceViewErrors, InterfaceFactsOfTheWrongForm) {
  const std::string no_kind =
      view_of(function_package("F", "", provided("go", "")), "SUBCOMPONENTS\n" + subcomponent("F"));
  EXPECT_EQ(only_error(no_kind),
            "6:3: expected Taste::RCMoperationKind on provided interface PI_go");

  const std::string range = view_of(
      function_package("F",
                       "SUBPROGRAM PI_go\nEND PI_go;\nSUBPROGRAM IMPLEMENTATION PI_go.others\n"
                       "PROPERTIES\n  Compute_Execution_Time => 0 ms 10 ms;\nEND PI_go.others;\n",
                       provided("go", "    Taste::RCMoperationKind => sporadic;\n")),
      "SUBCOMPONENTS\n" + subcomponent("F"));
  EXPECT_EQ(only_error(range),
            "8:34: expected '..' and the upper bound in Compute_Execution_Time, got '10'");

  const std::string in_out = view_of(
      function_package(
          "F", "SUBPROGRAM PI_go\nFEATURES\n  v : IN OUT PARAMETER DataView::T;\nEND PI_go;\n",
          provided("go", "    Taste::RCMoperationKind => sporadic;\n")),
      "SUBCOMPONENTS\n" + subcomponent("F"));
  EXPECT_EQ(only_error(in_out), "6:3: expected an IN or OUT PARAMETER, got 'in out parameter'");

  const std::string queue = view_of(
      function_package(
          "F", "SUBPROGRAM PI_go\nPROPERTIES\n  Taste::Associated_Queue_Size => -1;\nEND PI_go;\n",
          provided("go", "    Taste::RCMoperationKind => sporadic;\n")),
      "SUBCOMPONENTS\n" + subcomponent("F"));
  EXPECT_EQ(only_error(queue),
            "6:35: expected a non-negative integer below 2^32 in Taste::Associated_Queue_Size, got "
            "'-'");
}

TEST(AadlInterfaceViewErrors, ConnectionBackwardsAndFunctionTwice) {
  const std::string backwards = view_of(
      function_package(
          "A", "", "  RI_go : REQUIRES SUBPROGRAM ACCESS { Taste::RCMoperationKind => any; };\n") +
          function_package("F", "", provided("go", "    Taste::RCMoperationKind => sporadic;\n")),
      "SUBCOMPONENTS\n" + subcomponent("A") + subcomponent("F") +
          "CONNECTIONS\n  c : SUBPROGRAM ACCESS A.RI_go -> F.PI_go;\n");
  EXPECT_EQ(only_error(backwards),
            "37:25: expected a provided interface before '->' and a required one after it, got "
            "required 'A.RI_go' -> provided 'F.PI_go'");
  const std::string twice = view_of(function_package("F", "", ""),
                                    "SUBCOMPONENTS\n" + subcomponent("F") + subcomponent("f"));
  EXPECT_EQ(only_error(twice), "19:3: expected one function f at this level, got a second one");
}

TEST(AadlInterfaceViewErrors, UnknownInterfaceOfAConnectedFunction) {
  const Read r = read(view_of(
      function_package("F", "", provided("go", "    Taste::RCMoperationKind => sporadic;\n")),
      "SUBCOMPONENTS\n" + subcomponent("F") +
          "CONNECTIONS\n  c : SUBPROGRAM ACCESS F.PI_go -> F.RI_stop;\n"));
  ASSERT_EQ(r.diags.error_count(), 1u) << r.messages();
  EXPECT_EQ(r.diags.all()[0].location.line, 24u);
  EXPECT_EQ(r.diags.all()[0].location.column, 36u);
  EXPECT_EQ(r.diags.all()[0].message, "expected an interface of function F, got 'RI_stop'");
  EXPECT_TRUE(r.view.connections.empty());
}

}  // namespace
}  // namespace smcbip::taste2bip
