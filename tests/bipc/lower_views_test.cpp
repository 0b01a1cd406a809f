// Tests of the IR's JSON and Graphviz views and of rendering a picture through `dot`.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "bipc/ir/ir_dot.h"
#include "bipc/ir/ir_json.h"
#include "lower_test_util.h"

namespace smcbip::bipc {
namespace {

const std::string kModel =
    "package v\n"
    "  port type P(int d)\n"
    "  connector type Brd(P s, P r)\n"
    "    data int z\n"
    "    export port P e(z)\n"
    "    define s' r\n"
    "    on s up { z = s.d; }\n"
    "    on s r up { z = s.d; } down { r.d = s.d; }\n"
    "  end\n"
    "  connector type One(P a)\n"
    "    define a\n"
    "  end\n"
    "  atom type A(int init)\n"
    "    data int x\n"
    "    export port P p(x)\n"
    "    place S\n"
    "    initial to S do { x = init; }\n"
    "    on p from S to S provided (x < 10) do { x = x + 1; }\n"
    "  end\n"
    "  compound type Pair()\n"
    "    component A a(1), b(2)\n"
    "    connector Brd brd(a.p, b.p)\n"
    "    export port brd.e as out\n"
    "  end\n"
    "  compound type Top()\n"
    "    component Pair left()\n"
    "    component A c(3)\n"
    "    connector One top(left.out)\n"
    "    connector One solo(c.p)\n"
    "    priority first solo:* < top:*\n"
    "  end\n"
    "end\n";

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// A fresh directory under the system's temporary folder, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "lower_views_XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

TEST(LowerViews, JsonNamesInstancesPortsAndCode) {
  auto lowered = lower_test::lower_ok(kModel, "Top()");
  ASSERT_TRUE(lowered->system);
  const nlohmann::json j = ir::to_json(*lowered->system);
  EXPECT_EQ(j["root"]["type"], "v.Top");
  ASSERT_EQ(j["atoms"].size(), 3u);
  EXPECT_EQ(j["atoms"][0]["path"], "left.a");
  EXPECT_EQ(j["atoms"][0]["params"][0], 1);
  EXPECT_EQ(j["atoms"][1]["parent"], "left");
  const nlohmann::json& brd = j["connectors"][0];
  EXPECT_EQ(brd["path"], "left.brd");
  EXPECT_EQ(brd["bound"][0]["port"], "s");
  EXPECT_EQ(brd["bound"][0]["ports"][0], "left.a.p");
  EXPECT_EQ(brd["bound_by"], nlohmann::json::array({"top"}));
  EXPECT_EQ(j["connectors"][1]["bound"][0]["ports"][0], "left.brd.e");
  EXPECT_EQ(j["compounds"][1]["exported_ports"]["out"][0], "left.brd.e");
  EXPECT_EQ(j["compounds"][0]["priorities"][0]["low"]["connector"], "solo");
  EXPECT_EQ(j["compounds"][0]["priorities"][0]["low"]["ports"], "*");
  const nlohmann::json& atom = j["atom_types"][0];
  EXPECT_EQ(atom["name"], "v.A");
  EXPECT_EQ(atom["transitions"][0]["guard"],
            (nlohmann::json{"load atom.data[0]", "push.int 10", "lt.int"}));
  EXPECT_EQ(atom["transitions"][0]["port"], "p");
  EXPECT_EQ(atom["ports"][0]["data"][0], "x");
  EXPECT_EQ(j["connector_types"][0]["define"], "s' r");
  EXPECT_EQ(j["connector_types"][0]["interactions"][1]["down"],
            (nlohmann::json{"load port[0].param[0]", "store port[1].param[0]"}));
  // The dump is deterministic.
  EXPECT_EQ(j.dump(), ir::to_json(*lowered->system).dump());
}

TEST(LowerViews, DotDrawsClustersAtomsConnectorsAndEdges) {
  auto lowered = lower_test::lower_ok(kModel, "Top()");
  ASSERT_TRUE(lowered->system);
  const std::string dot = ir::to_dot(*lowered->system);
  EXPECT_NE(dot.find("digraph \"v.Top\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("subgraph cluster_c0"), std::string::npos);
  EXPECT_NE(dot.find("label=\"ROOT : Top\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("label=\"left : Pair\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("a0 [shape=record"), std::string::npos);
  EXPECT_NE(dot.find("<p0> p"), std::string::npos);
  EXPECT_NE(dot.find("a0:p0 -> k0 [style=dashed]"), std::string::npos) << dot;  // trigger s
  EXPECT_NE(dot.find("k0 -> a1:p0;"), std::string::npos) << dot;
  EXPECT_NE(dot.find("k0 -> k1 [penwidth=2"), std::string::npos) << dot;  // hierarchical
}

TEST(LowerViews, RenderWritesDotTextAndRefusesUnknownFormats) {
  TempDir dir;
  const std::string dot = "digraph g { a -> b; }\n";
  std::string error;
  const auto text = dir.path() / "arch.dot";
  ASSERT_TRUE(ir::render_svg(dot, text.string(), error)) << error;
  EXPECT_EQ(read_file(text), dot);
  EXPECT_FALSE(ir::render_svg(dot, (dir.path() / "arch.txt").string(), error));
  EXPECT_NE(error.find(".svg"), std::string::npos) << error;
  // Only the .dot file is left behind: no temporaries.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(LowerViews, RenderRunsGraphvizOrExplainsWhyNot) {
  TempDir dir;
  auto lowered = lower_test::lower_ok(kModel, "Top()");
  ASSERT_TRUE(lowered->system);
  const std::string dot = ir::to_dot(*lowered->system);
  const auto svg = dir.path() / "arch.svg";
  std::string error;
  if (std::system("command -v dot >/dev/null 2>&1") == 0) {
    ASSERT_TRUE(ir::render_svg(dot, svg.string(), error)) << error;
    EXPECT_NE(read_file(svg).find("<svg"), std::string::npos);
    // Bad Graphviz text: dot's complaint is reported, and nothing is written.
    const auto bad = dir.path() / "bad.svg";
    EXPECT_FALSE(ir::render_svg("digraph { a -> }", bad.string(), error));
    EXPECT_NE(error.find("dot"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(bad));
  }
  // Without dot on the PATH the error says so and no file appears.
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path ? old_path : "";
  ::setenv("PATH", dir.path().c_str(), 1);
  const auto missing = dir.path() / "missing.png";
  const bool ok = ir::render_svg(dot, missing.string(), error);
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_FALSE(ok);
  EXPECT_NE(error.find("not found"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(missing));
}

}  // namespace
}  // namespace smcbip::bipc
