// Tests of instantiation: instance paths, ports bound through exports, hierarchical connectors,
// folded parameters, compound priorities and the instance-level errors.
#include <gtest/gtest.h>

#include <string>

#include "bipc/lower/detail/lowering.h"
#include "lower_test_util.h"

namespace smcbip::bipc {
namespace {

using lower_test::atom_index;
using lower_test::atom_port;
using lower_test::connector_index;
using lower_test::lower_ok;
using lower_test::lower_text;

// One port type, a rendezvous and an atom with two individually exported ports and a merged
// pair; every test model starts with it.
const std::string kPrelude =
    "  port type P()\n"
    "  port type D(int v)\n"
    "  connector type Rdv(P a, P b)\n"
    "    define a b\n"
    "  end\n"
    "  connector type One(P a)\n"
    "    define a\n"
    "  end\n"
    "  atom type A()\n"
    "    data int x\n"
    "    export data int y\n"
    "    export port P p(), q()\n"
    "    export port P m1(), m2() as m\n"
    "    place S\n"
    "    initial to S\n"
    "    on p from S to S\n"
    "    on q from S to S\n"
    "    on m1 from S to S\n"
    "    on m2 from S to S\n"
    "  end\n";

std::string package(const std::string& body) { return "package t\n" + kPrelude + body + "end\n"; }

TEST(LowerInstantiate, InstancePathsFollowTheCompoundTree) {
  auto lowered = lower_ok(package("  compound type Inner()\n"
                                  "    component A u(), v()\n"
                                  "  end\n"
                                  "  compound type Mid()\n"
                                  "    component Inner in()\n"
                                  "    component A w()\n"
                                  "  end\n"
                                  "  compound type Top()\n"
                                  "    component Mid a()\n"
                                  "    component A z()\n"
                                  "  end\n"),
                          "Top()");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  EXPECT_EQ(s.root_type, "t.Top");
  ASSERT_EQ(s.compounds.size(), 3u);
  EXPECT_EQ(s.compounds[0].path, "");
  EXPECT_EQ(s.compounds[0].parent, ir::kNone);
  EXPECT_EQ(s.compounds[0].type, "t.Top");
  EXPECT_EQ(s.compounds[1].path, "a");
  EXPECT_EQ(s.compounds[1].parent, 0u);
  EXPECT_EQ(s.compounds[2].path, "a.in");
  EXPECT_EQ(s.compounds[2].parent, 1u);
  EXPECT_EQ(s.compounds[2].type, "t.Inner");
  ASSERT_EQ(s.atoms.size(), 4u);
  EXPECT_EQ(s.atoms[atom_index(s, "a.in.u")].parent, 2u);
  EXPECT_EQ(s.atoms[atom_index(s, "a.w")].parent, 1u);
  EXPECT_EQ(s.atoms[atom_index(s, "z")].parent, 0u);
  EXPECT_NE(atom_index(s, "a.in.v"), ir::kNone);
  // Four instances of one type share it.
  EXPECT_EQ(s.atom_types.size(), 1u);
  EXPECT_EQ(s.atom_types[0].name, "t.A");
}

TEST(LowerInstantiate, MergedAtomExportBindsEveryMergedPort) {
  auto lowered = lower_ok(package("  compound type Top()\n"
                                  "    component A x(), y()\n"
                                  "    connector Rdv r(x.m, y.p)\n"
                                  "  end\n"),
                          "Top()");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::ConnectorInstance& r = s.connectors.at(connector_index(s, "r"));
  ASSERT_EQ(r.bound.size(), 2u);
  EXPECT_EQ(r.bound[0],
            (std::vector<ir::PortRef>{atom_port(s, "x", "m1"), atom_port(s, "x", "m2")}));
  EXPECT_EQ(r.bound[1], (std::vector<ir::PortRef>{atom_port(s, "y", "p")}));
  const ir::AtomType& a = s.atom_types[0];
  ASSERT_EQ(a.interface.size(), 3u);
  EXPECT_EQ(a.interface[2].name, "m");
  EXPECT_EQ(a.interface[2].ports.size(), 2u);
}

TEST(LowerInstantiate, CompoundExportsResolveDownToAtomPorts) {
  auto lowered = lower_ok(package("  compound type C()\n"
                                  "    component A a1(), a2(), a3()\n"
                                  "    export port a1.p, a2.p, a3.m as xport\n"
                                  "    export data a2.y as yy\n"
                                  "  end\n"
                                  "  compound type Outer()\n"
                                  "    component C c()\n"
                                  "    export port c.xport as deep\n"
                                  "  end\n"
                                  "  compound type Top()\n"
                                  "    component Outer o()\n"
                                  "    connector One s(o.deep)\n"
                                  "  end\n"),
                          "Top()");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::ConnectorInstance& k = s.connectors.at(connector_index(s, "s"));
  ASSERT_EQ(k.bound.size(), 1u);
  EXPECT_EQ(k.bound[0],
            (std::vector<ir::PortRef>{atom_port(s, "o.c.a1", "p"), atom_port(s, "o.c.a2", "p"),
                                      atom_port(s, "o.c.a3", "m1"), atom_port(s, "o.c.a3", "m2")}));
  const ir::CompoundInstance& c = s.compounds.at(2);
  EXPECT_EQ(c.path, "o.c");
  ASSERT_EQ(c.exported_data.count("yy"), 1u);
  EXPECT_EQ(c.exported_data.at("yy"),
            (std::pair<ir::Index, ir::Index>{atom_index(s, "o.c.a2"), 1u}));
  EXPECT_EQ(c.exported_ports.at("xport").size(), 4u);
}

TEST(LowerInstantiate, HierarchicalConnectorsRecordWhoBindsThem) {
  auto lowered = lower_ok(package("  connector type Up(P a, P b)\n"
                                  "    export port P e()\n"
                                  "    define a' b'\n"
                                  "  end\n"
                                  "  compound type C()\n"
                                  "    component A a(), b()\n"
                                  "    connector Up inner(a.p, b.p)\n"
                                  "    export port inner.e as u\n"
                                  "  end\n"
                                  "  compound type Top()\n"
                                  "    component A x(), y()\n"
                                  "    component C c()\n"
                                  "    connector Up sel(x.p, y.p)\n"
                                  "    connector Rdv top(sel.e, c.u)\n"
                                  "  end\n"),
                          "Top()");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::Index sel = connector_index(s, "sel");
  const ir::Index inner = connector_index(s, "c.inner");
  const ir::Index top = connector_index(s, "top");
  ASSERT_NE(top, ir::kNone);
  const ir::ConnectorInstance& t = s.connectors[top];
  EXPECT_EQ(t.bound[0], (std::vector<ir::PortRef>{{ir::PortRef::Kind::Connector, sel, 0}}));
  EXPECT_EQ(t.bound[1], (std::vector<ir::PortRef>{{ir::PortRef::Kind::Connector, inner, 0}}));
  EXPECT_EQ(s.connectors[sel].bound_by, top);
  EXPECT_EQ(s.connectors[inner].bound_by, top);
  EXPECT_EQ(t.bound_by, ir::kNone);
  const ir::ConnectorType& up = s.connector_types[s.connectors[sel].type];
  EXPECT_EQ(up.export_name, "e");
  ASSERT_EQ(up.define.size(), 2u);
  EXPECT_TRUE(up.define[0].trigger);
  EXPECT_EQ(up.define[1].port, 1u);
}

TEST(LowerInstantiate, ParametersAndConstantsAreFoldedIntoAtomInstances) {
  auto lowered = lower_ok(
      "package t\n"
      "  const data int N = 3\n"
      "  const data int M = N * 2 + 1\n"
      "  const data float HALF = 0.5\n"
      "  port type P()\n"
      "  atom type B(int k, float f, bool flag, string name)\n"
      "    data int x\n"
      "    place S\n"
      "    initial to S do { x = k; }\n"
      "  end\n"
      "  compound type Mid(int k)\n"
      "    component B b(k + M, k, k > 2, \"mid\")\n"
      "  end\n"
      "  compound type Top()\n"
      "    component Mid m(N)\n"
      "    component B c(-M, HALF * 3, false, \"top\")\n"
      "  end\n"
      "end\n",
      "Top()");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const auto& b = s.atoms.at(atom_index(s, "m.b")).params;
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[0].kind, ir::ValueKind::Int);
  EXPECT_EQ(b[0].i, 10);
  EXPECT_EQ(b[1].kind, ir::ValueKind::Float);  // int argument for a float parameter
  EXPECT_DOUBLE_EQ(b[1].f, 3.0);
  EXPECT_EQ(b[2].kind, ir::ValueKind::Bool);
  EXPECT_TRUE(b[2].b);
  EXPECT_EQ(b[3].s, "mid");
  const auto& c = s.atoms.at(atom_index(s, "c")).params;
  EXPECT_EQ(c[0].i, -7);
  EXPECT_DOUBLE_EQ(c[1].f, 1.5);
  EXPECT_FALSE(c[2].b);
}

TEST(LowerInstantiate, CompoundPrioritiesResolvePatternsAndGuards) {
  auto lowered = lower_ok(package("  compound type Top(int limit)\n"
                                  "    component A a(), b(), c()\n"
                                  "    connector Rdv c1(a.p, b.p)\n"
                                  "    connector Rdv c2(a.q, b.q)\n"
                                  "    connector One c3(c.p)\n"
                                  "    priority one c1:* < c2:a.q,b.q provided (a.y < limit)\n"
                                  "    priority two *:* < c3:*\n"
                                  "  end\n"),
                          "Top(4)");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const auto& priorities = s.compounds[0].priorities;
  ASSERT_EQ(priorities.size(), 2u);
  const ir::Priority& one = priorities[0];
  EXPECT_EQ(one.name, "one");
  EXPECT_EQ(one.low.connector, connector_index(s, "c1"));
  EXPECT_TRUE(one.low.all_ports);
  EXPECT_EQ(one.high.connector, connector_index(s, "c2"));
  EXPECT_FALSE(one.high.all_ports);
  EXPECT_EQ(one.high.ports,
            (std::vector<ir::PortRef>{atom_port(s, "a", "q"), atom_port(s, "b", "q")}));
  // `a.y` reads slot 1 of atom a; the compound parameter is folded to its value.
  const std::string load_y =
      "load instance[" + std::to_string(atom_index(s, "a")) + "].data[1] ; a.y";
  EXPECT_EQ(lower_test::code_text(one.guard, s),
            (std::vector<std::string>{load_y, "push.int 4", "lt.int"}));
  const ir::Priority& two = priorities[1];
  EXPECT_EQ(two.low.connector, ir::kNone);
  EXPECT_EQ(two.high.connector, connector_index(s, "c3"));
  EXPECT_TRUE(two.guard.empty());
}

// The checker already refuses a connector binding one component twice; what reaches the
// instance check can only come from a hand-made system, so it is built here directly.
ir::System two_atom_system() {
  ir::System s;
  ir::AtomType a;
  a.name = "t.A";
  a.ports.resize(2);
  a.ports[0].name = "p";
  a.ports[1].name = "q";
  a.ports[1].stochastic = ir::Stochastic{};
  s.atom_types.push_back(a);
  s.connector_types.resize(1);
  s.compounds.resize(1);
  for (const char* path : {"x", "y"}) s.atoms.push_back({path, 0, 0, {}, {}});
  return s;
}

ir::ConnectorInstance connector(const std::string& path,
                                std::vector<std::vector<ir::PortRef>> bound) {
  ir::ConnectorInstance k;
  k.path = path;
  k.bound = std::move(bound);
  return k;
}

constexpr auto kAtom = ir::PortRef::Kind::Atom;
constexpr auto kConnector = ir::PortRef::Kind::Connector;

TEST(LowerInstanceChecks, AtomReachedThroughTwoPortsIsAnError) {
  ir::System s = two_atom_system();
  // sub binds x.p and exports; top binds sub's export and x.q: x would move twice.
  s.connectors.push_back(connector("sub", {{{kAtom, 0, 0}}}));
  s.connectors.push_back(connector("top", {{{kConnector, 0, 0}}, {{kAtom, 0, 1}}}));
  // Alternatives of one merged port are not a conflict.
  s.connectors.push_back(connector("merged", {{{kAtom, 1, 0}, {kAtom, 1, 1}}}));
  Diagnostics diags;
  lower::check_instances(s, {{0, 1, 1}, {0, 2, 1}, {0, 3, 1}}, diags);
  ASSERT_EQ(diags.error_count(), 1u) << diags.format({});
  EXPECT_EQ(diags.all()[0].message, "connector 'top' binds atom 'x' twice");
  EXPECT_EQ(diags.all()[0].location.line, 2u);
}

TEST(LowerInstanceChecks, StochasticPortsAreCountedPerInteraction) {
  ir::System s = two_atom_system();
  s.connectors.push_back(connector("one", {{{kAtom, 0, 1}, {kAtom, 0, 0}}}));
  s.connectors.push_back(connector("sub", {{{kAtom, 0, 1}}}));
  s.connectors.push_back(connector("two", {{{kConnector, 1, 0}}, {{kAtom, 1, 1}}}));
  Diagnostics diags;
  lower::check_instances(s, {}, diags);
  ASSERT_EQ(diags.error_count(), 1u) << diags.format({});
  EXPECT_NE(diags.all()[0].message.find("connector 'two': at most one stochastic port per "
                                        "interaction"),
            std::string::npos);
}

TEST(LowerInstanceChecks, CyclesOfHierarchicalConnectorsAreReported) {
  ir::System s = two_atom_system();
  s.connectors.push_back(connector("a", {{{kConnector, 1, 0}}}));
  s.connectors.push_back(connector("b", {{{kConnector, 0, 0}}}));
  Diagnostics diags;
  lower::check_instances(s, {}, diags);
  ASSERT_EQ(diags.error_count(), 1u) << diags.format({});
  EXPECT_NE(diags.all()[0].message.find("form a cycle"), std::string::npos);
}

TEST(LowerInstantiate, TwoStochasticPortsInOneConnectorAreAnError) {
  auto lowered = lower_text(
      "package t\n"
      "  port type P()\n"
      "  connector type Rdv(P a, P b)\n"
      "    define a b\n"
      "  end\n"
      "  atom type S()\n"
      "    clock c\n"
      "    @stochastic(dist=\"exponential\", clk=c, param=\"5\")\n"
      "    export port P p()\n"
      "    place L\n"
      "    initial to L\n"
      "    on p from L to L do { c = 0; }\n"
      "  end\n"
      "  compound type Top()\n"
      "    component S a(), b()\n"
      "    connector Rdv r(a.p, b.p)\n"
      "  end\n"
      "end\n",
      "Top()");
  EXPECT_TRUE(lowered->checked) << lowered->messages();
  EXPECT_FALSE(lowered->system);
  EXPECT_TRUE(lowered->has_message("connector 'r': at most one stochastic port per interaction"))
      << lowered->messages();
}

TEST(LowerInstantiate, ConnectorExportMayFeedSeveralConnectors) {
  // As in the conformance model maximal_progress: `low` is bound inside and exported outside.
  auto lowered = lower_ok(package("  connector type Up(P a)\n"
                                  "    export port P e()\n"
                                  "    define a\n"
                                  "  end\n"
                                  "  compound type C()\n"
                                  "    component A x(), y()\n"
                                  "    connector Up low(x.p)\n"
                                  "    connector Rdv high(low.e, y.p)\n"
                                  "    export port low.e as out\n"
                                  "  end\n"
                                  "  compound type Top()\n"
                                  "    component C c()\n"
                                  "    connector One single(c.out)\n"
                                  "  end\n"),
                          "Top()");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::ConnectorInstance& low = s.connectors.at(connector_index(s, "c.low"));
  EXPECT_EQ(low.bound_by, connector_index(s, "c.high"));
  EXPECT_EQ(low.bound_by_all,
            (std::vector<ir::Index>{connector_index(s, "c.high"), connector_index(s, "single")}));
}

TEST(LowerInstantiate, AnnotationsAndCppFilesAreKept) {
  auto lowered = lower_ok(
      "@cpp(src=\"a.cpp, b.cpp\", include=\"a.hpp\")\n"
      "package t\n" +
          kPrelude +
          "  compound type Top()\n"
          "    @fault(kind=\"stuck\")\n"
          "    component A x()\n"
          "    @mark\n"
          "    connector One k(x.p)\n"
          "  end\n"
          "end\n",
      "Top()");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  EXPECT_EQ(s.cpp_sources, (std::vector<std::string>{"a.cpp", "b.cpp"}));
  EXPECT_EQ(s.cpp_includes, (std::vector<std::string>{"a.hpp"}));
  ASSERT_EQ(s.atoms[0].annotations.size(), 1u);
  EXPECT_EQ(s.atoms[0].annotations[0].name, "fault");
  EXPECT_EQ(s.atoms[0].annotations[0].params.at(0).second, "stuck");
  ASSERT_EQ(s.connectors[0].annotations.size(), 1u);
  EXPECT_EQ(s.connectors[0].annotations[0].name, "mark");
}

}  // namespace
}  // namespace smcbip::bipc
