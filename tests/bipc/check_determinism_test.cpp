// Tests of the non-determinism an atom's text shows: transitions on one port, or internal ones,
// from nested sets of places (errors without guards, warnings with guards).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "check_test_util.h"
#include "shared_data.h"

namespace smcbip::bipc {
namespace {

using check_test::check_text;
using check_test::Checked;

/// An atom with data x, clock t, ports p and q, places L, M, N (L and M marked); `body` starts
/// at line 9 of the package.
std::string atom_with(const std::string& body, const std::string& atom_annotations = "") {
  return "package t\n"
         "  port type P()\n" +
         atom_annotations +
         "  atom type A()\n"
         "    data int x\n"
         "    clock t unit millisecond\n"
         "    export port P p(), q()\n"
         "    place L, M, N\n"
         "    initial to L, M do { x = 0; }\n" +
         body + "  end\nend\n";
}

std::size_t count(const Checked& c, Severity severity) {
  std::size_t n = 0;
  for (const Diagnostic& d : c.diags.all()) n += d.severity == severity;
  return n;
}

TEST(CheckDeterminism, UnguardedTransitionsOnOnePortFromOnePlaceAreAnError) {
  const Checked c =
      check_text(atom_with("    on p from L to N\n"
                           "    on p from L to M\n"));
  EXPECT_TRUE(c.has(10, 5,
                    "non-determinism: transitions on port 'p' from L (here) and from L "
                    "(line 9)"))
      << c.text();
  EXPECT_TRUE(c.has(Severity::Note, 9, 5, "the other transition is here")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
}

TEST(CheckDeterminism, UnguardedInternalTransitionsFromOnePlaceAreAnError) {
  const Checked c =
      check_text(atom_with("    internal from N to L\n"
                           "    internal from N to M\n"));
  EXPECT_TRUE(c.has(10, 5, "non-determinism: internal transitions from N")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
}

TEST(CheckDeterminism, NestedSourcePlacesAreAnErrorAtEachLaterTransition) {
  const Checked c =
      check_text(atom_with("    on p from L, M to N\n"
                           "    on p from M to L\n"
                           "    on p from L, M to L, M\n"));
  EXPECT_TRUE(c.has(10, 5, "from M (here) and from L, M (line 9)")) << c.text();
  EXPECT_TRUE(c.has(11, 5, "from L, M (here) and from L, M (line 9)")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 2U) << c.text();
}

TEST(CheckDeterminism, GuardedTransitionsAreAWarning) {
  const Checked c =
      check_text(atom_with("    on p from L to N provided (x > 0)\n"
                           "    on p from L to M provided (x > 1)\n"
                           "    on q from L to N provided (t >= 2)\n"
                           "    on q from L to M\n"));
  EXPECT_TRUE(c.ok) << c.text();
  EXPECT_TRUE(c.has(Severity::Warning, 10, 5, "possible non-determinism: transitions on port 'p'"))
      << c.text();
  EXPECT_TRUE(c.has(Severity::Warning, 12, 5, "transitions on port 'q'")) << c.text();
  EXPECT_EQ(count(c, Severity::Warning), 2U) << c.text();
}

TEST(CheckDeterminism, ComparisonsWithoutACommonOrderAreExclusive) {
  const Checked c =
      check_text(atom_with("    on p from L to N provided (x == 3)\n"
                           "    on p from L to M provided (x < 3)\n"
                           "    on p from L to L provided (3 < x)\n"
                           "    on q from L to N provided (x > 0 && x < 9 && x != 20)\n"
                           "    on q from L to M provided (!(x > 0 && x < 9 || x == 20))\n"
                           "    on q from L to L provided (x == 20)\n"
                           "    internal from N to L provided (x > 1 && (x < 5 || x == 7))\n"
                           "    internal from N to M provided (x > 1 && !(x < 5 || x == 7))\n"));
  EXPECT_TRUE(c.diags.all().empty()) << c.text();
}

TEST(CheckDeterminism, GuardsThatMayHoldTogetherAreStillAWarning) {
  const Checked c =
      check_text(atom_with("    on p from L to N provided (x == 1)\n"
                           "    on p from L to M provided (x == 1.0)\n"
                           "    on q from L to N provided (x == 1)\n"
                           "    on q from L to M provided (x + 1 == 2)\n"
                           "    internal from N to L provided (x <= 3)\n"
                           "    internal from N to M provided (3 <= x)\n"));
  EXPECT_TRUE(c.ok) << c.text();
  EXPECT_EQ(count(c, Severity::Warning), 3U) << c.text();
}

TEST(CheckDeterminism, AnUnguardedPairOutranksAGuardedOne) {
  const Checked c =
      check_text(atom_with("    on p from L to N provided (x > 0)\n"
                           "    on p from L to M\n"
                           "    on p from L to L\n"));
  EXPECT_TRUE(c.has(Severity::Warning, 10, 5, "possible non-determinism")) << c.text();
  EXPECT_TRUE(c.has(11, 5, "from L (here) and from L (line 10)")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
  EXPECT_EQ(count(c, Severity::Warning), 1U) << c.text();
}

TEST(CheckDeterminism, GuardsWrittenAsEachOthersNegationAreDeterministic) {
  const Checked c =
      check_text(atom_with("    on p from L to N provided (x == 0)\n"
                           "    on p from L to M provided (x != 0)\n"
                           "    on q from L to N provided (t >= 1 && (x < 3))\n"
                           "    on q from L to M provided (!(x < 3))\n"
                           "    internal from N to L provided (x + 1 <= 2)\n"
                           "    internal from N to M provided (x + 1 > 2)\n"
                           "    on q from M to N provided (t >= 1 && (x > 0 && x < 5))\n"
                           "    on q from M to L provided (t < 4 && !(x > 0 && x < 5))\n"
                           "    on p from M to N provided (x == 1)\n"
                           "    on p from M to L provided (2 == x)\n"));
  EXPECT_TRUE(c.ok) << c.text();
  EXPECT_TRUE(c.diags.all().empty()) << c.text();
}

TEST(CheckDeterminism, DisjointOrDifferentlyLabelledTransitionsAreNotReported) {
  // Two marked places on one port: non-deterministic when both are marked, which the engines
  // report when it happens (the reference engine's own test expects a run that exits with 1).
  const Checked c =
      check_text(atom_with("    on p from L to N\n"
                           "    on p from M to N\n"
                           "    on q from L to M\n"
                           "    internal from N to L\n"));
  EXPECT_TRUE(c.ok) << c.text();
  EXPECT_TRUE(c.diags.all().empty()) << c.text();
}

TEST(CheckDeterminism, SuppressWarningSilencesTheWarningButNotTheError) {
  const std::string body =
      "    on p from L to N provided (x > 0)\n"
      "    on p from L to M provided (x > 1)\n"
      "    on q from L to N\n"
      "    on q from L to M\n";
  const Checked on_atom = check_text(atom_with(body, "  @SuppressWarning(nondeterminism)\n"));
  EXPECT_EQ(count(on_atom, Severity::Warning), 0U) << on_atom.text();
  EXPECT_TRUE(on_atom.has(13, 5, "non-determinism: transitions on port 'q'")) << on_atom.text();
  const Checked on_other = check_text(atom_with(body, "  @SuppressWarning(deadcode)\n"));
  EXPECT_EQ(count(on_other, Severity::Warning), 1U) << on_other.text();
  const Checked on_transition =
      check_text(atom_with("    on p from L to N provided (x > 0)\n"
                           "    @SuppressWarning(nondeterminism)\n"
                           "    on p from L to M provided (x > 1)\n"));
  EXPECT_TRUE(on_transition.diags.all().empty()) << on_transition.text();
}

TEST(CheckDeterminism, UnresolvedPortsAndPlacesAreLeftToTheirOwnErrors) {
  const Checked c =
      check_text(atom_with("    on z from L to N\n"
                           "    on z from L to M\n"
                           "    on p from K to N\n"
                           "    on p from K to M\n"));
  EXPECT_EQ(c.diags.error_count(), 4U) << c.text();
  for (const Diagnostic& d : c.diags.all()) {
    EXPECT_EQ(d.message.find("non-determinism"), std::string::npos) << c.text();
  }
}

/// The non-determinism diagnostics of one model of the reference engine's tests, as
/// "line:severity" ("17:warning").
std::vector<std::string> nondeterminism_in(const std::filesystem::path& file) {
  Diagnostics diags;
  LoadedModel model = load(file.string(), {}, diags);
  check(model, diags);
  std::vector<std::string> found;
  for (const Diagnostic& d : diags.all()) {
    if (d.message.find("non-determinism") == std::string::npos) continue;
    found.push_back(std::to_string(d.location.line) + ":" +
                    (d.severity == Severity::Error ? "error" : "warning"));
  }
  return found;
}

// The reference engine's tests run these models: the compiler accepts them all, and the runs of
// the three non-deterministic ones exit with 1. Only the third, two identical guarded
// transitions, shows its non-determinism in the text.
TEST(CheckDeterminism, ReferenceEngineModels) {
  const std::filesystem::path dir = test::shared_data_dir() / "bip-conformance" / "running";
  if (!std::filesystem::exists(dir)) {
    GTEST_SKIP() << "shared conformance data not found (set SMCBIP_SHARED_DATA)";
  }
  EXPECT_TRUE(nondeterminism_in(dir / "petri_net_non_deterministic.bip").empty());
  EXPECT_TRUE(nondeterminism_in(dir / "petri_net_non_deterministic2.bip").empty());
  EXPECT_EQ(nondeterminism_in(dir / "petri_net_non_deterministic3.bip"),
            std::vector<std::string>{"17:warning"});
  EXPECT_TRUE(nondeterminism_in(dir / "petri_net_deterministic.bip").empty());
}

}  // namespace
}  // namespace smcbip::bipc
