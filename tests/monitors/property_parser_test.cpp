// The property parser: golden files (tests/monitors/properties/{valid,invalid}/*.mtl, each with
// the .expected text beside it) and the laws of the normalised text.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "monitors/monitors.h"

namespace smcbip::monitors {
namespace {

namespace fs = std::filesystem;

const fs::path kGoldenDir = fs::path(SMCBIP_SOURCE_DIR) / "tests/monitors/properties";

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The declarations then the queries, normalised, one per line.
std::string normalised(const PropertyFile& file) {
  std::string out;
  for (const Declaration& d : file.declarations) out += to_string(d) + "\n";
  for (const Query& q : file.queries) out += to_string(q) + "\n";
  return out;
}

/// The golden files of one folder, by name.
std::vector<std::string> golden_names(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kGoldenDir / folder)) {
    if (entry.path().extension() == ".mtl") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

/// What the golden file `folder/name.mtl` gives: its normalised text, or its diagnostics (the
/// file named without its folder, so the expectation does not depend on where the tree is).
std::string golden_output(const std::string& folder, const std::string& name) {
  const ParsedProperties parsed =
      parse_properties(read(kGoldenDir / folder / (name + ".mtl")), name + ".mtl");
  return parsed.ok() ? normalised(parsed.file) : parsed.diagnostics.format(parsed.sources);
}

class ValidProperties : public ::testing::TestWithParam<std::string> {};
class InvalidProperties : public ::testing::TestWithParam<std::string> {};

TEST_P(ValidProperties, ParseToTheirNormalisedText) {
  const ParsedProperties parsed =
      parse_properties(read(kGoldenDir / "valid" / (GetParam() + ".mtl")), GetParam() + ".mtl");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  EXPECT_EQ(normalised(parsed.file), read(kGoldenDir / "valid" / (GetParam() + ".expected")));
}

// The normalised text reads back as itself: it loses nothing the parser keeps.
TEST_P(ValidProperties, NormalisedTextIsAFixedPoint) {
  const std::string once = golden_output("valid", GetParam());
  const ParsedProperties again = parse_properties(once, "normalised.mtl");
  ASSERT_TRUE(again.ok()) << once << again.diagnostics.format(again.sources);
  EXPECT_EQ(normalised(again.file), once);
}

TEST_P(InvalidProperties, ReportTheirErrors) {
  EXPECT_EQ(golden_output("invalid", GetParam()),
            read(kGoldenDir / "invalid" / (GetParam() + ".expected")));
}

INSTANTIATE_TEST_SUITE_P(Golden, ValidProperties, ::testing::ValuesIn(golden_names("valid")),
                         [](const auto& info) { return info.param; });
INSTANTIATE_TEST_SUITE_P(Golden, InvalidProperties, ::testing::ValuesIn(golden_names("invalid")),
                         [](const auto& info) { return info.param; });

std::string formula_text(const std::string& formula) {
  const ParsedProperties parsed = parse_properties("P=? [ " + formula + " ]", "f.mtl");
  if (!parsed.ok()) return parsed.diagnostics.format(parsed.sources);
  return to_string(*parsed.file.queries.at(0).formula);
}

TEST(PropertyParser, BindsOperatorsAsPrismAndUppaalDo) {
  // The echo is fully parenthesised: it shows how each formula was read.
  EXPECT_EQ(formula_text("F die.s == 7 && die.d == 1"), "F (die.s == 7 && die.d == 1)");
  EXPECT_EQ(formula_text("a U b && c"), "a U (b && c)");
  EXPECT_EQ(formula_text("a && b U c"), "(a && b) U c");
  EXPECT_EQ(formula_text("F a U b"), "(F a) U b");
  EXPECT_EQ(formula_text("<> a && b"), "F (a && b)");
  EXPECT_EQ(formula_text("G (req -> F ack && ok)"), "G (req -> (F (ack && ok)))");
  EXPECT_EQ(formula_text("!a && b"), "(!a) && b");
  EXPECT_EQ(formula_text("!F a && b"), "!(F (a && b))");
  EXPECT_EQ(formula_text("a || b && c"), "a || (b && c)");
  EXPECT_EQ(formula_text("(a || b) && c"), "(a || b) && c");
  EXPECT_EQ(formula_text("a -> b -> c"), "a -> (b -> c)");
  EXPECT_EQ(formula_text("(a -> b) -> c"), "(a -> b) -> c");
  EXPECT_EQ(formula_text("a <-> b -> c"), "a <-> (b -> c)");
  EXPECT_EQ(formula_text("a -> b U c"), "(a -> b) U c");
  EXPECT_EQ(formula_text("a U[0,5] b U[1,2] c"), "a U[0,5] (b U[1,2] c)");
  EXPECT_EQ(formula_text("(a U[0,5] b) U[1,2] c"), "(a U[0,5] b) U[1,2] c");
  EXPECT_EQ(formula_text("a R b || c"), "a R (b || c)");
  EXPECT_EQ(formula_text("F[0,10] (a U b)"), "F[0,10] (a U b)");
  EXPECT_EQ(formula_text("X a && X b"), "X (a && (X b))");
  EXPECT_EQ(formula_text("F G a"), "F (G a)");
  EXPECT_EQ(formula_text("x + 1 * 2 > y - z - w"), "x + 1 * 2 > y - z - w");
  EXPECT_EQ(formula_text("(x + 1) * 2 > y - (z - w)"), "(x + 1) * 2 > y - (z - w)");
  EXPECT_EQ(formula_text("--x == -(-x)"), "--x == --x");
}

TEST(PropertyParser, ReadsTheSpellingsOfPrismAndUppaal) {
  EXPECT_EQ(formula_text("F s=7 & d=1"), "F (s == 7 && d == 1)");
  EXPECT_EQ(formula_text("a | b & !c"), "a || (b && (!c))");
  EXPECT_EQ(formula_text("a => b <=> c"), "a -> (b <-> c)");
  EXPECT_EQ(formula_text("s != 7"), "s != 7");
  EXPECT_EQ(formula_text("F \"deadlock\""), "F deadlock");
  EXPECT_EQ(formula_text("\"init\" -> x = 0"), "init -> x == 0");
  EXPECT_EQ(formula_text("a and not b or c"), "(a && (!b)) || c");
  EXPECT_EQ(formula_text("a imply b"), "a -> b");
  EXPECT_EQ(formula_text("<> deadlock"), "F deadlock");
  EXPECT_EQ(formula_text("[] !timelock"), "G (!timelock)");
  EXPECT_EQ(formula_text("F[0,10] time >= 5"), "F[0,10] (time >= 5)");
  const ParsedProperties constants =
      parse_properties("const int N = 3;\nconst double h = 0.5;\nP=? [ F x > N ]", "c.mtl");
  EXPECT_TRUE(constants.ok()) << constants.diagnostics.format(constants.sources);
}

TEST(PropertyParser, ReadsTheAlternativeSpellings) {
  EXPECT_EQ(formula_text("<>[0,10] a"), "F[0,10] a");
  EXPECT_EQ(formula_text("[][0,10] a"), "G[0,10] a");
  EXPECT_EQ(formula_text("F<=10 a"), "F[0,10] a");
  EXPECT_EQ(formula_text("F[<=10] a"), "F[0,10] a");
  EXPECT_EQ(formula_text("F<=#10 a"), "F{10} a");
  EXPECT_EQ(formula_text("F[#<=10] a"), "F{10} a");
  EXPECT_EQ(formula_text("G{3} (x > 1)"), "G{3} (x > 1)");
}

std::string query_text(const std::string& text) {
  const ParsedProperties parsed = parse_properties(text, "q.mtl");
  if (!parsed.ok()) return parsed.diagnostics.format(parsed.sources);
  return to_string(parsed.file.queries.at(0));
}

TEST(PropertyParser, ReadsPathQuantifiersAndExpectations) {
  EXPECT_EQ(query_text("A[] !deadlock"), "A[] !deadlock");
  EXPECT_EQ(query_text("A[] x <= 3 && y >= 0"), "A[] x <= 3 && y >= 0");
  EXPECT_EQ(query_text("E<> x == 3"), "E<> x == 3");
  EXPECT_EQ(query_text("E[<=10; 100](last: x)"), "E[<=10; 100](last: x)");
  EXPECT_EQ(query_text("E[<=10; 100](int: x + y)"), "E[<=10; 100](int: x + y)");
  EXPECT_EQ(query_text("E[#<=10; 100](count: fired(c))"), "E[#<=10; 100](count: fired(c))");
  EXPECT_NE(query_text("E[<=10; 100](count: x)").find("fired(connector) after count:"),
            std::string::npos);
  EXPECT_NE(query_text("A[] F x").find("A[] takes a state predicate"), std::string::npos);
}

TEST(PropertyParser, NamesTheSupportedFormOfWhatItRefuses) {
  EXPECT_NE(query_text("P=? [ a W b ]").find("(a U b) || G a"), std::string::npos);
  EXPECT_NE(query_text("P=? [ a --> b ]").find("G (a -> F b)"), std::string::npos);
  EXPECT_NE(query_text("A<> x").find("P>=1 [ F phi ]"), std::string::npos);
  EXPECT_NE(query_text("E[] x").find("P>0 [ G phi ]"), std::string::npos);
  EXPECT_NE(query_text("R=? [ C<=10 ]").find("E[<=T; N](int: e)"), std::string::npos);
  EXPECT_NE(query_text("S=? [ x ]").find("not supported"), std::string::npos);
  EXPECT_NE(query_text("P=? [ F \"goal\" ]").find("unknown label \"goal\""), std::string::npos);
}

TEST(PropertyParser, RefusesNestingBeyondItsLimit) {
  const std::string deep = std::string(1000, '(') + "a" + std::string(1000, ')');
  const ParsedProperties parsed = parse_properties("P=? [ " + deep + " ]", "deep.mtl");
  ASSERT_FALSE(parsed.ok());
  EXPECT_NE(parsed.diagnostics.format(parsed.sources).find("nested too deeply"), std::string::npos);
}

TEST(PropertyParser, LongChainsOfOperatorsAreRefusedOrPrintedWithoutExhaustingTheStack) {
  // A regression: 20,000 operands of && overflowed the stack when the query was printed.
  std::string chain = "a";
  for (int i = 0; i < 20000; ++i) chain += " && a";
  const ParsedProperties refused = parse_properties("P=? [ " + chain + " ]", "chain.mtl");
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.diagnostics.format(refused.sources).find("nested too deeply"),
            std::string::npos);
  std::string sum = "x";
  for (int i = 0; i < 900; ++i) sum += " + x";
  EXPECT_EQ(formula_text(sum + " > 0"), sum + " > 0");
}

TEST(PropertyParser, StopsReadingAFileOfNothingButErrors) {
  // A regression: 1 MB of NUL bytes gave a million error lines.
  const ParsedProperties parsed = parse_properties(std::string(1000000, '\0'), "nul.mtl");
  ASSERT_FALSE(parsed.ok());
  EXPECT_EQ(parsed.diagnostics.error_count(), 21u);
  EXPECT_NE(parsed.diagnostics.format(parsed.sources).find("too many errors"), std::string::npos);
}

TEST(PropertyParser, TakesParametersInEveryWrittenForm) {
  for (const char* given : {"t=5", "t=5,10,20", "t={5,10,20}", "t=0:20:5"}) {
    const ParsedProperties parsed = parse_properties("P=? [ F[0,t] a ]", "p.mtl", {given});
    ASSERT_TRUE(parsed.ok()) << given << "\n" << parsed.diagnostics.format(parsed.sources);
    ASSERT_EQ(parsed.file.declarations.size(), 1u);
  }
  const ParsedProperties unused = parse_properties("P=? [ F[0,5] a ]", "p.mtl", {"t=5"});
  EXPECT_NE(unused.diagnostics.format(unused.sources).find("not used by any query"),
            std::string::npos);
  const ParsedProperties huge = parse_properties("param t = 0:1:1e-300\nP=? [ F[0,t] a ]", "p.mtl");
  EXPECT_NE(huge.diagnostics.format(huge.sources).find("at most 100000"), std::string::npos);
}

TEST(PropertyParser, ReportsAnUnreadableFile) {
  const ParsedProperties parsed = load_properties("/nonexistent/property.mtl");
  ASSERT_FALSE(parsed.ok());
  EXPECT_EQ(parsed.diagnostics.format(parsed.sources),
            "/nonexistent/property.mtl:0:0: error: cannot read the property file\n");
}

TEST(PropertyParser, TakesParametersFromTheCommandLine) {
  const std::string text =
      "param t = 0:100:10\nconst c = 3\nP=? [ F[0,t] (x > c) ]\nP=? [ F[0,u] y ]\n";
  const ParsedProperties parsed = parse_properties(text, "f.mtl", {"t={5, 7}", "u=1:3:1"});
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  const auto values = parameter_values(parsed.file);
  EXPECT_EQ(values.at("t"), (std::vector<double>{5, 7}));
  EXPECT_EQ(values.at("u"), (std::vector<double>{1, 2, 3}));
  // The file's t keeps its place: it is still declared before the constant.
  EXPECT_EQ(parsed.file.declarations[1].name, "t");
  EXPECT_EQ(parsed.file.declarations[1].at.line, 1u);
  EXPECT_EQ(parsed.file.declarations.size(), 3u);
}

TEST(PropertyParser, GivenParametersReplaceConstants) {
  const ParsedProperties parsed =
      parse_properties("const c = 3\nP=? [ F[0,c] y ]\n", "f.mtl", {"c={1,2}"});
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  EXPECT_EQ(parameter_values(parsed.file).at("c"), (std::vector<double>{1, 2}));
  EXPECT_TRUE(constant_values(parsed.file).empty());
}

TEST(PropertyParser, ReportsBadCommandLineParameters) {
  const auto error = [](const std::string& given) {
    const ParsedProperties parsed = parse_properties("P=? [ F[0,t] y ]\n", "f.mtl", {given});
    EXPECT_FALSE(parsed.ok()) << given;
    return parsed.diagnostics.format(parsed.sources);
  };
  EXPECT_NE(error("t=0:10").find("--param:1:7: error: expected ':' between the range's stop"),
            std::string::npos);
  EXPECT_NE(error("t=5:1:1").find("stops (1) before it starts (5)"), std::string::npos);
  EXPECT_NE(error("t=0:10:0").find("must be > 0"), std::string::npos);
  EXPECT_NE(error("").find("--param:"), std::string::npos);
  EXPECT_NE(error("t={1}; P=? [ y ]").find("expected one parameter"), std::string::npos);
  // Without the parameter, t is unknown.
  const ParsedProperties unknown = parse_properties("P=? [ F[0,t] y ]\n", "f.mtl");
  EXPECT_NE(unknown.diagnostics.format(unknown.sources).find("unknown constant or parameter 't'"),
            std::string::npos);
}

}  // namespace
}  // namespace smcbip::monitors
