// Tests of code compilation: short circuits, conversions, folding, statements, connector
// transfer code and @stochastic parameters.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lower_test_util.h"

namespace smcbip::bipc {
namespace {

using lower_test::atom_type_of;
using lower_test::code_text;
using lower_test::lower_ok;
using Texts = std::vector<std::string>;

/// An atom type `A` with the given declarations and transitions, instantiated once as `a`.
std::unique_ptr<lower_test::Lowered> lower_atom(const std::string& externs,
                                                const std::string& body) {
  return lower_ok("package t\n" + externs +
                      "  port type P()\n"
                      "  atom type A(int k)\n" +
                      body +
                      "  end\n"
                      "  compound type Top()\n"
                      "    component A a(1)\n"
                      "  end\n"
                      "end\n",
                  "Top()");
}

TEST(LowerCode, ConjunctionShortCircuits) {
  auto lowered = lower_atom("",
                            "    data int x, y\n"
                            "    port P p()\n"
                            "    place S\n"
                            "    initial to S\n"
                            "    on p from S to S provided (x > 0 && y < 10)\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::Transition& t = atom_type_of(s, "a").transitions.at(0);
  EXPECT_EQ(code_text(t.guard, s),
            (Texts{"load atom.data[0]", "push.int 0", "gt.int", "jump_if_false_keep 7",
                   "load atom.data[1]", "push.int 10", "lt.int"}));
  EXPECT_EQ(t.urgency, ir::Urgency::Lazy);
  EXPECT_EQ(t.port, 0u);
}

TEST(LowerCode, DisjunctionShortCircuits) {
  auto lowered = lower_atom("",
                            "    data bool b\n"
                            "    data int x\n"
                            "    port P p()\n"
                            "    place S\n"
                            "    initial to S\n"
                            "    on p from S to S provided (b || !(x == k))\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  EXPECT_EQ(code_text(atom_type_of(s, "a").transitions.at(0).guard, s),
            (Texts{"load atom.data[0]", "jump_if_true_keep 6", "load atom.data[1]",
                   "load atom.param[0]", "eq.int", "not"}));
}

TEST(LowerCode, IntOperandsAreConvertedWhereFloatIsExpected) {
  auto lowered = lower_atom("",
                            "    data int x\n"
                            "    data float f\n"
                            "    port P p()\n"
                            "    place S\n"
                            "    initial to S do { f = x + 1; f = 2; }\n"
                            "    on p from S to S provided (x < f) do { f = x * f; }\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::AtomType& a = atom_type_of(s, "a");
  EXPECT_EQ(code_text(a.initial_action, s),
            (Texts{"load atom.data[0]", "push.int 1", "add.int", "int_to_float",
                   "store atom.data[1]", "push.float 2", "store atom.data[1]"}));
  EXPECT_EQ(code_text(a.transitions[0].guard, s),
            (Texts{"load atom.data[0]", "int_to_float", "load atom.data[1]", "lt.float"}));
  EXPECT_EQ(code_text(a.transitions[0].action, s),
            (Texts{"load atom.data[0]", "int_to_float", "load atom.data[1]", "mul.float",
                   "store atom.data[1]"}));
}

TEST(LowerCode, ConstantsAndConstantSubexpressionsAreFolded) {
  auto lowered = lower_atom("  const data int N = 3\n  const data int M = N * (N + 1)\n",
                            "    data int x\n"
                            "    port P p()\n"
                            "    place S\n"
                            "    initial to S do { x = -N; }\n"
                            "    on p from S to S provided (x < M * 2 && true)\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::AtomType& a = atom_type_of(s, "a");
  EXPECT_EQ(code_text(a.initial_action, s), (Texts{"push.int -3", "store atom.data[0]"}));
  EXPECT_EQ(code_text(a.transitions[0].guard, s),
            (Texts{"load atom.data[0]", "push.int 24", "lt.int", "jump_if_false_keep 5",
                   "push.bool true"}));
}

TEST(LowerCode, IfThenElseAndDiscardedCallResults) {
  auto lowered = lower_atom("  extern function int bump(int)\n  extern function note(string)\n",
                            "    data int x\n"
                            "    port P p()\n"
                            "    place S\n"
                            "    initial to S\n"
                            "    on p from S to S do {\n"
                            "      if (x > 0) then bump(x); note(\"hi\"); else x = bump(1); fi\n"
                            "      note(\"hi\");\n"
                            "    }\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  EXPECT_EQ(
      code_text(atom_type_of(s, "a").transitions.at(0).action, s),
      (Texts{"load atom.data[0]", "push.int 0", "gt.int", "jump_if_false 10", "load atom.data[0]",
             "call bump/1", "pop", "push.string \"hi\"", "call note/1", "jump 13", "push.int 1",
             "call bump/1", "store atom.data[0]", "push.string \"hi\"", "call note/1"}));
  EXPECT_EQ(s.strings, (std::vector<std::string>{"hi"}));  // pooled once
  ASSERT_EQ(s.functions.size(), 2u);
  EXPECT_EQ(s.functions[0].name, "bump");
  EXPECT_FALSE(s.functions[1].result.has_value());
}

TEST(LowerCode, OperatorsOnExternTypesAreCalls) {
  auto lowered = lower_atom(
      "  extern data type Vec as \"std::vector<double>\"\n"
      "  extern operator Vec +(Vec, Vec)\n"
      "  extern operator bool ==(const Vec, const Vec)\n"
      "  extern function float norm(const Vec)\n",
      "    data Vec u, v\n"
      "    data float n\n"
      "    port P p()\n"
      "    place S\n"
      "    initial to S\n"
      "    on p from S to S provided (u == v) do { u = u + v; n = norm(u) + k; }\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::Transition& t = atom_type_of(s, "a").transitions.at(0);
  EXPECT_EQ(code_text(t.guard, s), (Texts{"load atom.data[0]", "load atom.data[1]", "call ==/2"}));
  EXPECT_EQ(code_text(t.action, s),
            (Texts{"load atom.data[0]", "load atom.data[1]", "call +/2", "store atom.data[0]",
                   "load atom.data[0]", "call norm/1", "load atom.param[0]", "int_to_float",
                   "add.float", "store atom.data[2]"}));
  ASSERT_EQ(s.extern_types.size(), 1u);
  EXPECT_EQ(s.extern_types[0].name, "t.Vec");
  EXPECT_EQ(s.extern_types[0].backend_name, "std::vector<double>");
  ASSERT_EQ(s.functions.size(), 3u);
  EXPECT_TRUE(s.functions[0].is_operator);
  EXPECT_EQ(s.functions[0].const_params, (std::vector<bool>{true, true}));
  EXPECT_EQ(s.functions[0].params[0].extern_type, 0u);
}

TEST(LowerCode, ClocksResetAndRates) {
  auto lowered = lower_atom("",
                            "    clock c unit second\n"
                            "    clock d\n"
                            "    port P p()\n"
                            "    place S\n"
                            "    initial to S do { c = 0; d' = 2.5; }\n"
                            "    on p from S to S provided (c >= 3) eager do { c = k; }\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::AtomType& a = atom_type_of(s, "a");
  ASSERT_EQ(a.clocks.size(), 2u);
  EXPECT_EQ(a.clocks[0].unit, ir::TimeUnit::Second);
  EXPECT_EQ(a.clocks[1].unit, ir::TimeUnit::Millisecond);
  EXPECT_EQ(code_text(a.initial_action, s),
            (Texts{"push.float 0", "store clock[0]", "push.float 2.5", "rate clock[1]"}));
  EXPECT_EQ(code_text(a.transitions[0].guard, s),
            (Texts{"load clock[0]", "push.float 3", "ge.float"}));
  EXPECT_EQ(code_text(a.transitions[0].action, s),
            (Texts{"load atom.param[0]", "int_to_float", "store clock[0]"}));
  EXPECT_EQ(a.transitions[0].urgency, ir::Urgency::Eager);
}

TEST(LowerCode, ConnectorTransferCodeUsesPortParameters) {
  auto lowered = lower_ok(
      "package t\n"
      "  extern function int min(int, int)\n"
      "  port type D(int v)\n"
      "  connector type Sel(D p, D q)\n"
      "    data int z\n"
      "    export port D e(z)\n"
      "    define p' q'\n"
      "    on q p provided (p.v != q.v) up { z = min(p.v, q.v); } down { p.v = z; q.v = z; }\n"
      "  end\n"
      "  atom type A()\n"
      "    data int x\n"
      "    export port D o(x)\n"
      "    place S\n"
      "    initial to S\n"
      "    on o from S to S\n"
      "  end\n"
      "  compound type Top()\n"
      "    component A a(), b()\n"
      "    connector Sel sel(a.o, b.o)\n"
      "    export port sel.e as out\n"
      "  end\n"
      "end\n",
      "Top()");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::ConnectorType& sel = s.connector_types.at(0);
  ASSERT_EQ(sel.interactions.size(), 1u);
  const ir::InteractionCode& i = sel.interactions[0];
  EXPECT_EQ(i.ports, (std::vector<ir::Index>{0, 1}));  // sorted
  EXPECT_EQ(code_text(i.guard, s),
            (Texts{"load port[0].param[0]", "load port[1].param[0]", "ne.int"}));
  EXPECT_EQ(code_text(i.up, s), (Texts{"load port[0].param[0]", "load port[1].param[0]",
                                       "call min/2", "store connector.data[0]"}));
  EXPECT_EQ(code_text(i.down, s), (Texts{"load connector.data[0]", "store port[0].param[0]",
                                         "load connector.data[0]", "store port[1].param[0]"}));
  EXPECT_EQ(sel.export_data, (std::vector<ir::Index>{0}));
  EXPECT_EQ(s.compounds[0].exported_ports.at("out"),
            (std::vector<ir::PortRef>{{ir::PortRef::Kind::Connector, 0, 0}}));
}

TEST(LowerCode, StochasticPortsNameTheirDistribution) {
  auto lowered = lower_atom("",
                            "    data float sd\n"
                            "    clock c\n"
                            "    @stochastic(dist=\"normal\", clk=c, param=\"k, sd\")\n"
                            "    export port P p()\n"
                            "    @stochastic(dist=\"uniform\", clk=c, param=\"1,2.5\")\n"
                            "    port P q()\n"
                            "    place S\n"
                            "    initial to S do { sd = 1.5; c = 0; }\n"
                            "    on p from S to S do { c = 0; }\n"
                            "    on q from S to S do { c = 0; }\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::AtomType& a = atom_type_of(s, "a");
  ASSERT_TRUE(a.ports.at(0).stochastic);
  const ir::Stochastic& p = *a.ports[0].stochastic;
  EXPECT_EQ(p.distribution, ir::Distribution::Normal);
  EXPECT_EQ(p.clock, 0u);
  ASSERT_EQ(p.params.size(), 2u);
  EXPECT_EQ(code_text(p.params[0], s), (Texts{"load atom.param[0]", "int_to_float"}));
  EXPECT_EQ(code_text(p.params[1], s), (Texts{"load atom.data[0]"}));
  ASSERT_TRUE(a.ports.at(1).stochastic);
  const ir::Stochastic& q = *a.ports[1].stochastic;
  EXPECT_EQ(q.distribution, ir::Distribution::Uniform);
  EXPECT_EQ(code_text(q.params[0], s), (Texts{"push.float 1"}));
  EXPECT_EQ(code_text(q.params[1], s), (Texts{"push.float 2.5"}));
}

TEST(LowerCode, AtomStructureIsLowered) {
  auto lowered = lower_atom("",
                            "    data int x = 4\n"
                            "    export port P p()\n"
                            "    port P q()\n"
                            "    place S, T, U\n"
                            "    initial to S, T do { x = 0; }\n"
                            "    on p from S, T to U delayable resume (x > 0)\n"
                            "    internal from U to S provided (x == 0)\n"
                            "    on q from U to T\n"
                            "    priority pr p < * provided (x > 1)\n"
                            "    invariant inv at U provided (x < 9)\n");
  ASSERT_TRUE(lowered->system);
  const ir::System& s = *lowered->system;
  const ir::AtomType& a = atom_type_of(s, "a");
  EXPECT_EQ(code_text(a.data.at(0).initial_value, s), (Texts{"push.int 4"}));
  EXPECT_EQ(a.initial_places, (std::vector<ir::Index>{0, 1}));
  ASSERT_EQ(a.interface.size(), 1u);
  EXPECT_EQ(a.interface[0].name, "p");
  EXPECT_EQ(a.interface[0].ports, (std::vector<ir::Index>{0}));
  ASSERT_EQ(a.transitions.size(), 3u);
  EXPECT_EQ(a.transitions[0].from, (std::vector<ir::Index>{0, 1}));
  EXPECT_EQ(a.transitions[0].to, (std::vector<ir::Index>{2}));
  EXPECT_EQ(a.transitions[0].urgency, ir::Urgency::Delayable);
  ASSERT_TRUE(a.transitions[0].resume);
  EXPECT_EQ(a.transitions[1].port, ir::kNone);
  ASSERT_EQ(a.priorities.size(), 1u);
  EXPECT_EQ(a.priorities[0].low, 0u);
  EXPECT_EQ(a.priorities[0].high, ir::kNone);
  ASSERT_EQ(a.invariants.size(), 1u);
  EXPECT_EQ(a.invariants[0].places, (std::vector<ir::Index>{2}));
}

}  // namespace
}  // namespace smcbip::bipc
