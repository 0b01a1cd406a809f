// Tests of compound type checking (components, connectors, priorities, exports, recursive
// instantiation) and of the root instantiation.
#include <gtest/gtest.h>

#include <string>

#include "bipc/bipc.h"
#include "bipc/check/detail/check_context.h"
#include "check_test_util.h"

namespace smcbip::bipc {
namespace {

// Lines 1..31; the compound types of a test start on line 32.
const char* const kPrelude =
    "package t\n"
    "  port type P()\n"
    "  port type Q(int v)\n"
    "  atom type A(int n)\n"
    "    data int x\n"
    "    export data int y\n"
    "    export port P p()\n"
    "    export port P q()\n"
    "    export port Q r(x)\n"
    "    place S\n"
    "    initial to S do { x = 0; y = n; }\n"
    "    on p from S to S\n"
    "    on q from S to S\n"
    "    on r from S to S\n"
    "  end\n"
    "  connector type Rdv(P a, P b)\n"
    "    define a b\n"
    "  end\n"
    "  connector type Brd(P a, P b, P c)\n"
    "    define a' b' c'\n"
    "  end\n"
    "  connector type Up(P a, P b)\n"
    "    export port P e()\n"
    "    define a' b'\n"
    "  end\n"
    "  connector type One(P a)\n"
    "    define a\n"
    "  end\n"
    "  connector type OneQ(Q a)\n"
    "    define a\n"
    "  end\n";
constexpr int kFirstLine = 32;

struct Checked : check_test::Checked {
  bool error(int line, int column, const std::string& phrase) const {
    return has(Severity::Error, line, column, phrase);
  }
  bool error(const std::string& phrase) const { return error(0, 0, phrase); }
  bool warning(const std::string& phrase) const { return has(Severity::Warning, 0, 0, phrase); }
  std::size_t count(const std::string& phrase) const {
    std::size_t n = 0;
    for (const Diagnostic& d : diags.all()) n += d.message.find(phrase) != std::string::npos;
    return n;
  }
  const ast::Package& package() const { return *model.packages.front(); }
  const ast::CompoundTypeDecl& compound(std::size_t i = 0) const {
    return package().compound_types.at(i);
  }
};

/// Parses the prelude followed by `compounds` and checks the package.
std::unique_ptr<Checked> check_compounds(const std::string& compounds) {
  auto c = std::make_unique<Checked>();
  check_test::check_into(*c, std::string(kPrelude) + compounds + "end\n");
  return c;
}

int line(int offset) { return kFirstLine + offset; }

// ---------------------------------------------------------------------------------------------
// Parameters and components

TEST(CompoundParameters, MustBeNative) {
  auto c = check_compounds("  compound type K(P z, int n, int n)\n    component A a(n)\n  end\n");
  EXPECT_TRUE(c->error(line(0), 19, "native type")) << c->text();
  EXPECT_TRUE(c->error(line(0), 35, "duplicate parameter 'n'")) << c->text();
}

TEST(CompoundComponents, ResolvesAtomAndCompoundTypes) {
  auto c = check_compounds(
      "  compound type Inner()\n    component A a(1)\n    export port a.p as ip\n  end\n"
      "  compound type K()\n    component A a(1)\n    component Inner i()\n"
      "    connector Rdv r(a.p, i.ip)\n  end\n");
  ASSERT_TRUE(c->ok) << c->text();
  const ast::CompoundTypeDecl& k = c->compound(1);
  EXPECT_EQ(k.components[0].atom_type, &c->package().atom_types[0]);
  EXPECT_EQ(k.components[1].compound_type, &c->compound(0));
  EXPECT_EQ(k.connectors[0].connector_type, &c->package().connector_types[0]);
}

TEST(CompoundComponents, UnknownTypeReportedOncePerDeclaration) {
  auto c = check_compounds(
      "  compound type K()\n    component Nope a(), b()\n"
      "    component Rdv r()\n  end\n");
  EXPECT_TRUE(c->error(line(1), 15, "unknown component type 'Nope'")) << c->text();
  EXPECT_EQ(c->count("unknown component type"), 1u) << c->text();
  EXPECT_TRUE(c->error(line(2), 15, "'Rdv' is a connector type")) << c->text();
}

TEST(CompoundComponents, ArgumentCountAndTypes) {
  auto c = check_compounds(
      "  compound type K(int m, bool f)\n"
      "    component A a(), b(m), d(f), e(1, 2)\n  end\n");
  EXPECT_TRUE(c->error(line(1), 17, "component 'a' of type 'A' expects 1 argument, got 0"))
      << c->text();
  EXPECT_FALSE(c->error(line(1), 22, "")) << c->text();  // `m` is an int parameter
  EXPECT_TRUE(c->error(line(1), 30, "must be of type 'int'")) << c->text();
  EXPECT_TRUE(c->error(line(1), 34, "expects 1 argument, got 2")) << c->text();
}

TEST(CompoundComponents, ArgumentMayNotReadComponentData) {
  auto c = check_compounds("  compound type K()\n    component A a(1), b(a.y)\n  end\n");
  EXPECT_FALSE(c->ok) << c->text();
}

TEST(CompoundNames, ComponentsAndConnectorsShareOneNamespace) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1), a(2)\n"
      "    connector One a(a.p)\n    connector One k(a.q), k(a.q)\n  end\n");
  EXPECT_TRUE(c->error(line(1), 23, "duplicate component 'a'")) << c->text();
  EXPECT_TRUE(c->error(line(2), 19, "names both a component and a connector")) << c->text();
  EXPECT_TRUE(c->error(line(3), 27, "duplicate connector 'k'")) << c->text();
}

