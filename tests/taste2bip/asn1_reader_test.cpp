// The ASN.1 reader, construct by construct: what is read, with exact values.
#include <gtest/gtest.h>

#include "tests/taste2bip/asn1_test_support.h"

namespace smcbip::taste2bip::asn1 {
namespace {

using testing::module;
using testing::Read;

TEST(Asn1Reader, ModuleHeaderExportsAndImports) {
  Read r;
  r.add(
      "TASTE-Dataview DEFINITIONS AUTOMATIC TAGS ::=\nBEGIN\nEXPORTS ALL;\n"
      "IMPORTS T-Int32, T-UInt8 FROM TASTE-BasicTypes t-Max FROM Other;\n"
      "T ::= BOOLEAN\nEND\n");
  ASSERT_EQ(r.errors(), "");
  ASSERT_EQ(r.view.modules.size(), 1u);
  const Module& m = r.view.modules[0];
  EXPECT_EQ(m.name, "TASTE-Dataview");
  EXPECT_EQ(m.tag_default, "AUTOMATIC");
  EXPECT_TRUE(m.exports_all);
  ASSERT_EQ(m.imports.size(), 2u);
  EXPECT_EQ(m.imports[0].module, "TASTE-BasicTypes");
  EXPECT_EQ(m.imports[0].names, (std::vector<std::string>{"T-Int32", "T-UInt8"}));
  EXPECT_EQ(m.imports[0].name_at[1].line, 4u);
  EXPECT_EQ(m.imports[0].name_at[1].column, 18u);
  EXPECT_EQ(m.imports[1].module, "Other");
  EXPECT_EQ(m.imports[1].names, (std::vector<std::string>{"t-Max"}));
  ASSERT_EQ(m.types.size(), 1u);
  EXPECT_EQ(m.types[0].at.line, 5u);
  EXPECT_EQ(m.types[0].at.column, 1u);
}

TEST(Asn1Reader, SeveralModulesInOneFile) {
  Read r;
  r.add("A DEFINITIONS ::= BEGIN X ::= INTEGER END\nB DEFINITIONS ::= BEGIN Y ::= REAL END\n");
  ASSERT_EQ(r.errors(), "");
  ASSERT_EQ(r.view.modules.size(), 2u);
  EXPECT_EQ(r.view.modules[1].name, "B");
  EXPECT_EQ(r.view.modules[1].types[0].type.kind, TypeKind::Real);
}

TEST(Asn1Reader, IntegerRanges) {
  Read r;
  r.add(
      module("A ::= INTEGER (0..255)\nB ::= INTEGER(-2147483648 .. 2147483647)\nC ::= INTEGER (5)\n"
             "D ::= INTEGER (MIN..0)\nE ::= INTEGER (1..MAX)\nF ::= INTEGER (1 | 3..4, ...)\n"
             "G ::= INTEGER\nH ::= INTEGER (-9223372036854775808..9223372036854775807)"));
  ASSERT_EQ(r.errors(), "");
  const Type* a = r.type("A");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->kind, TypeKind::Integer);
  ASSERT_EQ(a->range.ranges.size(), 1u);
  EXPECT_EQ(a->range.ranges[0].lower.integer, 0);
  EXPECT_EQ(a->range.ranges[0].upper.integer, 255);
  EXPECT_EQ(r.type("B")->range.ranges[0].lower.integer, -2147483648LL);
  EXPECT_EQ(r.type("B")->range.ranges[0].upper.integer, 2147483647LL);
  EXPECT_EQ(r.type("B")->range.ranges[0].lower.text, "-2147483648");
  EXPECT_EQ(r.type("C")->range.ranges[0].lower.integer, 5);
  EXPECT_EQ(r.type("C")->range.ranges[0].upper.integer, 5);
  EXPECT_EQ(r.type("D")->range.ranges[0].lower.kind, Value::Kind::Min);
  EXPECT_EQ(r.type("E")->range.ranges[0].upper.kind, Value::Kind::Max);
  const Type* f = r.type("F");
  ASSERT_EQ(f->range.ranges.size(), 2u);
  EXPECT_EQ(f->range.ranges[1].lower.integer, 3);
  EXPECT_EQ(f->range.ranges[1].upper.integer, 4);
  EXPECT_TRUE(f->range.extensible);
  EXPECT_TRUE(r.type("G")->range.empty());
  EXPECT_EQ(r.type("H")->range.ranges[0].lower.integer, INT64_MIN);
  EXPECT_EQ(r.type("H")->range.ranges[0].upper.integer, INT64_MAX);
}

TEST(Asn1Reader, RealRangesWithExponents) {
  Read r;
  r.add(module(
      "A ::= REAL (-1.0 .. 1.0)\nB ::= REAL (-1.7976931348623157e+308..1.7976931348623157E308)\n"
      "C ::= REAL (0..10)"));
  ASSERT_EQ(r.errors(), "");
  const Type* a = r.type("A");
  EXPECT_EQ(a->kind, TypeKind::Real);
  EXPECT_EQ(a->range.ranges[0].lower.kind, Value::Kind::Real);
  EXPECT_DOUBLE_EQ(a->range.ranges[0].lower.real, -1.0);
  EXPECT_DOUBLE_EQ(a->range.ranges[0].upper.real, 1.0);
  EXPECT_DOUBLE_EQ(r.type("B")->range.ranges[0].lower.real, -1.7976931348623157e308);
  EXPECT_EQ(r.type("B")->range.ranges[0].upper.text, "1.7976931348623157E308");
  EXPECT_DOUBLE_EQ(r.type("C")->range.ranges[0].upper.real, 10.0);
}

TEST(Asn1Reader, ScalarsAndStrings) {
  Read r;
  r.add(module(
      "B ::= BOOLEAN\nN ::= NULL\nO ::= OCTET STRING (SIZE (3))\nS ::= IA5String (SIZE(1..10))\n"
      "Bits ::= BIT STRING (SIZE(32))\nP ::= PrintableString"));
  ASSERT_EQ(r.errors(), "");
  EXPECT_EQ(r.type("B")->kind, TypeKind::Boolean);
  EXPECT_EQ(r.type("N")->kind, TypeKind::Null);
  const Type* o = r.type("O");
  EXPECT_EQ(o->kind, TypeKind::OctetString);
  ASSERT_EQ(o->size.ranges.size(), 1u);
  EXPECT_EQ(o->size.ranges[0].lower.integer, 3);
  EXPECT_EQ(o->size.ranges[0].upper.integer, 3);
  const Type* s = r.type("S");
  EXPECT_EQ(s->kind, TypeKind::CharacterString);
  EXPECT_EQ(s->string_kind, "IA5String");
  EXPECT_EQ(s->size.ranges[0].lower.integer, 1);
  EXPECT_EQ(s->size.ranges[0].upper.integer, 10);
  EXPECT_EQ(r.type("Bits")->kind, TypeKind::BitString);
  EXPECT_EQ(r.type("Bits")->size.ranges[0].upper.integer, 32);
  EXPECT_EQ(r.type("P")->string_kind, "PrintableString");
}

TEST(Asn1Reader, EnumerantsNumberedAsX680Does) {
  Read r;
  r.add(
      module("E ::= ENUMERATED { hello, world, how-are-you }\n"
             "F ::= ENUMERATED { taste(1), welcomes(2), you(3) }\n"
             "G ::= ENUMERATED { a, b(0), c, d(-5), ... }"));
  ASSERT_EQ(r.errors(), "");
  const Type* e = r.type("E");
  EXPECT_EQ(e->kind, TypeKind::Enumerated);
  ASSERT_EQ(e->enumerants.size(), 3u);
  EXPECT_EQ(e->enumerants[2].name, "how-are-you");
  EXPECT_EQ(e->enumerants[2].value, 2);
  EXPECT_FALSE(e->enumerants[2].explicit_value);
  EXPECT_EQ(r.type("F")->enumerants[0].value, 1);
  EXPECT_TRUE(r.type("F")->enumerants[0].explicit_value);
  const Type* g = r.type("G");
  EXPECT_EQ(g->enumerants[0].value, 1);  // 0 is taken by b
  EXPECT_EQ(g->enumerants[1].value, 0);
  EXPECT_EQ(g->enumerants[2].value, 2);
  EXPECT_EQ(g->enumerants[3].value, -5);
  EXPECT_TRUE(g->extensible);
}

TEST(Asn1Reader, SequenceComponentsOptionalAndDefault) {
  Read r;
  r.add(
      module("S ::= SEQUENCE {\n  input-data MyInteger,\n  flag BOOLEAN OPTIONAL,\n"
             "  n INTEGER (0..9) DEFAULT 4,\n  v ENUMERATED { valid, invalid },\n  ...\n}\n"
             "E ::= SEQUENCE {}"));
  ASSERT_EQ(r.errors(), "");
  const Type* s = r.type("S");
  EXPECT_EQ(s->kind, TypeKind::Sequence);
  ASSERT_EQ(s->components.size(), 4u);
  EXPECT_EQ(s->components[0].name, "input-data");
  EXPECT_EQ(s->components[0].type.kind, TypeKind::Reference);
  EXPECT_EQ(s->components[0].type.name, "MyInteger");
  EXPECT_EQ(s->components[0].at.line, 3u);
  EXPECT_EQ(s->components[0].at.column, 3u);
  EXPECT_FALSE(s->components[0].optional);
  EXPECT_TRUE(s->components[1].optional);
  EXPECT_EQ(s->components[2].default_value, "4");
  EXPECT_EQ(s->components[2].type.range.ranges[0].upper.integer, 9);
  EXPECT_EQ(s->components[3].type.enumerants[1].name, "invalid");
  EXPECT_TRUE(s->extensible);
  EXPECT_TRUE(r.type("E")->components.empty());
}

TEST(Asn1Reader, ChoiceAndNestedTypes) {
  Read r;
  r.add(module("C ::= CHOICE {\n a BOOLEAN,\n b CHOICE { c BOOLEAN, d SEQUENCE { x REAL } }\n}"));
  ASSERT_EQ(r.errors(), "");
  const Type* c = r.type("C");
  EXPECT_EQ(c->kind, TypeKind::Choice);
  ASSERT_EQ(c->components.size(), 2u);
  const Type& b = c->components[1].type;
  EXPECT_EQ(b.kind, TypeKind::Choice);
  EXPECT_EQ(b.components[1].type.kind, TypeKind::Sequence);
  EXPECT_EQ(b.components[1].type.components[0].type.kind, TypeKind::Real);
}

TEST(Asn1Reader, SequenceOfWithSizes) {
  Read r;
  r.add(
      module("A ::= SEQUENCE (SIZE (2)) OF MyEnum\nB ::= SEQUENCE(SIZE(0..2)) OF INTEGER (1..2)\n"
             "C ::= SEQUENCE SIZE (1..10) OF BOOLEAN\nD ::= SEQUENCE OF SEQUENCE { x INTEGER }"));
  ASSERT_EQ(r.errors(), "");
  const Type* a = r.type("A");
  EXPECT_EQ(a->kind, TypeKind::SequenceOf);
  EXPECT_EQ(a->size.ranges[0].lower.integer, 2);
  EXPECT_EQ(a->size.ranges[0].upper.integer, 2);
  ASSERT_NE(a->element, nullptr);
  EXPECT_EQ(a->element->name, "MyEnum");
  const Type* b = r.type("B");
  EXPECT_EQ(b->size.ranges[0].lower.integer, 0);
  EXPECT_EQ(b->size.ranges[0].upper.integer, 2);
  EXPECT_EQ(b->element->range.ranges[0].lower.integer, 1);
  EXPECT_EQ(r.type("C")->size.ranges[0].upper.integer, 10);
  EXPECT_EQ(r.type("C")->element->kind, TypeKind::Boolean);
  EXPECT_TRUE(r.type("D")->size.empty());
  EXPECT_EQ(r.type("D")->element->kind, TypeKind::Sequence);
}

TEST(Asn1Reader, ReferencesWithModuleAndArguments) {
  Read r;
  r.add(
      module("A ::= Other.T-UInt8\nB ::= T-StringP{numT-String}\nC ::= T-UInt32 (0..10)\n"
             "T-StringP{T-UInt32: maxT-String} ::= OCTET STRING (SIZE(0..maxT-String))"));
  ASSERT_EQ(r.errors(), "");
  const Type* a = r.type("A");
  EXPECT_EQ(a->kind, TypeKind::Reference);
  EXPECT_EQ(a->module, "Other");
  EXPECT_EQ(a->name, "T-UInt8");
  const Type* b = r.type("B");
  ASSERT_EQ(b->arguments.size(), 1u);
  EXPECT_EQ(b->arguments[0].kind, Value::Kind::Name);
  EXPECT_EQ(b->arguments[0].text, "numT-String");
  EXPECT_EQ(r.type("C")->range.ranges[0].upper.integer, 10);
  const TypeAssignment* p = r.view.type(*r.view.find_type("T-StringP"));
  ASSERT_EQ(p->parameters.size(), 1u);
  EXPECT_EQ(p->parameters[0].governor, "T-UInt32");
  EXPECT_EQ(p->parameters[0].name, "maxT-String");
  EXPECT_EQ(p->type.size.ranges[0].upper.text, "maxT-String");
}

TEST(Asn1Reader, ValueAssignmentsKeepTheirText) {
  Read r;
  r.add(module(
      "numT-String T-UInt32::= 60\nmyVar MySeqOf ::= { hello, world }\nneg INTEGER ::= -5\n"
      "pi REAL ::= 3.14\nname IA5String ::= \"abc\"\nbits BIT STRING ::= '0101'B\n"
      "hex OCTET STRING ::= 'AF'H\nch MyChoice ::= a : TRUE\nnested S ::= { a { 1, 2 }, b 3 }"));
  ASSERT_EQ(r.errors(), "");
  const auto& values = r.view.modules[0].values;
  ASSERT_EQ(values.size(), 9u);
  EXPECT_EQ(values[0].name, "numT-String");
  EXPECT_EQ(values[0].type.name, "T-UInt32");
  EXPECT_EQ(values[0].value, "60");
  EXPECT_EQ(values[1].value, "{ hello, world }");
  EXPECT_EQ(values[2].value, "-5");
  EXPECT_EQ(values[3].type.kind, TypeKind::Real);
  EXPECT_EQ(values[4].value, "\"abc\"");
  EXPECT_EQ(values[5].value, "'0101'B");
  EXPECT_EQ(values[6].value, "'AF'H");
  EXPECT_EQ(values[7].value, "a : TRUE");
  EXPECT_EQ(values[8].value, "{ a { 1, 2 }, b 3 }");
}

TEST(Asn1Reader, CommentsAreSkipped) {
  Read r;
  r.add(module(
      "-- a line comment\nA ::= -- inline -- INTEGER -- to the end\n"
      "/* block /* nested */ still comment */ B ::= BOOLEAN\n--MyInteger ::= INTEGER (0..255)"));
  ASSERT_EQ(r.errors(), "");
  ASSERT_EQ(r.view.modules[0].types.size(), 2u);
  EXPECT_EQ(r.type("A")->kind, TypeKind::Integer);
  const TypeAssignment& b = r.view.modules[0].types[1];
  EXPECT_EQ(b.at.line, 4u);
  EXPECT_EQ(b.at.column, 40u);
  EXPECT_EQ(b.type.at.column, 46u);  // BOOLEAN
}

TEST(Asn1Reader, CommentedOutCommentLinesRunToTheEndOfTheLine) {
  // TASTE's DataView template has `--  -- You can also declare constants`: the second "--" would
  // end the comment under X.680 12.6.3, but it is a comment line commented out.
  Read r;
  r.add(module("--  -- You can also declare constants\nA ::= INTEGER -- x -- (0..1)"));
  ASSERT_EQ(r.errors(), "");
  EXPECT_EQ(r.type("A")->range.ranges[0].upper.integer, 1);
}

TEST(Asn1Reader, HyphenatedNamesAndExports) {
  Read r;
  r.add(
      "My-Module DEFINITIONS IMPLICIT TAGS ::= BEGIN\nEXPORTS T-A, t-b;\n"
      "T-A ::= INTEGER(0..1)--comment right after\nt-b T-A ::= 1\nEND\n");
  ASSERT_EQ(r.errors(), "");
  const Module& m = r.view.modules[0];
  EXPECT_EQ(m.name, "My-Module");
  EXPECT_EQ(m.tag_default, "IMPLICIT");
  EXPECT_FALSE(m.exports_all);
  EXPECT_EQ(m.types[0].name, "T-A");
  EXPECT_EQ(m.values[0].name, "t-b");
  EXPECT_EQ(m.values[0].at.line, 4u);
}

}  // namespace
}  // namespace smcbip::taste2bip::asn1
