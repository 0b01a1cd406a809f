// The ASN.1 reader's errors: each at the offending token, saying what was expected; constructs
// outside the subset are named, never dropped.
#include <gtest/gtest.h>

#include "tests/taste2bip/asn1_test_support.h"

namespace smcbip::taste2bip::asn1 {
namespace {

using testing::module;
using testing::Read;

std::string errors_of(const std::string& text) {
  Read r;
  r.add(text);
  return r.errors();
}

// `module()` puts the body on line 2.
TEST(Asn1Errors, MissingAssignAfterTypeName) {
  EXPECT_EQ(errors_of(module("T-Int INTEGER (0..1)")),
            "t0.asn:2:7: error: expected '::=' after the type name 'T-Int', got 'INTEGER'\n");
  EXPECT_EQ(errors_of(module("Colours IA5String ::= { \"red\" }")),
            "t0.asn:2:1: error: value set and information object assignments ('Colours "
            "IA5String ::= ...') are not supported\n");
  EXPECT_EQ(errors_of(module("T-Int = INTEGER")),
            "t0.asn:2:7: error: expected '::=' after the type name 'T-Int', got '='\n");
}

TEST(Asn1Errors, HeaderAndEnd) {
  EXPECT_EQ(errors_of("M ::= BEGIN END"),
            "t0.asn:1:3: error: expected 'DEFINITIONS' after the module name 'M', got '::='\n");
  EXPECT_EQ(errors_of("M DEFINITIONS AUTOMATIC ::= BEGIN END"),
            "t0.asn:1:25: error: expected 'TAGS' after 'AUTOMATIC', got '::='\n");
  EXPECT_EQ(errors_of("M DEFINITIONS ::= BEGIN\nT ::= BOOLEAN\n"),
            "t0.asn:3:1: error: expected 'END' at the end of module 'M', got the end of the "
            "file\n");
  EXPECT_EQ(errors_of("m DEFINITIONS ::= BEGIN END"),
            "t0.asn:1:1: error: expected a module name (`Name DEFINITIONS ::= BEGIN ... END`), "
            "got 'm'\n");
}

TEST(Asn1Errors, ImportsNeedFrom) {
  EXPECT_EQ(errors_of(module("IMPORTS A, B;\nT ::= A")),
            "t0.asn:2:13: error: expected 'FROM' after the imported names, got ';'\n");
}

TEST(Asn1Errors, TypesAndComponents) {
  EXPECT_EQ(errors_of(module("T ::= SEQUENCE { a INTEGER b BOOLEAN }")),
            "t0.asn:2:28: error: expected ',' or '}' after a component, got 'b'\n");
  EXPECT_EQ(errors_of(module("T ::= SEQUENCE { A INTEGER }")),
            "t0.asn:2:18: error: expected a component name (starting with a lowercase letter) "
            "or '...', got 'A'\n");
  EXPECT_EQ(errors_of(module("T ::= CHOICE { a INTEGER OPTIONAL }")),
            "t0.asn:2:26: error: 'OPTIONAL' is not allowed on a CHOICE alternative\n");
  EXPECT_EQ(errors_of(module("T ::= SEQUENCE { a x }")),
            "t0.asn:2:20: error: expected a type, got the value name 'x' (type names start with "
            "an uppercase letter)\n");
  EXPECT_EQ(errors_of(module("T ::= SEQUENCE (SIZE(2)) INTEGER")),
            "t0.asn:2:26: error: expected 'OF' after 'SEQUENCE', got 'INTEGER'\n");
  EXPECT_EQ(errors_of(module("T ::= ENUMERATED { a, a }")),
            "t0.asn:2:23: error: the enumerant 'a' is already defined in this ENUMERATED\n");
  EXPECT_EQ(errors_of(module("T ::= ENUMERATED { a(1), b(1) }")),
            "t0.asn:2:28: error: the value 1 of 'b' is already used in this ENUMERATED\n");
}

TEST(Asn1Errors, Constraints) {
  EXPECT_EQ(errors_of(module("T ::= INTEGER (0..)")),
            "t0.asn:2:19: error: expected a number, MIN, MAX or a value name after '..', got "
            "')'\n");
  EXPECT_EQ(errors_of(module("T ::= INTEGER (0..10")),
            "t0.asn:3:1: error: expected ')' to close the constraint, got 'END'\n");
  EXPECT_EQ(errors_of(module("T ::= OCTET STRING (SIZE 3)")),
            "t0.asn:2:26: error: expected '(' after 'SIZE', got '3'\n");
  EXPECT_EQ(errors_of(module("T ::= SEQUENCE (1..10) OF BOOLEAN")),
            "t0.asn:2:17: error: expected 'SIZE' in the constraint of a SEQUENCE OF, got '1'\n");
  EXPECT_EQ(errors_of(module("T ::= INTEGER (0..99999999999999999999)")),
            "t0.asn:2:19: error: the integer 99999999999999999999 is outside the 64-bit range\n");
}

TEST(Asn1Errors, ConstructsOutsideTheSubsetAreNamed) {
  EXPECT_EQ(errors_of(module("T ::= SET { a INTEGER }")),
            "t0.asn:2:7: error: SET and SET OF types are not supported (TASTE data views use "
            "SEQUENCE)\n");
  EXPECT_EQ(errors_of(module("T ::= [0] INTEGER")),
            "t0.asn:2:7: error: tagged types ('[n] Type') are not supported\n");
  EXPECT_EQ(errors_of(module("T ::= S (WITH COMPONENTS { a PRESENT })")),
            "t0.asn:2:10: error: 'WITH COMPONENT(S)' constraints are not supported\n");
  EXPECT_EQ(errors_of(module("T {Type} ::= SEQUENCE OF Type")),
            "t0.asn:2:4: error: expected a value parameter 'Type: name' (type parameters are "
            "not supported), got 'Type'\n");
  EXPECT_EQ(errors_of(module("OP ::= CLASS { &id INTEGER }")),
            "t0.asn:2:8: error: information object classes ('CLASS') are not supported\n");
  EXPECT_EQ(errors_of(module("T ::= OBJECT IDENTIFIER")),
            "t0.asn:2:7: error: the type 'OBJECT' is not supported\n");
  EXPECT_EQ(errors_of(module("T ::= INTEGER { one(1) }")),
            "t0.asn:2:15: error: named numbers in INTEGER are not supported\n");
  EXPECT_EQ(errors_of(module("T ::= SEQUENCE { COMPONENTS OF S }")),
            "t0.asn:2:18: error: 'COMPONENTS OF' is not supported\n");
}

TEST(Asn1Errors, LexicalErrors) {
  EXPECT_EQ(errors_of(module("T ::= BOOLEAN /* open")),
            "t0.asn:2:15: error: unterminated comment: expected '*/' before the end of the "
            "file\n"
            "t0.asn:4:1: error: expected 'END' at the end of module 'M', got the end of the "
            "file\n");
  EXPECT_EQ(errors_of(module("v IA5String ::= \"open")),
            "t0.asn:2:17: error: unterminated string: expected '\"' before the end of the "
            "file\n"
            "t0.asn:4:1: error: expected 'END' at the end of module 'M', got the end of the "
            "file\n");
  EXPECT_EQ(errors_of(module("T ::= BOOLEAN \x01\x02 S ::= NULL")),
            "t0.asn:2:15: error: unexpected character in ASN.1 text\n");
}

TEST(Asn1Errors, RecoveryReadsTheNextAssignments) {
  Read r;
  r.add(module("A ::= SEQUENCE { a INTEGER b }\nB ::= BOOLEAN\nc B ::= TRUE"));
  EXPECT_EQ(r.diags.error_count(), 1u);
  ASSERT_EQ(r.view.modules.size(), 1u);
  ASSERT_EQ(r.view.modules[0].types.size(), 1u);
  EXPECT_EQ(r.view.modules[0].types[0].name, "B");
  EXPECT_EQ(r.view.modules[0].values.size(), 1u);
}

TEST(Asn1Errors, StopsAfterTwentyErrors) {
  std::string body;
  for (int i = 0; i < 100; ++i) body += "T" + std::to_string(i) + " ::= SEQUENCE { a }\n";
  Read r;
  r.add(module(body));
  EXPECT_EQ(r.diags.error_count(), 20u);
  EXPECT_EQ(r.diags.all().back().severity, bipc::Severity::Note);
  EXPECT_EQ(r.diags.all().back().message, "too many errors: the rest of the file is not read");
}

}  // namespace
}  // namespace smcbip::taste2bip::asn1