TEST(CompoundNames, PriorityMayShareAComponentName) {
  // The reference suite's conflict_component_prio and conflict_type_instance models.
  auto c = check_compounds(
      "  compound type Bug()\n    component A low(1)\n"
      "    export port low.p as p\n  end\n"
      "  compound type K()\n    component A One(1), b(2)\n"
      "    component Bug prio()\n"
      "    connector One sa(One.p), sb(b.p), sc(b.p)\n"
      "    priority prio sa:One.p < sb:b.p\n  end\n");
  EXPECT_TRUE(c->ok) << c->text();
}

// ---------------------------------------------------------------------------------------------
// Recursive instantiation

TEST(CompoundRecursion, DirectSelfInstantiation) {
  auto c = check_compounds("  compound type K()\n    component K k()\n  end\n");
  EXPECT_TRUE(c->error(line(1), 15, "recursive instantiation: K contains K")) << c->text();
}

TEST(CompoundRecursion, CycleReportedOnceWhereItCloses) {
  auto c = check_compounds(
      "  compound type K1()\n    component K2 k()\n    export port k.x as x\n"
      "  end\n"
      "  compound type K2()\n    component K3 k()\n    export port k.x as x\n"
      "  end\n"
      "  compound type K3()\n    component K1 k()\n    export port k.x as x\n"
      "  end\n");
  EXPECT_TRUE(c->error(line(9), 15,
                       "recursive instantiation: K1 contains K2 contains K3 "
                       "contains K1"))
      << c->text();
  EXPECT_EQ(c->count("recursive instantiation"), 1u) << c->text();
}

TEST(CompoundRecursion, RootContainingACycleIsRejected) {
  auto c = check_compounds(
      "  compound type K()\n    component K k()\n  end\n"
      "  compound type Top()\n    component K k()\n  end\n");
  ast::ComponentDecl root;
  root.type.parts.push_back({"Top", {}});
  EXPECT_FALSE(check_root(c->model, root, c->diags));
  EXPECT_TRUE(c->error("never ends")) << c->text();
}

// ---------------------------------------------------------------------------------------------
// Connectors

TEST(CompoundConnectors, TypeAndArity) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1), b(2)\n"
      "    connector Nope n(a.p)\n    connector Rdv r(a.p)\n"
      "    connector A w(a.p)\n  end\n");
  EXPECT_TRUE(c->error(line(2), 15, "unknown connector type 'Nope'")) << c->text();
  EXPECT_TRUE(c->error(line(3), 19, "connector 'r' of type 'Rdv' expects 2 ports, got 1"))
      << c->text();
  EXPECT_TRUE(c->error(line(4), 15, "'A' is a component type")) << c->text();
}

TEST(CompoundConnectors, PortTypeMustMatchExactly) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1)\n"
      "    connector OneQ ok(a.r)\n    connector One bad(a.r)\n  end\n");
  EXPECT_TRUE(c->error(line(3), 23, "expected a port of type 'P', got 'Q'")) << c->text();
  EXPECT_EQ(c->count("expected a port of type"), 1u) << c->text();
}

