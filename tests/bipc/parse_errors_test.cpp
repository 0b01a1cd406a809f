// Tests of the BIP2 parser's diagnostics: messages and positions, recovery, limits, robustness.
#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <string>
#include <vector>

#include "bipc/bipc.h"

namespace smcbip::bipc {
namespace {

// Each error as `line:col: message`.
std::vector<std::string> errors_of(const std::string& text) {
  Diagnostics diags;
  parse_package(text, 0, diags);
  std::vector<std::string> errors;
  for (const Diagnostic& d : diags.all()) {
    if (d.severity != Severity::Error) continue;
    errors.push_back(std::to_string(d.location.line) + ":" + std::to_string(d.location.column) +
                     ": " + d.message);
  }
  return errors;
}

std::string first_error(const std::string& text) {
  std::vector<std::string> errors = errors_of(text);
  return errors.empty() ? "<no error>" : errors.front();
}

TEST(ParseErrors, MissingEndOfAtom) {
  EXPECT_EQ(first_error("package p\n  atom type A()\n    place s\n    initial to s\n"),
            "5:1: expected 'end' to close atom type 'A', got end of file");
}

TEST(ParseErrors, BadPlaceList) {
  EXPECT_EQ(first_error("package p\n  atom type A()\n    place s,, t\n"
                        "    initial to s\n  end\nend\n"),
            "3:13: expected a place name, got ','");
}

TEST(ParseErrors, GuardNeedsParentheses) {
  EXPECT_EQ(first_error("package p atom type A() place s initial to s\n"
                        "  on p from s to s provided x > 0\nend end"),
            "2:29: expected '(' after 'provided', got 'x'");
}

TEST(ParseErrors, MissingPlaceDeclaration) {
  EXPECT_EQ(first_error("package p atom type A() data int x initial to s end end"),
            "1:36: expected a data, port or clock declaration or 'place' in atom type 'A', got "
            "'initial'");
}

TEST(ParseErrors, MisplacedDeclarationsGetAHint) {
  EXPECT_EQ(first_error("package p atom type A() place s initial to s data int x end end"),
            "1:46: data, port and clock declarations must come before 'place' in atom type 'A'");
  EXPECT_EQ(first_error("package p atom type A() place s initial to s\n"
                        "  priority q a < b on a from s to s end end"),
            "2:20: transitions must come before priorities and invariants in atom type 'A'");
  EXPECT_EQ(first_error("package p compound type K() component A a()\n"
                        "  export port a.p as p component A b() end end"),
            "2:24: component and connector declarations must come before priorities and "
            "exports in compound type 'K'");
}

TEST(ParseErrors, ConnectorAndCompoundErrors) {
  EXPECT_EQ(first_error("package p connector type C(P p) define end end"),
            "1:40: expected a port name or '(' after 'define', got 'end'");
  EXPECT_EQ(first_error("package p connector type C(P p) define p resume later end end"),
            "1:49: expected 'sync' or 'async' after 'resume', got 'later'");
  EXPECT_EQ(first_error("package p compound type K() end end"),
            "1:29: expected a component or connector declaration in compound type 'K', got "
            "'end'");
  EXPECT_EQ(first_error("package p compound type K() component A a()\n"
                        "  priority q c1 < c2:* end end"),
            "2:17: expected ':' after connector name 'c1', got '<'");
}

TEST(ParseErrors, PackageLevelErrors) {
  EXPECT_EQ(errors_of(""),
            std::vector<std::string>{
                "1:1: expected 'package' at the start of the file, got end of file"});
  EXPECT_EQ(first_error("atom type A() end"),
            "1:1: expected 'package' at the start of the file, got 'atom'");
  EXPECT_EQ(first_error("package p\n  foo\nend"),
            "2:3: expected a declaration (const data, extern, port type, atom type, connector "
            "type or compound type) or 'end' to close package 'p', got 'foo'");
  EXPECT_EQ(first_error("package p\n  port type P()\n"),
            "3:1: expected 'end' to close package 'p', got end of file");
  EXPECT_EQ(first_error("package p end\nport type P()"),
            "2:1: expected end of file after the 'end' of package 'p', got 'port'");
  EXPECT_EQ(first_error("package p extern port P p() end"),
            "1:18: expected 'data type', 'function' or 'operator' after 'extern' (extern ports "
            "are declared in atom types), got 'port'");
  EXPECT_EQ(first_error("package p extern operator int *(int) end"),
            "1:31: operator '*' is not a unary operator; declare two operands");
  EXPECT_EQ(first_error("package p @cpp(src=3) end"),
            "1:20: expected an annotation value (a name, true, false or a string), got '3'");
}

TEST(ParseErrors, Bip1IsRejectedClearly) {
  std::vector<std::string> errors = errors_of("model M\n  atomic type A\n  end\nend\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0],
            "1:1: BIP1 syntax is not supported ('model'); this is BIP2: write 'package NAME ... "
            "end'");
  errors = errors_of("package p\n  port type P()\n  atomic type A\n  end\nend\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0],
            "3:3: BIP1 syntax is not supported ('atomic type'); this is BIP2: use 'atom type'");
}

TEST(ParseErrors, LexicalErrorsAreNotReportedTwice) {
  std::vector<std::string> errors = errors_of("package p\n  # comment\nend\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0], "2:3: unexpected character '#'");
}

TEST(ParseErrors, InternalTransitionsHaveNoUrgency) {
  EXPECT_EQ(first_error("package p atom type A() place s initial to s\n"
                        "  internal from s to s eager end end"),
            "2:24: an internal transition has no urgency");
}

TEST(ParseErrors, RecoveryReportsIndependentErrors) {
  const std::string text = R"(package p
  port type P()
  atom type A()
    place s,
    initial to s
  end
  atom type B()
    place s
    initial to s
    on p from s to s provided x
  end
  atom type Good()
    place s
    initial to s
  end
  connector type C(P p)
    define p
    on p up { x = ; }
  end
  compound type K()
    component Good g()
  end
end
)";
  Diagnostics diags;
  auto package = parse_package(text, 0, diags);
  std::vector<std::string> errors = errors_of(text);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0], "5:5: expected a place name, got 'initial'");
  EXPECT_EQ(errors[1], "10:31: expected '(' after 'provided', got 'x'");
  EXPECT_EQ(errors[2], "18:19: expected an expression, got ';'");
  // The declarations around the broken ones are kept.
  EXPECT_EQ(package->port_types.size(), 1u);
  ASSERT_EQ(package->atom_types.size(), 1u);
  EXPECT_EQ(package->atom_types[0].name.text, "Good");
  EXPECT_EQ(package->compound_types.size(), 1u);
}

