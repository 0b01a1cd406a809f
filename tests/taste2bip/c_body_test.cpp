// C and C++ function bodies: the data view as the C types bodies are written against, the C
// piece each BIP leaf reaches, and the atom and shim of a function with a body. That the shim
// compiles and runs real bodies is c_bodies.sh's part.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "taste2bip/translate/c_types.h"
#include "taste2bip/translate/package.h"
#include "tests/taste2bip/view_builders.h"

namespace smcbip::taste2bip {
namespace {

const char* const kTypes = R"(M DEFINITIONS AUTOMATIC TAGS ::= BEGIN
  T-Double ::= REAL
  Angle ::= SEQUENCE { rad T-Double }
  Mode ::= ENUMERATED { idle, run(5) }
  Phase ::= ENUMERATED { idle, busy }
  Count ::= INTEGER (0..255)
  Offset ::= INTEGER (-5..5)
  Pick ::= CHOICE { a BOOLEAN, b Mode }
  Opt ::= SEQUENCE { x INTEGER (0..9) OPTIONAL, y BOOLEAN }
  Fixed ::= SEQUENCE (SIZE (2)) OF INTEGER (0..3)
  Varying ::= SEQUENCE (SIZE (0..3)) OF Angle
  Bytes ::= OCTET STRING (SIZE (4))
  Name ::= IA5String (SIZE (1..8))
  Inner ::= SEQUENCE { pos SEQUENCE { x REAL, y REAL }, tag CHOICE { n INTEGER (0..1), a BOOLEAN } }
END
)";

asn1::DataView resolved(bipc::Diagnostics& diags) {
  asn1::DataView view;
  asn1::read_asn1(kTypes, 0, view, diags);
  asn1::resolve(view, diags);
  return view;
}

bool has(const std::string& text, const std::string& piece) {
  return text.find(piece) != std::string::npos;
}

TEST(CBodyTypes, HeaderDefinesEachTypeAsTheAsn1CompilerNamesIt) {
  bipc::Diagnostics diags;
  const std::string h = c_dataview_header(resolved(diags));
  ASSERT_FALSE(diags.has_errors());
  EXPECT_TRUE(has(h, "typedef asn1SccUint asn1SccCount;")) << h;
  EXPECT_TRUE(has(h, "typedef asn1SccSint asn1SccOffset;"));
  EXPECT_TRUE(has(h, "typedef asn1Real asn1SccT_Double;"));
  // Enumerants are named after their type (the TASTE toolchain's asn1scc does so); an
  // alternative that two CHOICEs share (`a` is Inner.tag's too) is prefixed with its type's name.
  EXPECT_TRUE(has(h, "asn1SccMode_idle = 0,\n    asn1SccMode_run = 5\n} asn1SccMode;"));
  EXPECT_TRUE(has(h, "asn1SccPhase_idle = 0,\n    asn1SccPhase_busy = 1\n} asn1SccPhase;"));
  EXPECT_TRUE(has(
      h, "asn1SccPick_NONE,\n    asn1SccPick_a_PRESENT,\n    b_PRESENT\n} asn1SccPick_selection;"));
  EXPECT_TRUE(has(h,
                  "    asn1SccPick_selection kind;\n    union {\n        flag a;\n"
                  "        asn1SccMode b;\n    } u;"));
  EXPECT_TRUE(has(h, "    struct {\n        unsigned int x:1;\n    } exist;\n} asn1SccOpt;"));
  EXPECT_TRUE(has(h, "typedef struct {\n    asn1SccUint arr[2];\n} asn1SccFixed;"));
  EXPECT_TRUE(
      has(h, "typedef struct {\n    int nCount;\n    asn1SccAngle arr[3];\n} asn1SccVarying;"));
  EXPECT_TRUE(has(h, "typedef struct {\n    byte arr[4];\n} asn1SccBytes;"));
  EXPECT_TRUE(has(h, "typedef char asn1SccName[9];"));
  // Anonymous inner types are named after their place, and written before their user.
  EXPECT_LT(h.find("} asn1SccInner_pos;"), h.find("} asn1SccInner;"));
  EXPECT_TRUE(has(h, "asn1SccInner_tag_selection kind;"));
  // What a type uses comes first.
  EXPECT_LT(h.find("} asn1SccAngle;"), h.find("} asn1SccVarying;"));
}

/// `suffix=C piece` of every leaf of `type`.
std::string pieces(const std::string& type) {
  bipc::Diagnostics diags;
  const asn1::DataView view = resolved(diags);
  const auto leaves = leaves_of(view, type, {}, diags);
  const auto id = find_type_spelled(view, type);
  std::string out;
  for (const Leaf& leaf : *leaves) {
    const auto c = c_access(view, view.type(*id)->type, leaf);
    out += (out.empty() ? "" : " ") + leaf.suffix + "=" + c.value_or("?");
  }
  return out;
}

TEST(CBodyTypes, EachLeafReachesItsCPiece) {
  EXPECT_EQ(pieces("Count"), "=");
  EXPECT_EQ(pieces("Pick"), "present=.kind a=.u.a b=.u.b");
  EXPECT_EQ(pieces("Opt"), "x_exist=.exist.x x=.x y=.y");
  EXPECT_EQ(pieces("Varying"),
            "length=.nCount 0_rad=.arr[0].rad 1_rad=.arr[1].rad 2_rad=.arr[2].rad");
  EXPECT_EQ(pieces("Inner"),
            "pos_x=.pos.x pos_y=.pos.y tag_present=.tag.kind tag_n=.tag.u.n "
            "tag_a=.tag.u.a");
}

using test::interface;
using test::parameter;

/// Caller (C, body given) has a cyclic `tick` that calls Callee's protected `get(in x, out y)`
/// and sporadic `put(v)`; Callee has a body too. `put` carries a value of `put_type`.
Design design_with_bodies(bipc::Diagnostics& diags, const std::string& put_type) {
  Design design;
  design.data = resolved(diags);
  using Direction = Parameter::Direction;
  Function caller{"Caller", "C", {}, {}, {}, std::nullopt, false, {}};
  Interface tick = interface("tick", InterfaceKind::Cyclic);
  tick.period = 100.0;
  caller.provided.push_back(tick);
  Interface get =
      interface("get", InterfaceKind::Protected,
                {parameter(Direction::In, "x", "Mode"), parameter(Direction::Out, "y", "Pick")});
  Interface put =
      interface("put", InterfaceKind::Sporadic, {parameter(Direction::In, "v", put_type)});
  caller.required = {get, put};
  Function callee{"Callee", "C", {}, {}, {}, std::nullopt, false, {}};
  callee.provided = {get, put};
  design.view.functions = {caller, callee};
  design.view.connections = {{{"Caller", "get", false}, {"Callee", "get", true}, {}},
                             {{"Caller", "put", false}, {"Callee", "put", true}, {}}};
  design.bodies["Caller"] = {"src/caller.c", "/* caller */"};
  design.bodies["Callee"] = {"src/callee.c", "/* callee */"};
  return design;
}

const OutputFile* file(const Packages& p, const std::string& name) {
  for (const OutputFile& f : p.files) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

TEST(CBodyAtom, CallsTheBodyAndMakesItsCallsStepsOfTheAtom) {
  bipc::Diagnostics diags;
  const Design design = design_with_bodies(diags, "Angle");
  const auto packages = translate(design, {}, diags);
  ASSERT_TRUE(packages) << diags.format(bipc::SourceFiles{});
  EXPECT_EQ(bipc_diagnostics(packages->nominal, "taste"), "");
  const std::string& bip = packages->nominal;
  EXPECT_TRUE(has(bip,
                  "@cpp(src=\"taste_bodies.cpp,caller.c,callee.c\", include=\"taste_bodies.h,"
                  "dataview-uniq.h,caller.h,callee.h\")\npackage taste"))
      << bip;
  EXPECT_TRUE(has(bip, "extern function int Caller_bip_call_tick()"));
  EXPECT_TRUE(has(bip, "extern function Caller_bip_set_get_y_present(int)"));
  // A synchronous call: its in data read from the paused body, the call, the result written
  // back, the body resumed.
  EXPECT_TRUE(has(bip,
                  "on body__step from tick__run to tick__get provided (body__status == 1) "
                  "eager do { get_x = Caller_bip_get_get_x(); }"));
  EXPECT_TRUE(has(bip, "on get_out from tick__get to tick__get__wait eager\n"));
  EXPECT_TRUE(has(bip,
                  "on get_result from tick__get__wait to tick__run do { "
                  "Caller_bip_set_get_y_present(get_y_present); Caller_bip_set_get_y_a(get_y_a); "
                  "Caller_bip_set_get_y_b(get_y_b); body__status = Caller_bip_resume(); }"));
  // A sporadic call: the body goes on once the call is made.
  EXPECT_TRUE(has(bip,
                  "on put_out from tick__put to tick__run eager do { body__status = "
                  "Caller_bip_resume(); }"));
  EXPECT_TRUE(has(bip,
                  "on get_in from idle to get__run eager do { body__status = "
                  "Callee_bip_call_get(get_x); }"));
  ASSERT_NE(file(*packages, "caller.h"), nullptr);
  EXPECT_TRUE(has(file(*packages, "caller.h")->text,
                  "void caller_RI_get(const asn1SccMode *IN_x, asn1SccPick *OUT_y);"));
  EXPECT_TRUE(
      has(file(*packages, "callee.h")->text, "void callee_PI_put(const asn1SccAngle *IN_v);"));
  ASSERT_NE(file(*packages, "taste_bodies.cpp"), nullptr);
  const std::string& shim = file(*packages, "taste_bodies.cpp")->text;
  EXPECT_TRUE(
      has(shim, "extern \"C\" void caller_RI_get(const asn1SccMode* IN_x, asn1SccPick* OUT_y)"));
  EXPECT_TRUE(has(shim, "(*Caller__get_y).u.a = "));
  EXPECT_EQ(file(*packages, "callee.c")->text, "/* callee */");
}

TEST(CBodyAtom, AParameterWithoutScalarFormIsALocatedError) {
  bipc::Diagnostics diags;
  Design design = design_with_bodies(diags, "Bytes");
  design.view.functions[0].required[1].parameters[0].at = bipc::Location{0, 7, 3};
  EXPECT_FALSE(translate(design, {}, diags));
  EXPECT_TRUE(has(diags.format(bipc::SourceFiles{}), "7:3: error: parameter v of put (Bytes)"))
      << diags.format(bipc::SourceFiles{});
}

TEST(CBodyAtom, AFunctionWithoutBodyStaysAbstract) {
  bipc::Diagnostics diags;
  Design design = design_with_bodies(diags, "Angle");
  design.bodies.erase("Callee");
  const auto packages = translate(design, {}, diags);
  ASSERT_TRUE(packages);
  EXPECT_TRUE(has(packages->nominal, "on get_in from idle to get__0 eager"));
  EXPECT_EQ(file(*packages, "callee.h"), nullptr);
}

}  // namespace
}  // namespace smcbip::taste2bip