TEST(CompoundConnectors, ArgumentsNameInterfacePorts) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1)\n"
      "    connector One r(nobody.p), s(a.x), u(r.e)\n  end\n");
  EXPECT_TRUE(c->error(line(2), 21, "unknown component or connector 'nobody'")) << c->text();
  EXPECT_TRUE(c->error(line(2), 36, "has no exported port 'x'")) << c->text();
  EXPECT_TRUE(c->error(line(2), 44, "exports no port")) << c->text();
}

TEST(CompoundConnectors, ConstantArgumentsAreNamedAsConstants) {
  auto c = check_compounds(
      "  const data int K = 1\n"
      "  compound type T(int n)\n    component A a(1), b(1)\n"
      "    connector Rdv r(K, n)\n    connector Rdv s(a.p, b.p)\n    connector Rdv u(a, b)\n"
      "  end\n");
  EXPECT_TRUE(c->error(line(3), 21, "'K' is a constant data, a connector binds ports"))
      << c->text();
  EXPECT_TRUE(c->error(line(3), 24, "'n' is a constant parameter, a connector binds ports"))
      << c->text();
  EXPECT_TRUE(c->error(line(5), 21, "expected 'component.port' or 'connector.port', got 'a'"))
      << c->text();
  EXPECT_EQ(c->diags.error_count(), 4U) << c->text();
}

TEST(CompoundConnectors, HierarchicalConnectorsBindExportedPorts) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1), b(2), d(3)\n"
      "    connector Up low(a.p, b.p)\n    connector Rdv top(low.e, d.p)\n"
      "    connector Rdv bad(low.x, d.q)\n  end\n");
  EXPECT_TRUE(c->error(line(4), 27, "exports port 'e', not 'x'")) << c->text();
  EXPECT_EQ(c->diags.error_count(), 1u) << c->text();
}

TEST(CompoundConnectors, ComponentBoundTwice) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1), b(2), d(3)\n"
      "    connector Rdv same(a.p, a.p), two(a.p, a.q)\n"
      "    connector Up l1(a.p, b.p), l2(b.q, d.p)\n"
      "    connector Rdv top(l1.e, l2.e), twice(l1.e, l1.e)\n  end\n");
  EXPECT_TRUE(c->error(line(2), 29, "connector 'same' binds component 'a' more than once"))
      << c->text();
  EXPECT_TRUE(c->error(line(2), 44, "connector 'two' binds component 'a' more than once"))
      << c->text();
  EXPECT_TRUE(c->error(line(4), 29, "connector 'top' binds component 'b' more than once"))
      << c->text();
  EXPECT_TRUE(c->error(line(4), 48, "connector 'twice' binds connector 'l1' more than once"))
      << c->text();
}

TEST(CompoundConnectors, BindingCycle) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1), b(2)\n"
      "    connector Up c1(c2.e, a.p), c2(c1.e, b.p), c3(c3.e, a.q)\n  end\n");
  EXPECT_TRUE(c->error("connectors bind each other in a cycle: c1 binds c2 binds c1")) << c->text();
  EXPECT_TRUE(c->error("connector 'c3' binds its own exported port")) << c->text();
}

// ---------------------------------------------------------------------------------------------
// Priorities

const char* const kThreeConnectors =
    "  compound type K()\n"
    "    component A a(1), b(2), d(3)\n"
    "    connector Brd brd(a.p, b.p, d.p)\n"
    "    connector Rdv rdv(a.q, b.q)\n"
    "    connector Up low(d.q, a.r)\n";  // a.r: wrong port type, reported once

std::unique_ptr<Checked> check_priorities(const std::string& priorities) {
  return check_compounds(std::string(kThreeConnectors) + priorities + "  end\n");
}

TEST(CompoundPriorities, ResolvesConnectors) {
  auto c = check_priorities("    priority ok brd:* < rdv:a.q,b.q\n    priority w brd:a.p < *:*\n");
  EXPECT_EQ(c->diags.error_count(), 1u) << c->text();
  const ast::CompoundPriorityDecl& ok = c->compound().priorities[0];
  EXPECT_EQ(ok.low.connector_index, 0);
  EXPECT_EQ(ok.high.connector_index, 1);
  EXPECT_EQ(c->compound().priorities[1].high.connector_index, -1);
}

