// Tests of the BIP2 parser: each construct of Bip2.g parses into the expected AST shape.
#include <gtest/gtest.h>

#include <string>

#include "bipc/bipc.h"

namespace smcbip::bipc {
namespace {

std::unique_ptr<ast::Package> parse_ok(const std::string& text) {
  Diagnostics diags;
  std::unique_ptr<ast::Package> package = parse_package(text, 0, diags);
  EXPECT_TRUE(diags.all().empty()) << diags.format(SourceFiles{});
  return package;
}

std::string param(const ast::Annotation& annotation, std::size_t i) {
  const ast::AnnotationParam& p = annotation.params.at(i);
  return p.key.text + "=" + p.value.value_or("<none>");
}

TEST(ParseParser, PackageHeaderUsesAndAnnotations) {
  auto package = parse_ok(
      "@cpp(src=\"a.cpp,b.cpp\", include=\"a.hpp\")\n"
      "@tool(flag, on=true, off=false, mode=fast)\n"
      "package a.b\n"
      "  use x.y\n"
      "  use z\n"
      "end\n");
  EXPECT_EQ(package->name.text(), "a.b");
  EXPECT_EQ(package->loc.line, 3u);
  ASSERT_EQ(package->uses.size(), 2u);
  EXPECT_EQ(package->uses[0].text(), "x.y");
  EXPECT_EQ(package->uses[1].loc().line, 5u);
  EXPECT_EQ(package->uses[1].loc().column, 7u);
  ASSERT_EQ(package->annotations.size(), 2u);
  EXPECT_EQ(package->annotations[0].name.text, "cpp");
  EXPECT_EQ(param(package->annotations[0], 0), "src=a.cpp,b.cpp");
  EXPECT_EQ(param(package->annotations[0], 1), "include=a.hpp");
  EXPECT_EQ(package->annotations[0].loc.line, 1u);
  EXPECT_EQ(param(package->annotations[1], 0), "flag=<none>");
  EXPECT_EQ(param(package->annotations[1], 1), "on=true");
  EXPECT_EQ(param(package->annotations[1], 2), "off=false");
  EXPECT_EQ(param(package->annotations[1], 3), "mode=fast");
}

TEST(ParseParser, ConstantsAndExterns) {
  auto package = parse_ok(
      "package p\n"
      "  const data int K = 3, L = K + 1\n"
      "  data const float F = 2.5\n"
      "  extern data type T refine U, int as \"std::list<int>\"\n"
      "  extern data type V\n"
      "  extern function int f(T, const int n)\n"
      "  extern function g()\n"
      "  extern function const q.R h(const q.S)\n"
      "  extern operator T +(T a, T b)\n"
      "  extern operator bool !(const T)\n"
      "end\n");
  ASSERT_EQ(package->consts.size(), 3u);
  EXPECT_EQ(package->consts[0].name.text, "K");
  EXPECT_TRUE(package->consts[0].type.is_const);
  EXPECT_EQ(package->consts[0].type.name.text(), "int");
  EXPECT_EQ(package->consts[1].name.text, "L");
  EXPECT_EQ(package->consts[1].value->kind, ast::Expr::Kind::Binary);
  EXPECT_EQ(package->consts[2].type.name.text(), "float");
  EXPECT_DOUBLE_EQ(package->consts[2].value->float_value, 2.5);

  ASSERT_EQ(package->extern_types.size(), 2u);
  const ast::ExternTypeDecl& t = package->extern_types[0];
  EXPECT_EQ(t.name.text, "T");
  ASSERT_EQ(t.refines.size(), 2u);
  EXPECT_EQ(t.refines[0].name.text(), "U");
  EXPECT_EQ(t.refines[1].name.text(), "int");
  EXPECT_EQ(t.backend_name, "std::list<int>");
  EXPECT_FALSE(package->extern_types[1].backend_name.has_value());

  ASSERT_EQ(package->extern_functions.size(), 5u);
  const ast::ExternFunctionDecl& f = package->extern_functions[0];
  EXPECT_FALSE(f.is_operator);
  EXPECT_EQ(f.name.text, "f");
  ASSERT_TRUE(f.result.has_value());
  EXPECT_EQ(f.result->name.text(), "int");
  ASSERT_EQ(f.params.size(), 2u);
  EXPECT_EQ(f.params[0].type.name.text(), "T");
  EXPECT_EQ(f.params[0].name.text, "");
  EXPECT_TRUE(f.params[1].type.is_const);
  EXPECT_EQ(f.params[1].name.text, "n");
  EXPECT_FALSE(package->extern_functions[1].result.has_value());
  EXPECT_TRUE(package->extern_functions[1].params.empty());
  const ast::ExternFunctionDecl& h = package->extern_functions[2];
  EXPECT_TRUE(h.result->is_const);
  EXPECT_EQ(h.result->name.text(), "q.R");
  EXPECT_EQ(h.params[0].type.name.text(), "q.S");
  const ast::ExternFunctionDecl& plus = package->extern_functions[3];
  EXPECT_TRUE(plus.is_operator);
  EXPECT_EQ(plus.name.text, "+");
  EXPECT_EQ(plus.params.size(), 2u);
  EXPECT_EQ(package->extern_functions[4].name.text, "!");
  EXPECT_EQ(package->extern_functions[4].params.size(), 1u);
}

TEST(ParseParser, PortType) {
  auto package = parse_ok("package p port type P(int x, const bool b) port type Q() end");
  ASSERT_EQ(package->port_types.size(), 2u);
  EXPECT_EQ(package->port_types[0].name.text, "P");
  ASSERT_EQ(package->port_types[0].params.size(), 2u);
  EXPECT_EQ(package->port_types[0].params[1].name.text, "b");
  EXPECT_TRUE(package->port_types[0].params[1].type.is_const);
  EXPECT_TRUE(package->port_types[1].params.empty());
}

const char* const kAtom = R"(package p
  port type P(int x)
  @doc(text="an atom")
  atom type A(int n, float f)
    data int x = 1, y
    export data bool b
    @stochastic(dist="normal", clk=c, param="10,2")
    export port P p(x)
    port P q(y), r(x)
    export port P s(x), t(y) as st
    extern port P e(x) as "Ev" remember
    extern port P e2(y) error
    clock c, d unit millisecond
    clock k
    place L1, L2, L3
    initial to L1, L2 do { x = 0; } resume (x > 1)
    @fault
    on p from L1, L2 to L3 provided (x > 0) eager do { x = x + 1; } resume (c < 3)
    on q from L3 to L1 delayable
    on r from L1 to L2 lazy resume
    internal from L2 to L1 provided (y == 0) do { y = 2; }
    priority pr1 p < q provided (x > 2)
    invariant inv1 at L1, L2 provided (c <= 5)
    priority pr2 * < r
    invariant inv2 from L3 provided (d < 1)
    priority pr3 p < *
  end
end
)";

TEST(ParseParser, AtomType) {
  auto package = parse_ok(kAtom);
  ASSERT_EQ(package->atom_types.size(), 1u);
  const ast::AtomTypeDecl& atom = package->atom_types[0];
  EXPECT_EQ(atom.name.text, "A");
  EXPECT_EQ(atom.loc.line, 4u);
  ASSERT_EQ(atom.annotations.size(), 1u);
  EXPECT_EQ(atom.annotations[0].name.text, "doc");
  ASSERT_EQ(atom.params.size(), 2u);
  EXPECT_EQ(atom.params[1].type.name.text(), "float");

  ASSERT_EQ(atom.data.size(), 3u);
  EXPECT_EQ(atom.data[0].name.text, "x");
  EXPECT_EQ(atom.data[0].initial_value->int_value, 1);
  EXPECT_EQ(atom.data[1].initial_value, nullptr);
  EXPECT_TRUE(atom.data[2].exported);
  EXPECT_EQ(atom.data[2].type.name.text(), "bool");

  ASSERT_EQ(atom.ports.size(), 7u);
  const ast::PortDecl& p = atom.ports[0];
  EXPECT_TRUE(p.exported);
  EXPECT_EQ(p.type.text(), "P");
  ASSERT_EQ(p.bound_data.size(), 1u);
  EXPECT_EQ(p.bound_data[0].text, "x");
  ASSERT_EQ(p.annotations.size(), 1u);
  EXPECT_EQ(param(p.annotations[0], 0), "dist=normal");
  EXPECT_EQ(param(p.annotations[0], 1), "clk=c");
  EXPECT_EQ(param(p.annotations[0], 2), "param=10,2");
  EXPECT_FALSE(atom.ports[1].exported);
  EXPECT_EQ(atom.ports[2].name.text, "r");
  EXPECT_EQ(atom.ports[3].merged_as->text, "st");
  EXPECT_EQ(atom.ports[4].merged_as->text, "st");
  EXPECT_TRUE(atom.ports[4].exported);
  EXPECT_TRUE(atom.ports[5].is_extern);
  EXPECT_EQ(atom.ports[5].backend_name, "Ev");
  EXPECT_EQ(atom.ports[5].policy, ast::ExternPolicy::Remember);
  EXPECT_EQ(atom.ports[6].policy, ast::ExternPolicy::Error);
  EXPECT_FALSE(atom.ports[6].backend_name.has_value());

  ASSERT_EQ(atom.clocks.size(), 3u);
  EXPECT_EQ(atom.clocks[1].name.text, "d");
  EXPECT_EQ(atom.clocks[1].unit, ast::TimeUnit::Millisecond);
  EXPECT_FALSE(atom.clocks[2].unit.has_value());

  ASSERT_EQ(atom.places.size(), 3u);
  EXPECT_EQ(atom.places[2].text, "L3");
  ASSERT_EQ(atom.initial.to.size(), 2u);
  EXPECT_EQ(atom.initial.action.size(), 1u);
  ASSERT_TRUE(atom.initial.resume.has_value());
  EXPECT_NE(atom.initial.resume->guard, nullptr);

  ASSERT_EQ(atom.transitions.size(), 4u);
  const ast::Transition& t0 = atom.transitions[0];
  EXPECT_EQ(t0.port->text, "p");
  EXPECT_EQ(t0.from.size(), 2u);
  EXPECT_EQ(t0.to[0].text, "L3");
  EXPECT_NE(t0.guard, nullptr);
  EXPECT_EQ(t0.urgency, ast::Urgency::Eager);
  EXPECT_TRUE(t0.has_action);
  EXPECT_EQ(t0.action.size(), 1u);
  ASSERT_TRUE(t0.resume.has_value());
  EXPECT_NE(t0.resume->guard, nullptr);
  ASSERT_EQ(t0.annotations.size(), 1u);
  EXPECT_EQ(t0.annotations[0].name.text, "fault");
  EXPECT_EQ(t0.loc.line, 18u);
  EXPECT_EQ(atom.transitions[1].urgency, ast::Urgency::Delayable);
  EXPECT_FALSE(atom.transitions[1].has_action);
  EXPECT_EQ(atom.transitions[2].urgency, ast::Urgency::Lazy);
  ASSERT_TRUE(atom.transitions[2].resume.has_value());
  EXPECT_EQ(atom.transitions[2].resume->guard, nullptr);
  const ast::Transition& internal = atom.transitions[3];
  EXPECT_FALSE(internal.port.has_value());
  EXPECT_FALSE(internal.urgency.has_value());
  EXPECT_TRUE(internal.has_action);

  ASSERT_EQ(atom.priorities.size(), 3u);
  EXPECT_EQ(atom.priorities[0].name.text, "pr1");
  EXPECT_EQ(atom.priorities[0].low->text, "p");
  EXPECT_EQ(atom.priorities[0].high->text, "q");
  EXPECT_NE(atom.priorities[0].guard, nullptr);
  EXPECT_FALSE(atom.priorities[1].low.has_value());
  EXPECT_EQ(atom.priorities[1].low_loc.column, 18u);
  EXPECT_EQ(atom.priorities[1].high->text, "r");
  EXPECT_FALSE(atom.priorities[2].high.has_value());
  ASSERT_EQ(atom.invariants.size(), 2u);
  EXPECT_TRUE(atom.invariants[0].at);
  EXPECT_EQ(atom.invariants[0].places.size(), 2u);
  EXPECT_FALSE(atom.invariants[1].at);
  EXPECT_EQ(atom.invariants[1].places[0].text, "L3");
}

TEST(ParseParser, ConnectorType) {
  auto package = parse_ok(R"(package p
  port type P(int x)
  connector type C(P p, P q, p2.P r, P s)
    data int d, e
    @doc
    export port P ep(d)
    define p' (q r)' s
    resume sync
    on p q provided (p.x < q.x) up { d = p.x; } down { p.x = d; q.x = d; }
    @prio(level=high)
    on p
    on p r s down { }
  end
  connector type D(P a, P b)
    define a b
    resume async
  end
end
)");
  ASSERT_EQ(package->connector_types.size(), 2u);
  const ast::ConnectorTypeDecl& c = package->connector_types[0];
  EXPECT_EQ(c.name.text, "C");
  ASSERT_EQ(c.ports.size(), 4u);
  EXPECT_EQ(c.ports[2].type.text(), "p2.P");
  EXPECT_EQ(c.ports[2].name.text, "r");
  ASSERT_EQ(c.data.size(), 2u);
  ASSERT_TRUE(c.export_port.has_value());
  EXPECT_EQ(c.export_port->name.text, "ep");
  EXPECT_EQ(c.export_port->bound_data[0].text, "d");
  EXPECT_EQ(c.export_port->annotations.size(), 1u);
  ASSERT_EQ(c.define.size(), 3u);
  EXPECT_EQ(c.define[0].port->text, "p");
  EXPECT_TRUE(c.define[0].trigger);
  EXPECT_FALSE(c.define[1].port.has_value());
  EXPECT_TRUE(c.define[1].trigger);
  ASSERT_EQ(c.define[1].children.size(), 2u);
  EXPECT_EQ(c.define[1].children[1].port->text, "r");
  EXPECT_FALSE(c.define[1].children[1].trigger);
  EXPECT_FALSE(c.define[2].trigger);
  EXPECT_EQ(c.define_loc.line, 7u);
  EXPECT_EQ(c.resume, ast::ConnectorResume::Sync);
  ASSERT_EQ(c.interactions.size(), 3u);
  const ast::InteractionDecl& i0 = c.interactions[0];
  EXPECT_EQ(i0.ports.size(), 2u);
  EXPECT_NE(i0.guard, nullptr);
  EXPECT_TRUE(i0.has_up);
  EXPECT_TRUE(i0.has_down);
  EXPECT_EQ(i0.up.size(), 1u);
  EXPECT_EQ(i0.down.size(), 2u);
  EXPECT_EQ(c.interactions[1].annotations.size(), 1u);
  EXPECT_FALSE(c.interactions[1].has_up);
  EXPECT_TRUE(c.interactions[2].has_down);
  EXPECT_TRUE(c.interactions[2].down.empty());
  EXPECT_EQ(package->connector_types[1].resume, ast::ConnectorResume::Async);
  EXPECT_FALSE(package->connector_types[1].export_port.has_value());
}

TEST(ParseParser, CompoundType) {
  auto package = parse_ok(R"(package p
  compound type K(int n)
    component A a(n, 2), b(3, 4)
    @doc
    connector C c1(a.p, b.q)
    component q.B z()
    connector C c2(c1.ep, z.r), c3(a.p)
    priority pr1 c1:a.p, b.q < c2:* provided (a.x > 1)
    priority pr2 *:* < c3:*
    export port a.p, b.p as ep
    @doc
    export data a.x as ax
    export port z.r as zr
  end
end
)");
  ASSERT_EQ(package->compound_types.size(), 1u);
  const ast::CompoundTypeDecl& k = package->compound_types[0];
  EXPECT_EQ(k.params.size(), 1u);
  ASSERT_EQ(k.components.size(), 3u);
  EXPECT_EQ(k.components[0].type.text(), "A");
  EXPECT_EQ(k.components[0].name.text, "a");
  EXPECT_EQ(k.components[0].args.size(), 2u);
  EXPECT_EQ(k.components[1].name.text, "b");
  EXPECT_EQ(k.components[2].type.text(), "q.B");
  EXPECT_TRUE(k.components[2].args.empty());
  ASSERT_EQ(k.connectors.size(), 3u);
  EXPECT_EQ(k.connectors[0].annotations.size(), 1u);
  EXPECT_EQ(k.connectors[0].ports[1].text(), "b.q");
  EXPECT_EQ(k.connectors[1].ports[0].text(), "c1.ep");
  EXPECT_EQ(k.connectors[2].name.text, "c3");
  ASSERT_EQ(k.priorities.size(), 2u);
  const ast::CompoundPriorityDecl& pr1 = k.priorities[0];
  EXPECT_EQ(pr1.low.connector->text, "c1");
  EXPECT_FALSE(pr1.low.all_ports);
  ASSERT_EQ(pr1.low.ports.size(), 2u);
  EXPECT_EQ(pr1.low.ports[1].text(), "b.q");
  EXPECT_EQ(pr1.high.connector->text, "c2");
  EXPECT_TRUE(pr1.high.all_ports);
  EXPECT_NE(pr1.guard, nullptr);
  EXPECT_FALSE(k.priorities[1].low.connector.has_value());
  EXPECT_TRUE(k.priorities[1].high.all_ports);
  ASSERT_EQ(k.port_exports.size(), 2u);
  EXPECT_EQ(k.port_exports[0].ports.size(), 2u);
  EXPECT_EQ(k.port_exports[0].name.text, "ep");
  EXPECT_EQ(k.port_exports[1].name.text, "zr");
  ASSERT_EQ(k.data_exports.size(), 1u);
  EXPECT_EQ(k.data_exports[0].data.text(), "a.x");
  EXPECT_EQ(k.data_exports[0].name.text, "ax");
  EXPECT_EQ(k.data_exports[0].annotations.size(), 1u);
}

TEST(ParseParser, ContextualKeywordsServeAsNames) {
  auto package = parse_ok(R"(package p
  port type error(int second)
  atom type up(int day)
    data int down, sync, hour, unit, lazy
    export port error async(down), at(sync)
    clock minute unit second
    place eager, remember
    initial to eager do { down = day + hour; minute = 0; }
    on async from eager to remember provided (second.x < 3) eager
    on at from remember to eager
    invariant at at eager provided (minute < 2)
  end
  connector type as(error up, error down)
    define up' down
    on up down up { } down { }
    on down
  end
end
)");
  const ast::AtomTypeDecl& atom = package->atom_types.at(0);
  EXPECT_EQ(atom.name.text, "up");
  EXPECT_EQ(atom.data.size(), 5u);
  EXPECT_EQ(atom.ports[1].name.text, "at");
  EXPECT_EQ(atom.clocks[0].unit, ast::TimeUnit::Second);
  EXPECT_EQ(atom.transitions[0].urgency, ast::Urgency::Eager);
  EXPECT_EQ(atom.invariants[0].name.text, "at");
  EXPECT_EQ(atom.invariants[0].places[0].text, "eager");
  const ast::ConnectorTypeDecl& c = package->connector_types.at(0);
  ASSERT_EQ(c.interactions.size(), 2u);
  ASSERT_EQ(c.interactions[0].ports.size(), 2u);
  EXPECT_EQ(c.interactions[0].ports[1].text, "down");
  EXPECT_TRUE(c.interactions[0].has_up);
  EXPECT_TRUE(c.interactions[0].has_down);
}

TEST(ParseParser, DeclarationsInAnyOrder) {
  auto package = parse_ok(R"(package p
  compound type K() component A a() end
  atom type A() place s initial to s end
  port type P()
  connector type C(P p) define p end
  const data int N = 2
  extern function f()
end
)");
  EXPECT_EQ(package->compound_types.size(), 1u);
  EXPECT_EQ(package->atom_types.size(), 1u);
  EXPECT_EQ(package->port_types.size(), 1u);
  EXPECT_EQ(package->connector_types.size(), 1u);
  EXPECT_EQ(package->consts.size(), 1u);
  EXPECT_EQ(package->extern_functions.size(), 1u);
}

TEST(ParseParser, RootInstantiation) {
  Diagnostics diags;
  std::optional<ast::ComponentDecl> root = parse_root("pkg.Top(3, true, -x)", 0, diags);
  EXPECT_FALSE(diags.has_errors());
  ASSERT_TRUE(root.has_value());
  EXPECT_EQ(root->type.text(), "pkg.Top");
  ASSERT_EQ(root->args.size(), 3u);
  EXPECT_EQ(root->args[0]->int_value, 3);
  EXPECT_TRUE(root->args[1]->bool_value);
  EXPECT_EQ(root->args[2]->kind, ast::Expr::Kind::Unary);

  std::optional<ast::ComponentDecl> simple = parse_root("Syst()", 0, diags);
  ASSERT_TRUE(simple.has_value());
  EXPECT_TRUE(simple->args.empty());
  EXPECT_FALSE(diags.has_errors());
}

TEST(ParseParser, RootInstantiationErrors) {
  Diagnostics diags;
  EXPECT_FALSE(parse_root("Syst", 0, diags).has_value());
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.all()[0].message, "expected '(' after the component type name, got end of file");
  Diagnostics more;
  EXPECT_FALSE(parse_root("Syst() x", 0, more).has_value());
  EXPECT_EQ(more.all().at(0).message, "expected end of the root instantiation, got 'x'");
  EXPECT_EQ(more.all().at(0).location.column, 8u);
}

}  // namespace
}  // namespace smcbip::bipc
