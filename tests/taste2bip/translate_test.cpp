// The translation's data and contracts: ASN.1 values as scalar leaves, function signatures, and
// whole designs whose BIP the front end accepts.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "taste2bip/sdl/sdl_reader.h"
#include "taste2bip/translate/bip_types.h"
#include "taste2bip/translate/package.h"
#include "taste2bip/translate/signature.h"
#include "tests/taste2bip/view_builders.h"

namespace smcbip::taste2bip {
namespace {

asn1::DataView resolved(const std::string& text, bipc::Diagnostics& diags) {
  asn1::DataView view;
  asn1::read_asn1(text, 0, view, diags);
  asn1::resolve(view, diags);
  return view;
}

/// `suffix:type` of each leaf, comma-separated.
std::string outline(const std::vector<Leaf>& leaves) {
  std::string out;
  for (const Leaf& leaf : leaves) out += (out.empty() ? "" : ", ") + leaf.suffix + ":" + leaf.type;
  return out;
}

const char* const kTypes = R"(M DEFINITIONS AUTOMATIC TAGS ::= BEGIN
  T-Double ::= REAL
  Angle ::= SEQUENCE { rad T-Double }
  Motion2D ::= SEQUENCE { translation T-Double, rotation T-Double, heading Angle }
  Mode ::= ENUMERATED { idle, run(5) }
  Count ::= INTEGER (0..255)
  Pick ::= CHOICE { a BOOLEAN, b Mode }
  Opt ::= SEQUENCE { x INTEGER (0..9) OPTIONAL, y BOOLEAN }
  Fixed ::= SEQUENCE (SIZE (2)) OF INTEGER (0..3)
  Varying ::= SEQUENCE (SIZE (0..3)) OF Angle
  Big ::= SEQUENCE (SIZE (1..100)) OF INTEGER (0..3)
  Bytes ::= OCTET STRING (SIZE (4))
  Name ::= IA5String (SIZE (1..8))
  Holder ::= SEQUENCE { data Bytes, n NULL }
END
)";

std::string leaves_text(const std::string& type) {
  bipc::Diagnostics diags;
  const asn1::DataView view = resolved(kTypes, diags);
  EXPECT_FALSE(diags.has_errors());
  const auto leaves = leaves_of(view, type, {}, diags);
  return leaves ? outline(*leaves) : "not found";
}

TEST(TranslateLeaves, ScalarsAreOneLeafWithoutSuffix) {
  EXPECT_EQ(leaves_text("T-Double"), ":float");
  EXPECT_EQ(leaves_text("Mode"), ":int");
  EXPECT_EQ(leaves_text("Name"), ":string");
}

TEST(TranslateLeaves, SequencesSpreadOverTheirFieldsAtAnyDepth) {
  EXPECT_EQ(leaves_text("Motion2D"), "translation:float, rotation:float, heading_rad:float");
}

TEST(TranslateLeaves, ChoicesOptionalsAndArraysKeepTheirBookkeeping) {
  EXPECT_EQ(leaves_text("Pick"), "present:int, a:bool, b:int");
  EXPECT_EQ(leaves_text("Opt"), "x_exist:bool, x:int, y:bool");
  EXPECT_EQ(leaves_text("Fixed"), "0:int, 1:int");
  EXPECT_EQ(leaves_text("Varying"), "length:int, 0_rad:float, 1_rad:float, 2_rad:float");
}

TEST(TranslateLeaves, WhatHasNoBoundedScalarFormStaysExtern) {
  EXPECT_EQ(leaves_text("Big"), ":asn1SccBig");
  EXPECT_EQ(leaves_text("Bytes"), ":asn1SccBytes");
  EXPECT_EQ(leaves_text("Holder"), "data:asn1SccBytes");
}

TEST(TranslateLeaves, TypesAreFoundAsEveryViewSpellsThem) {
  bipc::Diagnostics diags;
  const asn1::DataView view = resolved(kTypes, diags);
  EXPECT_TRUE(find_type_spelled(view, "Motion2D"));
  EXPECT_TRUE(find_type_spelled(view, "t_double"));  // AADL's '_', SDL's any case
  EXPECT_FALSE(find_type_spelled(view, "Motion3D"));
  const auto none = leaves_of(view, "Motion3D", bipc::Location{0, 4, 7}, diags);
  EXPECT_FALSE(none);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].location.line, 4u);
}

TEST(TranslatePortTypes, EqualTypeListsShareOnePortType) {
  EXPECT_EQ(port_type_name({}), "Port");
  EXPECT_EQ(port_type_name({"float", "float", "int", "bool"}), "Port_ffib");
  EXPECT_EQ(port_type_name({"asn1SccBytes", "int"}), "Port_xasn1SccBytes_i");
  EXPECT_NE(port_type_name({"int", "int"}), port_type_name({"int"}));
}