TEST(CompoundPriorities, NamesAndWildcards) {
  auto c = check_priorities(
      "    priority p1 nope:* < rdv:*\n    priority p2 *:* < *:*\n"
      "    priority p1 rdv:* < brd:*\n");
  EXPECT_TRUE(c->error(line(5), 17, "unknown connector 'nope' in priority")) << c->text();
  EXPECT_TRUE(c->error(line(6), 14, "'*:* < *:*' is not allowed")) << c->text();
  EXPECT_TRUE(c->error(line(7), 14, "duplicate priority 'p1'")) << c->text();
}

TEST(CompoundPriorities, PortListsAreInteractionsOfTheConnector) {
  auto c = check_priorities(
      "    priority p1 rdv:a.q < brd:*\n"
      "    priority p2 rdv:a.p,b.q < brd:*\n"
      "    priority p3 brd:a.p,a.p < rdv:*\n");
  EXPECT_TRUE(c->error(line(5), 17, "'rdv:a.q' is not an interaction of connector 'rdv'"))
      << c->text();
  EXPECT_TRUE(c->error(line(6), 21, "'a.p' is not a port of connector 'rdv'")) << c->text();
  EXPECT_TRUE(c->error(line(7), 25, "'a.p' appears twice")) << c->text();
}

TEST(CompoundPriorities, OnlyTopLevelConnectors) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1), b(2), d(3)\n"
      "    connector Up low(a.p, b.p)\n    connector Rdv top(low.e, d.p)\n"
      "    priority bad low:* < top:*\n  end\n");
  EXPECT_TRUE(c->error(line(4), 18,
                       "priority must name a top-level connector: 'low' is bound "
                       "by 'top'"))
      << c->text();
}

TEST(CompoundPriorities, GuardReadsExportedDataAndParameters) {
  auto c = check_compounds(
      "  compound type K(int m)\n    component A a(1), b(2)\n"
      "    connector One pa(a.p), pb(b.p)\n"
      "    priority ok pa:* < pb:* provided (a.y < m)\n"
      "    priority bad pb:* < pa:* provided (a.x < m)\n  end\n");
  EXPECT_FALSE(c->ok);
  EXPECT_TRUE(c->error(line(4), 0, "")) << c->text();
  EXPECT_FALSE(c->error(line(3), 0, "")) << c->text();
}

TEST(CompoundPriorities, ContradictsMaximalProgress) {
  // Verimag's compoundPriorityContradictMaximalProgress: an error, guarded or not.
  auto c = check_priorities(
      "    priority c1 brd:a.p,b.p < brd:b.p\n"
      "    priority c2 brd:a.p,b.p,d.p < brd:d.p,b.p provided (false)\n");
  EXPECT_TRUE(c->error(line(5), 14,
                       "priority contradicts maximal progress: 'brd:b.p' is "
                       "contained in 'brd:a.p,b.p'"))
      << c->text();
  EXPECT_TRUE(c->error(line(6), 14, "contradicts maximal progress")) << c->text();
}

TEST(CompoundPriorities, DuplicatesMaximalProgressIsAWarning) {
  auto c = check_priorities("    priority d1 brd:b.p < brd:a.p,b.p\n");
  EXPECT_EQ(c->diags.error_count(), 1u) << c->text();  // the prelude's a.r only
  EXPECT_TRUE(c->warning("priority duplicates maximal progress")) << c->text();
}

TEST(CompoundPriorities, RuleRelatingAnInteractionToItself) {
  auto c =
      check_priorities("    priority s1 rdv:* < rdv:a.q,b.q\n    priority s2 brd:a.p < brd:a.p\n");
  EXPECT_TRUE(c->error(line(5), 14, "lower than itself")) << c->text();
  EXPECT_TRUE(c->error(line(6), 14, "lower than itself")) << c->text();
}

TEST(CompoundPriorities, UnguardedCycleIsAnError) {
  auto c = check_priorities(
      "    priority p1 brd:a.p,b.p < rdv:*\n    priority p2 rdv:* < brd:a.p\n"
      "    priority p3 brd:a.p < *:*\n");
  EXPECT_TRUE(c->error(line(5), 14,
                       "priorities form a cycle: p1 (brd:a.p,b.p < rdv:*) -> p2 "
                       "(rdv:* < brd:a.p) -> p1"))
      << c->text();
  EXPECT_EQ(c->count("cycle"), 1u) << c->text();
}

