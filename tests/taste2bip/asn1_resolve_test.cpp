// Resolution of a data view: references across modules and IMPORTS, value names in
// constraints, parameterized types, errors for unknown names and self-defined types, BIP data.
#include <gtest/gtest.h>

#include "tests/taste2bip/asn1_test_support.h"

namespace smcbip::taste2bip::asn1 {
namespace {

using testing::module;
using testing::Read;

// The TASTE-BasicTypes module as the toolchain ships it (esa/kazoo test/Demo_Timers).
const char* const kBasicTypes =
    "TASTE-BasicTypes DEFINITIONS ::=\nBEGIN\n"
    "T-Int32 ::=  INTEGER (-2147483648 .. 2147483647)\nT-UInt32 ::= INTEGER (0 .. 4294967295)\n"
    "T-Int8 ::= INTEGER (-128 .. 127)\nT-UInt8 ::= INTEGER (0 .. 255)\nT-Boolean ::= BOOLEAN\n"
    "END\n";

TEST(Asn1Resolve, ImportsFromTasteBasicTypes) {
  Read r;
  r.add(
       "TASTE-Dataview DEFINITIONS ::= BEGIN\n"
       "IMPORTS T-Int32, T-UInt8, T-Boolean FROM TASTE-BasicTypes;\n"
       "MyInteger ::= T-UInt8\nS ::= SEQUENCE { a T-Int32, b T-Boolean, c MyInteger }\nEND\n")
      .add(kBasicTypes)
      .resolved();
  ASSERT_EQ(r.errors(), "");
  const Type* my = r.type("MyInteger");
  ASSERT_TRUE(my->target.has_value());
  EXPECT_EQ(r.view.modules[my->target->module].name, "TASTE-BasicTypes");
  EXPECT_EQ(r.view.type(*my->target)->name, "T-UInt8");
  EXPECT_EQ(my->bip, BipData::Int);
  const Type* s = r.type("S");
  EXPECT_EQ(s->bip, BipData::Extern);
  EXPECT_EQ(s->components[0].type.bip, BipData::Int);
  EXPECT_EQ(s->components[1].type.bip, BipData::Bool);
  EXPECT_EQ(s->components[2].type.bip, BipData::Int);
  // Lookups from a module follow its IMPORTS; without a module, only definitions count.
  EXPECT_TRUE(r.view.find_type("T-Int32", "TASTE-Dataview").has_value());
  EXPECT_FALSE(r.view.find_type("T-Int8", "TASTE-Dataview").has_value());
  EXPECT_EQ(r.view.find_type("T-Int8")->module, 1u);
  EXPECT_EQ(r.view.module("TASTE-BasicTypes"), &r.view.modules[1]);
}

TEST(Asn1Resolve, ImportChainsAndQualifiedNames) {
  Read r;
  r.add("A DEFINITIONS ::= BEGIN IMPORTS X FROM B; T ::= X U ::= C.Y END\n")
      .add("B DEFINITIONS ::= BEGIN IMPORTS X FROM C; END\n")
      .add("C DEFINITIONS ::= BEGIN X ::= REAL Y ::= BOOLEAN END\n")
      .resolved();
  ASSERT_EQ(r.errors(), "");
  EXPECT_EQ(r.type("T")->bip, BipData::Float);
  EXPECT_EQ(r.type("T")->target->module, 2u);
  EXPECT_EQ(r.type("U")->bip, BipData::Bool);
}

TEST(Asn1Resolve, BipDataOfEveryKind) {
  Read r;
  r.add(module("I ::= INTEGER\nR ::= REAL\nB ::= BOOLEAN\nE ::= ENUMERATED { a }\nN ::= NULL\n"
               "S ::= SEQUENCE { a I }\nO ::= SEQUENCE OF I\nC ::= CHOICE { a I }\n"
               "Oc ::= OCTET STRING\nBs ::= BIT STRING\nIa ::= IA5String\nRef ::= R"))
      .resolved();
  ASSERT_EQ(r.errors(), "");
  EXPECT_EQ(r.type("I")->bip, BipData::Int);
  EXPECT_EQ(r.type("R")->bip, BipData::Float);
  EXPECT_EQ(r.type("B")->bip, BipData::Bool);
  EXPECT_EQ(r.type("E")->bip, BipData::Int);
  for (const char* name : {"N", "S", "O", "C", "Oc", "Bs", "Ia"}) {
    EXPECT_EQ(r.type(name)->bip, BipData::Extern) << name;
  }
  EXPECT_EQ(r.type("Ref")->bip, BipData::Float);
  EXPECT_EQ(bip_data(r.view, *r.type("Ref")), BipData::Float);
  EXPECT_EQ(r.type("O")->element->bip, BipData::Int);
}

TEST(Asn1Resolve, ValueNamesInConstraintsAndParameters) {
  Read r;
  r.add(module("max-len INTEGER ::= 60\nalias INTEGER ::= max-len\n"
               "S ::= OCTET STRING (SIZE(1..max-len))\nA ::= INTEGER (0..alias)\n"
               "P{INTEGER: n} ::= SEQUENCE (SIZE(1..n)) OF BOOLEAN\nQ ::= P{max-len}"))
      .resolved();
  ASSERT_EQ(r.errors(), "");
  const Value& upper = r.type("S")->size.ranges[0].upper;
  EXPECT_TRUE(upper.resolved);
  EXPECT_EQ(upper.integer, 60);
  EXPECT_EQ(r.type("A")->range.ranges[0].upper.integer, 60);
  EXPECT_TRUE(r.type("P")->size.ranges[0].upper.is_parameter);
  EXPECT_EQ(r.type("Q")->arguments[0].integer, 60);
  EXPECT_EQ(r.type("Q")->bip, BipData::Extern);
}

TEST(Asn1Resolve, BoundsOfParameterizedInstances) {
  Read r;
  r.add(module("max-len INTEGER ::= 60\nhalf REAL ::= 0.5\n"
               "P{INTEGER: lo, INTEGER: hi} ::= SEQUENCE (SIZE(lo..hi)) OF BOOLEAN\n"
               "Q ::= P{2, max-len}\nR ::= REAL (0..half)\nI ::= INTEGER (MIN..7)"))
      .resolved();
  ASSERT_EQ(r.errors(), "");
  const Type* p = r.type("P");
  const Type* q = r.type("Q");
  EXPECT_EQ(bound_integer(r.view, p->size.ranges[0].lower, q), 2);
  EXPECT_EQ(bound_integer(r.view, p->size.ranges[0].upper, q), 60);
  EXPECT_EQ(bound_integer(r.view, p->size.ranges[0].upper), std::nullopt);  // no instance
  EXPECT_EQ(bound_integer(r.view, r.type("R")->range.ranges[0].upper), std::nullopt);  // real
  EXPECT_DOUBLE_EQ(r.type("R")->range.ranges[0].upper.real, 0.5);
  EXPECT_EQ(bound_integer(r.view, r.type("I")->range.ranges[0].lower), std::nullopt);  // MIN
  EXPECT_EQ(bound_integer(r.view, r.type("I")->range.ranges[0].upper), 7);
}

TEST(Asn1Resolve, UnknownNamesAndBadImports) {
  Read r;
  r.add(
       "A DEFINITIONS ::= BEGIN\nIMPORTS X, Nope FROM B Z FROM Missing;\n"
       "T ::= Unknown\nU ::= INTEGER (0..nothing)\nV ::= Nope\nW ::= Missing.Q\nEND\n")
      .add("B DEFINITIONS ::= BEGIN\nX ::= INTEGER\nEND\n")
      .resolved();
  EXPECT_EQ(r.errors(),
            "t0.asn:2:12: error: module 'B' has no type or value 'Nope' to import\n"
            "t0.asn:2:31: error: unknown module 'Missing' in IMPORTS\n"
            "t0.asn:3:7: error: unknown type 'Unknown'\n"
            "t0.asn:4:19: error: unknown value 'nothing'\n"
            "t0.asn:6:7: error: unknown module 'Missing' in 'Missing.Q'\n");
}

TEST(Asn1Resolve, ArgumentCountsAndDuplicates) {
  Read r;
  r.add(module("P{INTEGER: n} ::= OCTET STRING (SIZE(n))\nA ::= P\nB ::= INTEGER{1}\n"
               "C ::= BOOLEAN\nC ::= REAL"))
      .add(module(""))
      .resolved();
  EXPECT_EQ(r.errors(),
            "t0.asn:4:14: error: named numbers in INTEGER are not supported\n"
            "t0.asn:6:1: error: the type 'C' is already defined in module 'M' (line 5)\n"
            "t1.asn:1:1: error: the module 'M' is already defined (line 1)\n"
            "t0.asn:3:7: error: 'P' takes 1 argument(s), but 0 are given\n");
}

TEST(Asn1Resolve, TypesDefinedInTermsOfThemselves) {
  Read r;
  r.add(module("A ::= B\nB ::= A\nS ::= SEQUENCE { next S }\nSelf ::= Self\n"
               "List ::= SEQUENCE { head INTEGER, tail List OPTIONAL }\n"
               "Tree ::= CHOICE { leaf INTEGER, node SEQUENCE OF Tree }"))
      .resolved();
  EXPECT_EQ(r.errors(),
            "t0.asn:3:7: error: the type 'A' is defined in terms of itself (A -> B -> A) without "
            "SEQUENCE OF, CHOICE or OPTIONAL between\n"
            "t0.asn:4:23: error: the type 'S' is defined in terms of itself (S -> S) without "
            "SEQUENCE OF, CHOICE or OPTIONAL between\n"
            "t0.asn:5:10: error: the type 'Self' is defined in terms of itself (Self -> Self) "
            "without SEQUENCE OF, CHOICE or OPTIONAL between\n");
  EXPECT_EQ(r.type("A")->bip, BipData::Unknown);
  EXPECT_EQ(r.type("List")->bip, BipData::Extern);
  EXPECT_EQ(r.type("Tree")->bip, BipData::Extern);
}

}  // namespace
}  // namespace smcbip::taste2bip::asn1