using test::interface;
using test::parameter;

/// A design of two C functions: Caller's cyclic `tick` calls Callee's protected `get(in x, out
/// y)` and sporadic `put(v)`.
Design small_design(bipc::Diagnostics& diags, InterfaceKind get_kind) {
  Design design;
  design.data = resolved(kTypes, diags);
  Function caller{"Caller", "C", {}, {}, {}, std::nullopt, false, {}};
  Interface tick = interface("tick", InterfaceKind::Cyclic);
  tick.period = 100.0;
  tick.deadline = 20.0;
  tick.dispatch_offset = 0.0;
  tick.wcet_low = 1.0;
  tick.wcet_high = 2.0;
  caller.provided.push_back(tick);
  using Direction = Parameter::Direction;
  Interface get = interface(
      "get", InterfaceKind::Any,
      {parameter(Direction::In, "x", "Mode"), parameter(Direction::Out, "y", "Motion2D")});
  Interface put = interface("put", InterfaceKind::Any, {parameter(Direction::In, "v", "Angle")});
  caller.required = {get, put};
  Function callee{"Callee", "C", {}, {}, {}, std::nullopt, false, {}};
  get.kind = get_kind;
  put.kind = InterfaceKind::Sporadic;
  put.queue_size = 2;
  callee.provided = {get, put};
  design.view.functions = {caller, callee};
  design.view.connections = {{{"Caller", "get", false}, {"Callee", "get", true}, {}},
                             {{"Caller", "put", false}, {"Callee", "put", true}, {}}};
  return design;
}

TEST(TranslateSignature, InterfacesCarryTheirParametersLeavesAndReachedKinds) {
  bipc::Diagnostics diags;
  Design design = small_design(diags, InterfaceKind::Protected);
  const FunctionSignature caller = function_signature(design.view, 0, design.data, diags);
  EXPECT_FALSE(diags.has_errors());
  ASSERT_EQ(caller.required.size(), 2u);
  EXPECT_TRUE(caller.required[0].synchronous());
  EXPECT_FALSE(caller.required[1].synchronous());
  EXPECT_EQ(caller.required[0].data_names(false), std::vector<std::string>{"get_x"});
  EXPECT_EQ(caller.required[0].data_names(true),
            (std::vector<std::string>{"get_y_translation", "get_y_rotation", "get_y_heading_rad"}));
  const std::string ports = interface_declarations(caller);
  EXPECT_NE(ports.find("export port Port_i get_out(get_x)"), std::string::npos) << ports;
  EXPECT_NE(ports.find("export port Port_fff get_result(get_y_translation, get_y_rotation, "
                       "get_y_heading_rad)"),
            std::string::npos)
      << ports;
  EXPECT_NE(ports.find("export port Port tick_return()"), std::string::npos) << ports;
}

TEST(TranslateSignature, ARequiredInterfaceNamedLikeAProvidedOneGetsItsOwnData) {
  bipc::Diagnostics diags;
  Design design = small_design(diags, InterfaceKind::Protected);
  design.view.functions[1].required.push_back(design.view.functions[0].required[1]);  // put
  const FunctionSignature callee = function_signature(design.view, 1, design.data, diags);
  EXPECT_EQ(callee.provided[1].data_names(false), std::vector<std::string>{"put_v_rad"});
  EXPECT_EQ(callee.required[0].data_names(false), std::vector<std::string>{"put_ri_v_rad"});
}

TEST(TranslateDesign, EveryCallKindAndWcetModeGivesBipTheFrontEndAccepts) {
  for (InterfaceKind kind :
       {InterfaceKind::Protected, InterfaceKind::Unprotected, InterfaceKind::Sporadic}) {
    for (Wcet wcet : {Wcet::Zero, Wcet::Interval, Wcet::Uniform}) {
      bipc::Diagnostics diags;
      Design design = small_design(diags, kind);
      if (kind == InterfaceKind::Sporadic) {  // a sporadic interface has no out parameters
        design.view.functions[0].required[0].parameters.pop_back();
        design.view.functions[1].provided[0].parameters.pop_back();
      }
      PackageOptions options;
      options.wcet = wcet;
      const auto packages = translate(design, options, diags);
      ASSERT_TRUE(packages) << static_cast<int>(kind) << diags.format({});
      EXPECT_EQ(bipc_diagnostics(packages->nominal, "taste"), "") << packages->nominal;
      EXPECT_NE(packages->faulty.find("atom type Caller_faulty()"), std::string::npos);
    }
  }
}