TEST(ParseErrors, RecoveryStopsAtAnAnnotatedDeclaration) {
  std::vector<std::string> errors = errors_of(R"(package p
  atom type A()
    place s s
  @cpp(include="x.hpp")
  atom type B()
    place s initial to
  end
end
)");
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0],
            "3:13: expected 'initial' (the initial transition) in atom type 'A', got 's'");
  EXPECT_EQ(errors[1], "7:3: expected a place name, got 'end'");
}

TEST(ParseErrors, ErrorCountIsBounded) {
  std::string text = "package p\n";
  for (int i = 0; i < 500; ++i) text += "  port type P(int)\n";
  text += "end\n";
  Diagnostics diags;
  parse_package(text, 0, diags);
  EXPECT_EQ(diags.error_count(), 50u);
  EXPECT_EQ(diags.all().back().severity, Severity::Note);

  Diagnostics binary;
  std::string noise(10000, '\x01');
  parse_package("package p " + noise, 0, binary);
  EXPECT_EQ(binary.error_count(), 50u);
}

// A note pointing at an earlier line (the first of two clashing declarations) used to be sorted
// away from the error it explains.
TEST(ParseErrors, SortingKeepsNotesAfterTheirDiagnostic) {
  Diagnostics diags;
  diags.error({0, 9, 5}, "second");
  diags.note({0, 2, 5}, "first is here");
  diags.warning({0, 4, 1}, "middle");
  diags.note({0, 1, 1}, "the middle's note");
  diags.sort_by_location();
  ASSERT_EQ(diags.all().size(), 4u);
  EXPECT_EQ(diags.all()[0].message, "middle");
  EXPECT_EQ(diags.all()[1].message, "the middle's note");
  EXPECT_EQ(diags.all()[2].message, "second");
  EXPECT_EQ(diags.all()[3].message, "first is here");
}

TEST(ParseErrors, DeepNestingIsReportedNotCrashed) {
  const std::string parens(10000, '(');
  std::vector<std::string> errors = errors_of("package p const data int K = " + parens + "1 end");
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors[0], "1:286: nesting too deep (more than 256 levels)");

  errors = errors_of("package p const data int K = " + std::string(10000, '-') + "1 end");
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors[0].find("nesting too deep"), std::string::npos);

  std::string calls;
  for (int i = 0; i < 10000; ++i) calls += "f(";
  errors = errors_of("package p const data int K = " + calls + " end");
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors[0].find("nesting too deep"), std::string::npos);

  std::string ifs;
  for (int i = 0; i < 10000; ++i) ifs += "if (x) then ";
  errors = errors_of("package p atom type A() place s initial to s do {" + ifs + "} end end");
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors[0].find("nesting too deep"), std::string::npos);

  errors = errors_of("package p connector type C(P p) define " + parens + " end end");
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors[0].find("nesting too deep"), std::string::npos);
}

