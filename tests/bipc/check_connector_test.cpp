// Tests of connector type checking: the define expression and the interactions it allows,
// interaction clauses, guards, up and down, and the exported port.
#include <gtest/gtest.h>

#include <string>

#include "bipc/bipc.h"
#include "bipc/check/detail/check_context.h"
#include "check_test_util.h"

namespace smcbip::bipc {
namespace {

using check_test::check_text;
using check_test::Checked;

/// A connector over ports a..e (indices 0..4) with the given define, checked.
Checked connector(const std::string& define) {
  return check_text(
      "package t\n  port type P()\n"
      "  connector type C(P a, P b, P c, P d, P e)\n"
      "    define " +
      define + "\n  end\nend\n");
}

bool allows(const Checked& c, std::vector<int> ports) {
  return detail::define_allows(c.model.packages[0]->connector_types[0].define, ports);
}

TEST(DefineAllows, Rendezvous) {
  const Checked c = connector("a b c d e");
  ASSERT_TRUE(c.ok) << c.text();
  EXPECT_TRUE(allows(c, {0, 1, 2, 3, 4}));
  EXPECT_TRUE(allows(c, {4, 3, 2, 1, 0}));
  EXPECT_FALSE(allows(c, {0, 1, 2, 3}));
  EXPECT_FALSE(allows(c, {}));
}

TEST(DefineAllows, Broadcast) {
  const Checked c = connector("a' b c d e");
  ASSERT_TRUE(c.ok) << c.text();
  EXPECT_TRUE(allows(c, {0}));
  EXPECT_TRUE(allows(c, {0, 2, 4}));
  EXPECT_FALSE(allows(c, {1, 2}));
}

TEST(DefineAllows, NestedTriggerGroup) {
  // (a b)' c: interactions contain both a and b (language.rst's `(p q)' r s` example).
  const Checked c = connector("(a b)' (c' d) e");
  ASSERT_TRUE(c.ok) << c.text();
  EXPECT_TRUE(allows(c, {0, 1}));
  EXPECT_TRUE(allows(c, {0, 1, 2}));
  EXPECT_TRUE(allows(c, {0, 1, 4}));
  EXPECT_TRUE(allows(c, {0, 1, 2, 3, 4}));
  EXPECT_FALSE(allows(c, {0}));
  EXPECT_FALSE(allows(c, {0, 1, 3}));  // d needs its trigger c inside (c' d)
  EXPECT_FALSE(allows(c, {2, 4}));     // no trigger of the top level, not every part
  EXPECT_TRUE(allows(c, {0, 1, 2, 3}));
}

TEST(DefineAllows, TwoTriggers) {
  const Checked c = connector("a' b' c d e");
  ASSERT_TRUE(c.ok) << c.text();
  EXPECT_TRUE(allows(c, {1}));
  EXPECT_TRUE(allows(c, {0, 1, 3}));
  EXPECT_FALSE(allows(c, {2, 3, 4}));
}

TEST(DefineAllows, ScalesToLargeBroadcasts) {
  std::string define = "p0'";
  std::string params = "P p0";
  for (int i = 1; i < 2000; ++i) {
    define += " p" + std::to_string(i);
    params += ", P p" + std::to_string(i);
  }
  const Checked c = check_text("package t\n  port type P()\n  connector type C(" + params +
                               ")\n    define " + define + "\n  end\nend\n");
  ASSERT_TRUE(c.ok) << c.text();
  std::vector<int> all;
  for (int i = 1999; i >= 0; --i) all.push_back(i);
  EXPECT_TRUE(allows(c, all));
  all.pop_back();  // without the trigger p0
  EXPECT_FALSE(allows(c, all));
}

TEST(CheckConnector, DefineLeaves) {
  const Checked c = check_text(
      "package t\n  port type P()\n"
      "  connector type C(P a, P b, P c)\n"
      "    define a (b z)' b\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(4, 17, "unknown port 'z' in define")) << c.text();
  EXPECT_TRUE(c.has(4, 21, "port 'b' appears twice in define")) << c.text();
  EXPECT_TRUE(c.has(3, 32, "port 'c' does not appear in define")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 3U) << c.text();
}

TEST(CheckConnector, Interactions) {
  const Checked c = check_text(
      "package t\n  port type V(int v)\n"
      "  connector type C(V a, V b, V c)\n"
      "    define a' b c\n"
      "    on a b down { b.v = a.v; }\n"
      "    on b a\n"
      "    on b c\n"
      "    on a a\n"
      "    on a z\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(6, 8, "interaction 'b a' is declared twice")) << c.text();
  EXPECT_TRUE(c.has(7, 8, "interaction 'b c' is not allowed by the define expression")) << c.text();
  EXPECT_TRUE(c.has(8, 10, "port 'a' appears twice in interaction")) << c.text();
  EXPECT_TRUE(c.has(9, 10, "unknown port 'z' in interaction")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 4U) << c.text();
}

TEST(CheckConnector, DataFlowRules) {
  const Checked c = check_text(
      "package t\n  port type V(int v)\n"
      "  connector type C(V a, V b)\n"
      "    data int tmp\n"
      "    export port V ep(tmp)\n"
      "    define a' b'\n"
      "    on a b provided (tmp > 0 && a.v > b.v) up { tmp = a.v; a.v = 1; } down { b.v = tmp; }\n"
      "    on a up { tmp = b.v; } down { b.v = 0; a.v = ep; }\n"
      "    on b up { tmp = b.v; } down { b.v = tmp + 1; tmp = 0; }\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(7, 22, "guard cannot read connector data 'tmp'")) << c.text();
  EXPECT_TRUE(c.has(7, 60, "'up' cannot assign port data 'a.v'")) << c.text();
  EXPECT_TRUE(c.has(8, 21, "port 'b' is not involved in this interaction")) << c.text();
  EXPECT_TRUE(c.has(8, 35, "port 'b' is not involved in this interaction")) << c.text();
  EXPECT_TRUE(c.has(8, 50, "undeclared variable 'ep'")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 5U) << c.text();
}

TEST(CheckConnector, UpNeedsAnExportedPortAndExportedDataNeedsUp) {
  const Checked c = check_text(
      "package t\n  port type V(int v)\n"
      "  connector type C(V a, V b)\n"
      "    data int tmp\n"
      "    define a b\n"
      "    on a b up { tmp = a.v; } down { b.v = tmp; }\n"
      "  end\n"
      "  connector type D(V a, V b)\n"
      "    data int tmp\n"
      "    export port V ep(tmp)\n"
      "    define a b\n"
      "    on a b down { b.v = 1; }\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(6, 12, "'up' needs an exported port")) << c.text();
  // Data no interaction computes keep their initial values: legal, so only a warning.
  EXPECT_TRUE(c.has(Severity::Warning, 10, 19,
                    "exported port 'ep' binds data that no interaction computes: no interaction "
                    "of connector type 'D' has an 'up'"))
      << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
}

TEST(CheckConnector, ExportedDataWithoutAnyInteractionIsAWarning) {
  const Checked c = check_text(
      "package t\n  port type V(int v)\n"
      "  connector type D(V a, V b)\n"
      "    data int tmp = 4\n"
      "    export port V ep(tmp)\n"
      "    define a b\n"
      "  end\nend\n");
  EXPECT_TRUE(c.ok) << c.text();
  EXPECT_TRUE(c.has(Severity::Warning, 5, 19, "binds data that no interaction computes"))
      << c.text();
}

TEST(CheckConnector, SuppressWarningSilencesMissingUp) {
  const Checked c = check_text(
      "package t\n  port type V(int v)\n"
      "  @SuppressWarning(missingup)\n"
      "  connector type D(V a, V b)\n"
      "    data int tmp = 4\n"
      "    export port V ep(tmp)\n"
      "    define a b\n"
      "  end\nend\n");
  EXPECT_TRUE(c.diags.all().empty()) << c.text();
}

TEST(CheckConnector, ExportedPortBindsConstantsNotVariables) {
  const Checked c = check_text(
      "package t\n  const data int K = 2\n  port type V(int v)\n"
      "  connector type C(V a)\n"
      "    data const int fixed = 1\n"
      "    export port V ep(K)\n"
      "    define a\n"
      "  end\n"
      "  connector type D(V a)\n"
      "    data const int fixed = 1\n"
      "    export port V ep(fixed)\n"
      "    define a\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(6, 22, "'K' is a constant data, an exported port can only bind variables"))
      << c.text();
  EXPECT_TRUE(c.has(11, 22, "'fixed' is a constant data, an exported port can only bind variables"))
      << c.text();
  EXPECT_EQ(c.diags.error_count(), 2U) << c.text();
}

TEST(CheckConnector, ExportPortBinding) {
  const Checked c = check_text(
      "package t\n  port type V(int v)\n"
      "  connector type C(V a, V b)\n"
      "    data float f\n"
      "    export port V ep(f)\n"
      "    define a b\n"
      "    on a b up { f = a.v; }\n"
      "  end\nend\n");
  EXPECT_TRUE(c.has(5, 22, "binds 'f' of type float to parameter 'v' of type int")) << c.text();
  EXPECT_EQ(c.diags.error_count(), 1U) << c.text();
}

}  // namespace
}  // namespace smcbip::bipc
