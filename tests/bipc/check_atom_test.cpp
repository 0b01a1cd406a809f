// Tests of atom type checking: declarations, port bindings, the Petri net, priorities (including
// the compile-time cycle check) and the @stochastic annotation.
#include <gtest/gtest.h>

#include <string>

#include "bipc/bipc.h"
#include "check_test_util.h"

namespace smcbip::bipc {
namespace {

using check_test::check_text;
using check_test::Checked;

/// Ports p, q, r, s of type P in an atom; `body` comes at line 7.
std::string ports_atom(const std::string& body) {
  return "package t\n"
         "  port type P()\n"
         "  atom type A()\n"
         "    export port P p(), q(), r(), s()\n"
         "    place L\n"
         "    initial to L\n" +
         body + "  end\nend\n";
}

TEST(CheckAtom, ResolvedFieldsAreFilled) {
  Checked c = check_text(
      "package t\n"
      "  port type V(int v, float w)\n"
      "  atom type A()\n"
      "    data float g\n    data int n\n"
      "    export port V p(n, g)\n    port V q(n, g)\n"
      "    place L, M\n"
      "    initial to L\n"
      "    on q from L, M to M\n"
      "    priority low p < q\n"
      "    invariant i at M provided (n > 0)\n"
      "  end\nend\n");
  ASSERT_TRUE(c.ok) << c.text();
  const ast::AtomTypeDecl& atom = c.model.packages[0]->atom_types[0];
  EXPECT_EQ(atom.ports[0].port_type, &c.model.packages[0]->port_types[0]);
  EXPECT_EQ(atom.ports[0].bound_data_index, (std::vector<int>{1, 0}));
  EXPECT_EQ(atom.transitions[0].port_index, 1);
  EXPECT_EQ(atom.transitions[0].from_index, (std::vector<int>{0, 1}));
  EXPECT_EQ(atom.transitions[0].to_index, (std::vector<int>{1}));
  EXPECT_EQ(atom.priorities[0].low_index, 0);
  EXPECT_EQ(atom.priorities[0].high_index, 1);
  EXPECT_EQ(atom.invariants[0].place_index, (std::vector<int>{1}));
}

TEST(CheckAtom, OneNamespaceForParamsDataPortsClocks) {
  const Checked c = check_text(
      "package t\n"
      "  port type P()\n"
      "  atom type A(int x)\n"
      "    data int x\n"
      "    clock p\n"
      "    export port P p(), q() as p\n"
      "    place L, L\n"
      "    initial to L\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(4, 14, "duplicate declaration of 'x'")) << c.text();
  EXPECT_TRUE(c.has(6, 19, "duplicate declaration of 'p'")) << c.text();  // the clock came first
  EXPECT_TRUE(c.has(6, 31, "duplicate declaration of 'p'")) << c.text();
  EXPECT_TRUE(c.has(7, 14, "duplicate declaration of 'L'")) << c.text();
}

TEST(CheckAtom, PortBindings) {
  const Checked c = check_text(
      "package t\n"
      "  port type V(int v, float w)\n"
      "  atom type A(int k)\n"
      "    data int n\n    data int m\n    clock x\n"
      "    port V a(n)\n"
      "    port V b(k, m)\n"
      "    port V c(n, m)\n"
      "    port V d(n, x)\n"
      "    port W e()\n"
      "    place L\n"
      "    initial to L\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(7, 12, "port 'a' of type 'V' expects 2 data, got 1")) << c.text();
  EXPECT_TRUE(c.has(8, 14, "'k' is a constant parameter, a port can only bind variables"))
      << c.text();
  EXPECT_TRUE(c.has(9, 17, "binds 'm' of type int to parameter 'w' of type float")) << c.text();
  EXPECT_TRUE(c.has(10, 17, "port 'd' cannot bind clock 'x'")) << c.text();
  EXPECT_TRUE(c.has(11, 10, "unknown port type 'W'")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 6U) << c.text();  // b's 'm' is also of the wrong type
}

TEST(CheckAtom, PortBindsConstantsNotVariables) {
  const Checked c = check_text(
      "package t\n"
      "  const data int LIMIT = 3\n"
      "  port type V(int v)\n"
      "  atom type A(int k)\n"
      "    data const int fixed = 1\n"
      "    data int n\n"
      "    export port V a(LIMIT), b(fixed), c(k), d(n), e(missing)\n"
      "    place L\n"
      "    initial to L\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(7, 21, "'LIMIT' is a constant data, a port can only bind variables"))
      << c.text();
  EXPECT_TRUE(c.has(7, 31, "'fixed' is a constant data, a port can only bind variables"))
      << c.text();
  EXPECT_TRUE(c.has(7, 41, "'k' is a constant parameter, a port can only bind variables"))
      << c.text();
  EXPECT_TRUE(c.has(7, 53, "undeclared data 'missing' bound by port 'e'")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 4U) << c.text();
}

TEST(CheckAtom, PetriNetReferences) {
  const Checked c =
      check_text(ports_atom("    on z from L to M\n"
                            "    on p from L, L to L\n"
                            "    invariant i at N provided (true)\n"));
  EXPECT_TRUE(c.has(7, 8, "undeclared port 'z'")) << c.text();
  EXPECT_TRUE(c.has(7, 20, "undeclared place 'M'")) << c.text();
  EXPECT_TRUE(c.has(8, 18, "place 'L' appears twice in 'from'")) << c.text();
  EXPECT_TRUE(c.has(9, 20, "undeclared place 'N'")) << c.text();
}

TEST(CheckAtom, PriorityCycleThroughWildcard) {
  const Checked c =
      check_text(ports_atom("    priority a p < q\n"
                            "    priority b q < *\n"
                            "    priority c r < s provided (true)\n"
                            "    priority d s < r\n"));
  EXPECT_TRUE(c.has(8, 14, "atom priorities form a cycle: q < p < q")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
}

TEST(CheckAtom, PriorityCycleReportedWhereItCloses) {
  const Checked c =
      check_text(ports_atom("    priority a p < q\n"
                            "    priority b q < r\n"
                            "    priority c r < p\n"
                            "    priority d s < s\n"
                            "    priority e * < *\n"
                            "    priority e p < s\n"));
  EXPECT_TRUE(c.has(9, 14, "atom priorities form a cycle: r < p < q < r")) << c.text();
  EXPECT_TRUE(c.has(10, 14, "atom priorities form a cycle: s < s")) << c.text();
  EXPECT_TRUE(c.has(11, 14, "wildcard '*' on both sides")) << c.text();
  EXPECT_TRUE(c.has(12, 14, "duplicate declaration of 'e'")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 4U) << c.text();
}

TEST(CheckAtom, WildcardsWithoutCycle) {
  const Checked c =
      check_text(ports_atom("    priority a p < q\n"
                            "    priority b * < q\n"
                            "    priority c s < *\n"));
  EXPECT_TRUE(c.ok) << c.text();
}

TEST(CheckAtom, StochasticAnnotation) {
  const Checked c = check_text(
      "package t\n"
      "  port type P()\n"
      "  atom type A(float mu)\n"
      "    data int n\n    data bool b\n    clock x\n"
      "    @stochastic(dist=\"normal\", clk=x, param=\"mu, 2.5\")\n"
      "    export port P ok()\n"
      "    @stochastic(dist=\"poisson\", clk=y, param=\"1\")\n"
      "    export port P bad1()\n"
      "    @stochastic(dist=\"gamma\", clk=x, param=\"n\")\n"
      "    export port P bad2()\n"
      "    @stochastic(dist=\"uniform\", clk=x, param=\"b, zz\")\n"
      "    export port P bad3()\n"
      "    @stochastic(dist=\"custom\", clk=x, param=\"cdf.txt\")\n"
      "    @stochastic(dist=\"exponential\", clk=x, param=\"1e3\")\n"
      "    export port P twice()\n"
      "    place L\n"
      "    initial to L\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(9, 22, "unknown distribution 'poisson'")) << c.text();
  EXPECT_TRUE(c.has(9, 37, "undeclared clock 'y'")) << c.text();
  EXPECT_TRUE(c.has(11, 44, "distribution 'gamma' takes 2 parameters")) << c.text();
  EXPECT_TRUE(c.has(13, 46, "'b' has type bool: expected int or float")) << c.text();
  EXPECT_TRUE(c.has(13, 46, "'zz' must be a number or the name of a parameter or data"))
      << c.text();
  EXPECT_TRUE(c.has(16, 5, "annotation '@stochastic' is redefined on port 'twice'")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 6U) << c.text();
}

TEST(CheckAtom, ConstDataNeedsAValue) {
  const Checked c = check_text(
      "package t\n"
      "  port type P()\n"
      "  atom type A(string name)\n"
      "    data const int j\n    data int n = 1.5\n    data float f = n\n"
      "    export port P p()\n    place L\n    initial to L\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(4, 20, "constant data 'j' must be initialised")) << c.text();
  EXPECT_TRUE(c.has(5, 18, "cannot assign float to int 'n'")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 2U) << c.text();
}

}  // namespace
}  // namespace smcbip::bipc