TEST(CompoundPriorities, WildcardCycle) {
  // `*:*` stands for every other top-level connector: brd < rdv (through `*:*`) < brd.
  auto c = check_priorities("    priority p1 brd:* < *:*\n    priority p2 rdv:* < brd:*\n");
  EXPECT_TRUE(c->error(line(5), 14, "priorities form a cycle")) << c->text();
}

TEST(CompoundPriorities, GuardedCycleIsOnlyAWarning) {
  // The reference engine reports such cycles at run time (priority_rules_cycle*.bip, exit 3).
  auto c = check_priorities(
      "    priority p1 brd:* < rdv:* provided (true)\n"
      "    priority p2 rdv:* < brd:*\n");
  EXPECT_EQ(c->diags.error_count(), 1u) << c->text();
  EXPECT_TRUE(c->warning("priorities form a cycle when their guards hold")) << c->text();
}

TEST(CompoundPriorities, WildcardsOverASingleConnectorFormNoCycle) {
  // The reference suite's priority_rules_no_cycle model.
  auto c = check_compounds(
      "  compound type K()\n    component A a(1), b(2)\n"
      "    connector Rdv rdv(a.p, b.p)\n"
      "    priority p1 rdv:a.p,b.p < *:*\n    priority p2 rdv:* < *:*\n"
      "    priority p3 *:* < rdv:a.p,b.p\n    priority p4 *:* < rdv:*\n"
      "  end\n");
  EXPECT_TRUE(c->ok) << c->text();
  EXPECT_FALSE(c->warning("cycle")) << c->text();
}

// ---------------------------------------------------------------------------------------------
// Exports

TEST(CompoundExports, MergedPorts) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1), b(2)\n"
      "    connector Up up(a.p, b.p)\n"
      "    export port a.q, b.q, up.e as ok\n"
      "    export port a.p, b.r as mixed\n"
      "    export port a.r, a.r as twice\n  end\n");
  EXPECT_TRUE(c->error(line(4), 22, "merged ports must have the same type")) << c->text();
  EXPECT_TRUE(c->error(line(5), 22, "'a.r' is referenced twice")) << c->text();
  EXPECT_EQ(c->diags.error_count(), 2u) << c->text();
}

TEST(CompoundExports, Data) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1)\n"
      "    connector One con(a.p)\n"
      "    export data a.y as y\n    export data a.x as x\n"
      "    export data con.y as z\n    export port a.q as y\n  end\n");
  EXPECT_TRUE(c->error(line(4), 19, "has no exported data 'x'")) << c->text();
  EXPECT_TRUE(c->error(line(5), 17, "'con' is a connector")) << c->text();
  EXPECT_TRUE(c->error(line(6), 24, "duplicate export 'y'")) << c->text();
}

TEST(CompoundExports, UnconnectedPortsAreWarnings) {
  auto c = check_compounds(
      "  compound type K()\n    component A a(1)\n"
      "    connector Up up(a.p, a.q)\n  end\n");
  EXPECT_TRUE(
      c->warning("component 'a' has ports that no connector binds and no export names: "
                 "'r'"))
      << c->text();
  EXPECT_TRUE(c->warning("exported port 'e' of connector 'up' is neither bound")) << c->text();
}

TEST(CompoundExports, SuppressWarningSilencesUnconnectedPorts) {
  auto on_elements = check_compounds(
      "  compound type K()\n    @SuppressWarning(unboundcomponentport)\n    component A a(1)\n"
      "    @SuppressWarning(unboundcomponentport)\n    component A b(1)\n"
      "    @SuppressWarning(unboundconnectorport)\n    connector Up up(a.p, b.p)\n  end\n");
  EXPECT_TRUE(on_elements->diags.all().empty()) << on_elements->text();
  auto on_compound = check_compounds(
      "  @SuppressWarning(unboundcomponentport, unboundconnectorport)\n  compound type K()\n"
      "    component A a(1), b(1)\n    connector Up up(a.p, b.p)\n  end\n");
  EXPECT_TRUE(on_compound->diags.all().empty()) << on_compound->text();
  auto other_name = check_compounds(
      "  compound type K()\n    @SuppressWarning(nondeterminism)\n    component A a(1), b(1)\n"
      "    connector Up up(a.p, b.p)\n  end\n");
  EXPECT_EQ(other_name->count("has ports that no connector binds"), 2U) << other_name->text();
  EXPECT_TRUE(other_name->warning("exported port 'e' of connector 'up' is neither bound"))
      << other_name->text();
}