TEST(TranslateDesign, ASporadicInterfaceWithOutParametersIsRefusedAtIt) {
  bipc::Diagnostics diags;
  Design design = small_design(diags, InterfaceKind::Sporadic);
  design.view.functions[1].provided[0].at = bipc::Location{0, 9, 3};
  EXPECT_FALSE(translate(design, {}, diags));
  ASSERT_TRUE(diags.has_errors());
  EXPECT_EQ(diags.all()[0].location.line, 9u);
  EXPECT_NE(diags.all()[0].message.find("out parameters"), std::string::npos);
}

TEST(TranslateDesign, AnUnconnectedRequiredInterfaceIsReported) {
  bipc::Diagnostics diags;
  Design design = small_design(diags, InterfaceKind::Protected);
  design.view.connections.pop_back();
  const auto packages = translate(design, {}, diags);
  ASSERT_TRUE(packages);
  EXPECT_NE(packages->report.find("Caller.put: connected to nothing"), std::string::npos)
      << packages->report;
  EXPECT_EQ(bipc_diagnostics(packages->nominal, "taste"), "");
}

}  // namespace
}  // namespace smcbip::taste2bip

namespace smcbip::taste2bip {
namespace {

/// What bipc's front end says of a package without a root ("" when it checks).
std::string package_diagnostics(const std::string& text) {
  bipc::LoadedModel model;
  bipc::Diagnostics diags;
  model.packages.push_back(bipc::parse_package(text, model.files.add("faulty.bip"), diags));
  model.main = model.packages.back().get();
  if (!diags.has_errors()) bipc::check(model, diags);
  return diags.has_errors() ? diags.format(model.files) : "";
}

TEST(TranslateFaults, FaultSignalsOfSdlFunctionsBecomeFaultTransitionsOfTheFaultyPackage) {
  bipc::Diagnostics diags;
  Design design;
  design.data = resolved(kTypes, diags);
  Function sensor{"Sensor", "SDL", {}, {}, {}, std::nullopt, false, {}};
  Interface tick = interface("tick", InterfaceKind::Cyclic);
  tick.period = 100.0;
  tick.deadline = 100.0;
  Interface stuck = interface("fault_stuck", InterfaceKind::Sporadic);
  stuck.queue_size = 1;
  sensor.provided = {tick, stuck};
  design.view.functions = {sensor};
  design.sdl.push_back(sdl::read_sdl(R"(process Sensor;
    dcl reads Count := 0;
    START;
        NEXTSTATE Ok;
    state Ok;
        input tick;
            task reads := (reads + 1) mod 256;
            NEXTSTATE Ok;
        input fault_stuck;
            NEXTSTATE Stuck;
    endstate;
    state Stuck;
    endstate;
endprocess Sensor;)",
                                     1, diags));
  ASSERT_FALSE(diags.has_errors()) << diags.format({});
  const auto packages = translate(design, {}, diags);
  ASSERT_TRUE(packages) << diags.format({});
  const std::string& faulty = packages->faulty;
  EXPECT_EQ(package_diagnostics(faulty), "") << faulty;
  EXPECT_NE(faulty.find("atom type Sensor_faulty()"), std::string::npos) << faulty;
  EXPECT_NE(faulty.find("@fault\n    port Port fault_stuck_fault()"), std::string::npos) << faulty;
  // Lazy (no urgency): a fault comes when it comes; the state's place and the ready token move.
  EXPECT_NE(faulty.find("on fault_stuck_fault from Ok, ready to Stuck, ready\n"), std::string::npos)
      << faulty;
  EXPECT_EQ(faulty.find("on tick_in"), std::string::npos) << faulty;  // nominal behaviour left out
  // The nominal package keeps the fault signal an ordinary interface.
  EXPECT_NE(packages->nominal.find("on fault_stuck_in from Ok, ready"), std::string::npos);
}

}  // namespace
}  // namespace smcbip::taste2bip

namespace smcbip::taste2bip {
namespace {

TEST(TranslateSignature, DataNamedLikeAPortTakeAnotherPrefix) {
  bipc::Diagnostics diags;
  Design design = small_design(diags, InterfaceKind::Protected);
  for (Function& f : design.view.functions) {  // an int `result`: data get_result, a port's name
    Interface& get = f.name == "Caller" ? f.required[0] : f.provided[0];
    get.parameters[1].name = "result";
    get.parameters[1].type = "Mode";
  }
  const FunctionSignature caller = function_signature(design.view, 0, design.data, diags);
  EXPECT_EQ(caller.required[0].data_names(false), std::vector<std::string>{"get_data_x"});
  EXPECT_EQ(caller.required[0].data_names(true), std::vector<std::string>{"get_data_result"});
  const auto packages = translate(design, {}, diags);
  ASSERT_TRUE(packages) << diags.format({});
  EXPECT_EQ(bipc_diagnostics(packages->nominal, "taste"), "") << packages->nominal;
}

}  // namespace
}  // namespace smcbip::taste2bip
