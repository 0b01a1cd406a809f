// Tests of package-level checking: lookup across used packages, constants, extern types and
// prototypes, duplicate declarations, component interfaces, and the conformance corpus.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bipc/bipc.h"
#include "bipc/check/detail/check_context.h"
#include "check_test_util.h"
#include "shared_data.h"

namespace smcbip::bipc {
namespace {

using check_test::check_text;
using check_test::check_texts;
using check_test::Checked;

TEST(CheckPackage, QualifiedAndTransitiveLookup) {
  const Checked c =
      check_texts({"package lib.base\n  const data int N = 4\n  port type P(int v)\nend\n",
                   "package mid\n  use lib.base\n  extern data type T\nend\n",
                   "package top\n  use mid\n"
                   "  atom type A()\n    data int n = lib.base.N + N\n    data T t\n"
                   "    export port lib.base.P p(n)\n    export port P q(n)\n    place L\n"
                   "    initial to L\n  end\nend\n"});
  EXPECT_TRUE(c.ok) << c.text();
  const ast::AtomTypeDecl& atom = c.model.packages[2]->atom_types[0];
  EXPECT_EQ(atom.ports[0].port_type, &c.model.packages[0]->port_types[0]);
  EXPECT_EQ(atom.ports[1].port_type, &c.model.packages[0]->port_types[0]);
  EXPECT_EQ(atom.data[1].type.resolved.extern_type, &c.model.packages[1]->extern_types[0]);
  const detail::Symbols symbols(c.model);
  EXPECT_EQ(symbols.package_of(&atom), c.model.packages[2].get());
}

TEST(CheckPackage, OwnDeclarationsHideUsedOnes) {
  const Checked c = check_texts(
      {"package lib\n  port type P(int v)\nend\n",
       "package top\n  use lib\n  port type P()\n"
       "  atom type A()\n    export port P p()\n    place L\n    initial to L\n  end\nend\n"});
  EXPECT_TRUE(c.ok) << c.text();
}

TEST(CheckPackage, Constants) {
  const Checked c = check_text(
      "package t\n"
      "  extern data type T\n"
      "  extern function int f()\n"
      "  const data int A = B + 1\n"
      "  const data int B = 2\n"
      "  const data float C = B * 1.5\n"
      "  const data int D = 2.5\n"
      "  const data T E = 1\n"
      "  const data int F = f()\n"
      "end\n");
  EXPECT_TRUE(c.has(4, 22, "constant 'B' is used before its declaration")) << c.text();
  EXPECT_TRUE(c.has(7, 22, "cannot assign float to int constant 'D'")) << c.text();
  EXPECT_TRUE(c.has(8, 14, "must have a native type")) << c.text();
  EXPECT_TRUE(c.has(9, 22, "constant expression")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 4U) << c.text();
}

TEST(CheckPackage, ExternTypesAndPrototypes) {
  const Checked c = check_text(
      "package t\n"
      "  extern data type A refine B\n"
      "  extern data type B refine A\n"
      "  extern data type C refine int\n"
      "  extern function Nope g(int)\n"
      "  extern operator A -(A)\n"
      "  extern operator A -(A, Nope)\n"
      "end\n");
  EXPECT_TRUE(c.has(2, 29, "the refinements form a cycle")) << c.text();
  EXPECT_TRUE(c.has(3, 29, "the refinements form a cycle")) << c.text();
  EXPECT_TRUE(c.has(4, 29, "can only refine extern data types")) << c.text();
  EXPECT_TRUE(c.has(5, 19, "unknown data type 'Nope'")) << c.text();
  EXPECT_TRUE(c.has(7, 26, "unknown data type 'Nope'")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 5U) << c.text();
}

TEST(CheckPackage, RefinementMakesSubtypes) {
  const Checked c = check_text(
      "package t\n"
      "  extern data type List\n"
      "  extern data type IntList refine List\n"
      "  extern function IntList make()\n"
      "  extern function int size(const List)\n"
      "  port type P()\n"
      "  atom type A()\n    data List l\n    data IntList il\n    data int n\n"
      "    export port P p()\n    place L\n"
      "    initial to L do { il = make(); l = il; n = size(il); il = l; }\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(13, 63, "cannot assign List to IntList")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
}

TEST(CheckPackage, DuplicateTypesAcrossKinds) {
  const Checked c = check_text(
      "package t\n"
      "  const data int X = 1\n  const data int X = 2\n"
      "  port type X()\n"
      "  connector type X(X p)\n    define p\n  end\n"
      "end\n");
  EXPECT_TRUE(c.has(3, 18, "duplicate declaration of 'X'")) << c.text();
  EXPECT_TRUE(c.has(5, 18, "duplicate declaration of 'X'")) << c.text();
  bool noted = false;
  for (const Diagnostic& d : c.diags.all()) {
    noted = noted || (d.severity == Severity::Note && d.location.line == 4);
  }
  EXPECT_TRUE(noted) << c.text();
}

TEST(CheckPackage, ComponentInterfaces) {
  Checked c = check_text(
      "package t\n"
      "  port type P(int v)\n  port type Q()\n"
      "  atom type A()\n"
      "    export data int n\n    data int hidden\n"
      "    export port P a(n), b(n) as m\n    export port Q q()\n    port Q inner()\n"
      "    place L\n    initial to L\n  end\n"
      "  connector type R(P x)\n    data int d\n    export port P e(d)\n    define x\n"
      "    on x up { d = x.v; }\n  end\n"
      "  compound type K()\n    component A c1(), c2()\n    connector R r(c1.m)\n"
      "    export port r.e as out\n    export port c2.q as qq\n    export data c1.n as nn\n"
      "  end\n"
      "  compound type Top()\n    component K k()\n    connector R r2(k.out)\n  end\n"
      "end\n");
  ASSERT_TRUE(c.ok) << c.text();
  const ast::Package& package = *c.model.packages[0];
  const detail::Symbols symbols(c.model);
  const detail::ComponentInterface atom =
      detail::interface_of(package.compound_types[0].components[0], symbols);
  ASSERT_EQ(atom.ports.size(), 2U);
  EXPECT_EQ(atom.ports[0].name, "m");
  EXPECT_EQ(atom.ports[0].type, &package.port_types[0]);
  EXPECT_EQ(atom.ports[1].name, "q");
  ASSERT_EQ(atom.data.size(), 1U);
  EXPECT_EQ(atom.data[0].name, "n");
  const detail::ComponentInterface compound =
      detail::interface_of(package.compound_types[1].components[0], symbols);
  ASSERT_EQ(compound.ports.size(), 2U);
  EXPECT_EQ(compound.ports[0].name, "out");
  EXPECT_EQ(compound.ports[0].type, &package.port_types[0]);
  EXPECT_EQ(compound.ports[1].type, &package.port_types[1]);
  ASSERT_EQ(compound.data.size(), 1U);
  EXPECT_EQ(compound.data[0].name, "nn");
  EXPECT_EQ(compound.data[0].type.kind, ast::ValueType::Kind::Int);
}

TEST(CheckPackage, RedefinedAnnotationIsAnError) {
  const Checked c = check_text(
      "@cpp(src=\"a.cpp\") @cpp(src=\"b.cpp\")\n"
      "package t\n"
      "  @doc @doc(text=\"again\")\n"
      "  port type P()\n"
      "  atom type A()\n"
      "    @trace(level=high) @fault @trace\n"
      "    export port P p(), q()\n"
      "    place L\n"
      "    initial to L\n"
      "    @a @b @a\n"
      "    on p from L to L\n"
      "  end\n"
      "  @doc @text @note\n"
      "  connector type C(P a)\n    define a\n  end\n"
      "end\n");
  EXPECT_TRUE(c.has(1, 19, "annotation '@cpp' is redefined on package 't'")) << c.text();
  EXPECT_TRUE(c.has(3, 8, "annotation '@doc' is redefined on port type 'P'")) << c.text();
  EXPECT_TRUE(c.has(Severity::Note, 3, 3, "it is first given here")) << c.text();
  // The ports of one declaration share its annotations: one error, not one per port.
  EXPECT_TRUE(c.has(6, 31, "annotation '@trace' is redefined on port 'p'")) << c.text();
  EXPECT_TRUE(c.has(10, 11, "annotation '@a' is redefined on a transition of atom type 'A'"))
      << c.text();
  EXPECT_EQ(c.diags.error_count(), 4U) << c.text();
}

/// Checks every model of a corpus; returns the files with errors.
std::vector<std::string> rejected_in(const std::filesystem::path& dir) {
  std::vector<std::string> rejected;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".bip") continue;
    Diagnostics diags;
    LoadedModel model = load(entry.path().string(), {}, diags);
    if (!diags.has_errors()) check(model, diags);
    if (diags.has_errors()) rejected.push_back(entry.path().filename().string());
  }
  std::sort(rejected.begin(), rejected.end());
  return rejected;
}

TEST(CheckConformance, ReferenceModelsCheckClean) {
  const std::filesystem::path data = test::shared_data_dir();
  if (!std::filesystem::exists(data / "bip-conformance")) {
    GTEST_SKIP() << "shared conformance data not found (set SMCBIP_SHARED_DATA)";
  }
  EXPECT_EQ(rejected_in(data / "bip-conformance" / "running"),
            std::vector<std::string>{"priority_rules_cycle2.bip"});
  EXPECT_EQ(rejected_in(data / "bip-conformance" / "compile_only"),
            (std::vector<std::string>{"priority_rules_atom_cycle.bip",
                                      "priority_rules_atom_cycle2.bip"}));
  EXPECT_TRUE(rejected_in(data / "bip-conformance" / "running_multithread_extra").empty());
  EXPECT_TRUE(rejected_in(data / "esrocos-mc_watchdog" / "BipModel" / "sources").empty());
}

}  // namespace
}  // namespace smcbip::bipc