// ---------------------------------------------------------------------------------------------
// Roots

ast::ComponentDecl parsed_root(Checked& c, const std::string& text) {
  std::optional<ast::ComponentDecl> root = parse_root(text, c.model.files.add("<root>"), c.diags);
  EXPECT_TRUE(root.has_value()) << c.text();
  return root ? std::move(*root) : ast::ComponentDecl{};
}

const char* const kRootModel =
    "  const data int Size = 3\n"
    "  compound type Top(int n, bool f)\n    component A a(n)\n  end\n"
    "  compound type Plain()\n    component Top t(1, true)\n  end\n";

TEST(CompoundRoot, ResolvesAndChecksArguments) {
  auto c = check_compounds(kRootModel);
  ASSERT_TRUE(c->ok) << c->text();
  ast::ComponentDecl good = parsed_root(*c, "t.Top(3, false)");
  EXPECT_TRUE(check_root(c->model, good, c->diags)) << c->text();
  EXPECT_EQ(good.compound_type, &c->compound(0));
  ast::ComponentDecl few = parsed_root(*c, "Top(3)");
  EXPECT_FALSE(check_root(c->model, few, c->diags));
  EXPECT_TRUE(c->error("root type 'Top' expects 2 arguments, got 1")) << c->text();
  ast::ComponentDecl typed = parsed_root(*c, "Top(true, false)");
  EXPECT_FALSE(check_root(c->model, typed, c->diags));
  EXPECT_TRUE(c->error("must be of type 'int'")) << c->text();
}

TEST(CompoundRoot, WrongTypes) {
  auto c = check_compounds(kRootModel);
  ast::ComponentDecl unknown = parsed_root(*c, "Nowhere()");
  EXPECT_FALSE(check_root(c->model, unknown, c->diags));
  EXPECT_TRUE(c->error("unknown root type 'Nowhere'")) << c->text();
  ast::ComponentDecl atom = parsed_root(*c, "A(1)");
  EXPECT_FALSE(check_root(c->model, atom, c->diags));
  EXPECT_TRUE(c->error("root type 'A' is an atom type")) << c->text();
}

TEST(CompoundRoot, ArgumentsAreConstants) {
  auto c = check_compounds(kRootModel);
  ast::ComponentDecl constant = parsed_root(*c, "Top(Size, true)");
  EXPECT_TRUE(check_root(c->model, constant, c->diags)) << c->text();
  ast::ComponentDecl root = parsed_root(*c, "Top(n, true)");
  EXPECT_FALSE(check_root(c->model, root, c->diags));
}

TEST(DefaultRoot, TheOnlyTypeNothingInstantiates) {
  auto c = check_compounds(kRootModel);
  EXPECT_EQ(default_root(c->model), std::optional<std::string>("Plain()"));
}

TEST(DefaultRoot, NoneWhenAmbiguousOrParameterised) {
  auto two = check_compounds(
      "  compound type K1()\n    component A a(1)\n  end\n"
      "  compound type K2()\n    component A a(1)\n  end\n");
  EXPECT_EQ(default_root(two->model), std::nullopt);
  auto params = check_compounds("  compound type K(int n)\n    component A a(n)\n  end\n");
  EXPECT_EQ(default_root(params->model), std::nullopt);
}

// ---------------------------------------------------------------------------------------------
// Partial trees (as left by syntax errors) must not crash the check.

TEST(CompoundPartialTrees, EmptyNamesAndMissingParts) {
  auto c = check_compounds("  compound type K()\n    component A a(1)\n  end\n");
  ast::CompoundTypeDecl& k = c->model.packages.front()->compound_types.front();
  k.components.emplace_back();                  // no type, no name
  k.components.back().args.push_back(nullptr);  // a missing argument
  k.connectors.emplace_back();                  // no type, no ports
  k.connectors.back().ports.emplace_back();     // an empty reference
  k.priorities.emplace_back();                  // `*:* < *:*` with no name
  k.port_exports.emplace_back();                // nothing exported
  k.data_exports.emplace_back();
  Diagnostics diags;
  const detail::Symbols symbols(c->model);
  detail::check_compound_type(k, c->package(), symbols, diags);
  EXPECT_TRUE(diags.has_errors());
}

}  // namespace
}  // namespace smcbip::bipc
