// Tests of expression and statement checking: native and extern operators, overloads, names per
// context, assignments, and the timed-automata forms of clock guards.
#include <gtest/gtest.h>

#include <string>

#include "bipc/bipc.h"
#include "check_test_util.h"

namespace smcbip::bipc {
namespace {

using check_test::check_text;
using check_test::Checked;

/// An atom with data `n`, `f`, `b`, `s`, parameter `k`, clocks `x`, `y`, an extern type and a
/// few prototypes; `body` adds transitions (line 14 onwards).
std::string atom_with(const std::string& body) {
  return "package p\n"                                // 1
         "  extern data type List\n"                  // 2
         "  extern function int size(const List)\n"   // 3
         "  extern function float min(float, int)\n"  // 4
         "  extern function float min(int, float)\n"  // 5
         "  extern function log(const string)\n"      // 6
         "  const data int K = 3\n"                   // 7
         "  port type P()\n"                          // 8
         "  atom type A(int k)\n"                     // 9
         "    data int n\n    data float f\n"         // 10, 11
         "    data bool b\n    data string s\n"       // 12, 13
         "    data List l\n    clock x, y\n"          // 14, 15
         "    export port P p()\n    place L\n"       // 16, 17
         "    initial to L\n" +                       // 18
         body +
         "  end\nend\n";  // 19..
}

TEST(CheckExpressions, NativeArithmeticAndComparisons) {
  const Checked c = check_text(
      atom_with("    on p from L to L provided (n + 1 < f && !b && s == \"a\" && n % 2 == 0)\n"
                "      do { f = n * 2.5; n = n / 2; b = (n & 1) == 1; }\n"));
  EXPECT_TRUE(c.ok) << c.text();
}

TEST(CheckExpressions, OperatorTypeErrors) {
  const Checked c =
      check_text(atom_with("    on p from L to L do { n = f % 2; b = b + 1; n = s; f = true; }\n"));
  EXPECT_FALSE(c.ok);
  EXPECT_TRUE(c.has(19, 0, "operator '%' expects int operands, got float and int")) << c.text();
  EXPECT_TRUE(c.has(19, 0, "operator '+' expects int or float operands")) << c.text();
  EXPECT_TRUE(c.has(19, 0, "cannot assign string to int")) << c.text();
  EXPECT_TRUE(c.has(19, 0, "cannot assign bool to float")) << c.text();
}

TEST(CheckExpressions, IntConvertsToFloatButNotBack) {
  const Checked c = check_text(atom_with("    on p from L to L do { f = n; n = f; }\n"));
  EXPECT_TRUE(c.has(19, 38, "cannot assign float to int 'n'")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
}

TEST(CheckExpressions, OverloadResolution) {
  const Checked c = check_text(atom_with(
      "    on p from L to L do { f = min(1.0, 2); n = size(l); f = min(1, 2); }\n"
      "    internal from L to L do { n = nope(1); log(\"x\"); n = log(\"y\"); log(3); }\n"));
  EXPECT_TRUE(c.has(19, 61, "ambiguous call to 'min' with argument types (int, int)")) << c.text();
  EXPECT_TRUE(c.has(20, 35, "undeclared function 'nope'")) << c.text();
  EXPECT_TRUE(c.has(20, 58, "function 'log' has no return value")) << c.text();
  EXPECT_TRUE(c.has(20, 68, "no matching prototype for call to 'log' with argument types (int)"))
      << c.text();
  EXPECT_EQ(c.diags.error_count(), 4U) << c.text();
}

TEST(CheckExpressions, MostPreciseOverloadWins) {
  const Checked c = check_text(
      "package p\n"
      "  extern function float g(float, float)\n"
      "  extern function int g(int, int)\n"
      "  port type P()\n"
      "  atom type A()\n    data int n\n    export port P p()\n    place L\n"
      "    initial to L do { n = g(1, 2); }\n"
      "  end\nend\n");
  EXPECT_TRUE(c.ok) << c.text();
}

TEST(CheckExpressions, ExternOperators) {
  const Checked c = check_text(
      "package p\n"
      "  extern data type C\n"
      "  extern function C zero()\n"
      "  extern operator C +(const C, const C)\n"
      "  extern operator C *(const float, const C)\n"
      "  extern operator bool ==(const C, const C)\n"
      "  port type P()\n"
      "  atom type A()\n    data C c\n    export port P p()\n    place L\n"
      "    initial to L do { c = zero(); }\n"
      "    on p from L to L provided (c == c) do { c = 2 * c + c; c = c * 2; }\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(13, 66, "no matching operator '*' for operand types (C, int)")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
}

TEST(CheckExpressions, AssignmentTargets) {
  const Checked c = check_text(
      atom_with("    on p from L to L do { k = 1; K = 2; x = 0; x' = 2.0; n' = 1.0; }\n"));
  EXPECT_TRUE(c.has(19, 27, "cannot assign to parameter 'k'")) << c.text();
  EXPECT_TRUE(c.has(19, 34, "cannot assign to constant 'K'")) << c.text();
  EXPECT_TRUE(c.has(19, 58, "only a clock has a rate")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 3U) << c.text();
}

TEST(CheckExpressions, ConstArgumentsAndGuardCalls) {
  const Checked c = check_text(
      "package p\n"
      "  extern function bump(int)\n"
      "  extern function bool peek(int)\n"
      "  const data int K = 1\n"
      "  port type P()\n"
      "  atom type A()\n    data int n\n    data const int j = 2\n"
      "    export port P p()\n    place L\n"
      "    initial to L do { n = 0; bump(n); bump(K); bump(j); }\n"
      "    on p from L to L provided (peek(n))\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(11, 44, "cannot pass constant 'K'")) << c.text();
  EXPECT_TRUE(c.has(11, 53, "cannot pass constant 'j'")) << c.text();
  EXPECT_TRUE(c.has(12, 37, "non-const parameter 1")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 3U) << c.text();
}

TEST(CheckExpressions, ClockGuardForms) {
  const Checked c = check_text(atom_with(
      "    on p from L to L provided (x >= 2 && 5 > y && (x < k || n == 1)) do { x = 0; }\n"
      "    on p from L to L provided (x - y <= 3 && x <= y + 1 && -x < -2)\n"
      "    on p from L to L provided (x != 3)\n"
      "    on p from L to L provided (!(x < 3))\n"
      "    on p from L to L provided (x < 1 || y > 2)\n"
      "    on p from L to L provided (2 * x < 3)\n"
      "    on p from L to L provided (x + y < 3)\n"
      "    on p from L to L do { n = x; }\n"));
  EXPECT_TRUE(c.has(21, 32, "'!=' cannot compare clock 'x'")) << c.text();
  EXPECT_TRUE(c.has(22, 32, "negation '!' cannot apply")) << c.text();
  EXPECT_TRUE(c.has(23, 32, "one side of '||'")) << c.text();
  EXPECT_TRUE(c.has(24, 36, "clock 'x' can only be compared with")) << c.text();
  EXPECT_TRUE(c.has(25, 32, "through their difference")) << c.text();
  EXPECT_TRUE(c.has(26, 31, "clock 'x' can only be compared with")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 6U) << c.text();
}

TEST(CheckExpressions, ClocksAreUntimedInPrioritiesAndInternalTransitions) {
  const Checked c =
      check_text(atom_with("    internal from L to L provided (x > 1)\n"
                           "    priority q p < p provided (x > 2)\n"));
  EXPECT_TRUE(c.has(19, 36, "internal transition cannot use clock 'x'")) << c.text();
  EXPECT_TRUE(c.has(20, 32, "clock 'x' can only be compared with")) << c.text();
}

TEST(CheckExpressions, ConditionsMustBeBool) {
  const Checked c =
      check_text(atom_with("    on p from L to L provided (n + 1) do { if (f) then n = 1; fi }\n"));
  EXPECT_TRUE(c.has(19, 32, "a transition guard must be a bool expression, got int")) << c.text();
  EXPECT_TRUE(c.has(19, 48, "an if condition must be a bool expression, got float")) << c.text();
}

TEST(CheckExpressions, UndeclaredNames) {
  const Checked c =
      check_text(atom_with("    on p from L to L provided (m > 0) do { n = q.r; }\n"));
  EXPECT_TRUE(c.has(19, 32, "undeclared variable 'm'")) << c.text();
  EXPECT_TRUE(c.has(19, 48, "undeclared variable 'q.r'")) << c.text();
}

}  // namespace
}  // namespace smcbip::bipc