TEST(ParseErrors, LongChainsAreBoundedOrBalanced) {
  std::string sum = "1";
  for (int i = 0; i < 5000; ++i) sum += " + 1";
  std::vector<std::string> errors = errors_of("package p const data int K = " + sum + " end");
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors[0].find("expression nested too deeply (more than 1024 levels)"),
            std::string::npos);

  // Associative chains are balanced: a generated 100,000-way disjunction is fine.
  std::string disjunction = "x == 0";
  for (int i = 1; i < 100000; ++i) disjunction += " || x == " + std::to_string(i);
  EXPECT_TRUE(errors_of("package p const data bool B = " + disjunction + " end").empty());
}

TEST(ParseErrors, TruncatedAndMutatedInputsNeverCrash) {
  const std::string model = R"(@cpp(include="a.h")
package p
  use q
  const data int K = 3
  extern function int f(const int)
  port type P(int x)
  atom type A(int n)
    data int x = -n * (2 + K)
    export port P p(x)
    clock c unit second
    place s, t
    initial to s do { x = f(1); }
    on p from s to t provided (x > 0 && c <= 2) eager do { if (x == 1) then x = 2; else x' = 1.0; fi }
    internal from t to s
    priority pr p < *
    invariant i at t provided (c < 3)
  end
  connector type C(P a, P b)
    data int d
    define a' (b)'
    on a b provided (a.x != b.x) up { d = a.x; } down { b.x = d; }
  end
  compound type K()
    component A a(1), b(2)
    connector C c(a.p, b.p)
    priority pr c:a.p < *:*
    export port a.p as e
  end
end
)";
  for (std::size_t length = 0; length <= model.size(); ++length) {
    Diagnostics diags;
    parse_package(model.substr(0, length), 0, diags);
    if (length < model.size() - 1) {
      EXPECT_TRUE(diags.has_errors()) << "prefix of length " << length;
    }
  }
  std::mt19937 random(20240601);
  const std::string alphabet = "(){}'.,;:@=<>!&|+-*/%^~\"\\ \nabc0123456789";
  for (int round = 0; round < 2000; ++round) {
    std::string mutated = model;
    for (int edit = 0; edit < 4; ++edit) {
      std::size_t at = random() % mutated.size();
      mutated[at] = alphabet[random() % alphabet.size()];
    }
    Diagnostics diags;
    parse_package(mutated, 0, diags);
  }
}

TEST(ParseErrors, LargeGeneratedModelParsesInLinearTime) {
  std::string text = "package big\n  port type P()\n  connector type R(P a, P b) define a b end\n";
  constexpr int kAtoms = 10000;
  for (int i = 0; i < kAtoms; ++i) {
    std::string n = std::to_string(i);
    text += "  atom type A" + n +
            "(int k)\n    data int x = k\n    export port P p(), q()\n"
            "    place s, t\n    initial to s do { x = 0; }\n"
            "    on p from s to t provided (x < 10) do { x = x + 1; }\n"
            "    on q from t to s\n  end\n";
  }
  text += "  compound type Top()\n";
  for (int i = 0; i < kAtoms; ++i) {
    text += "    component A" + std::to_string(i) + " c" + std::to_string(i) + "(" +
            std::to_string(i) + ")\n";
  }
  for (int i = 0; i + 1 < kAtoms; ++i) {
    text += "    connector R r" + std::to_string(i) + "(c" + std::to_string(i) + ".p, c" +
            std::to_string(i + 1) + ".q)\n";
  }
  text += "  end\nend\n";
  Diagnostics diags;
  auto start = std::chrono::steady_clock::now();
  auto package = parse_package(text, 0, diags);
  auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_FALSE(diags.has_errors());
  EXPECT_EQ(package->atom_types.size(), static_cast<std::size_t>(kAtoms));
  EXPECT_EQ(package->compound_types.at(0).connectors.size(), static_cast<std::size_t>(kAtoms - 1));
  // Generous bound (debug builds, sanitizers, a busy machine); a quadratic parser takes minutes.
  EXPECT_LT(seconds, 30.0);
}

}  // namespace
}  // namespace smcbip::bipc
