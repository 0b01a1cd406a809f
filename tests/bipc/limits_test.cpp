// Regression tests for adversarial model shapes that once hung or overflowed the stack.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "bipc/bipc.h"

namespace smcbip::bipc {
namespace {

/// A compound chain of `depth` levels, each re-exporting `ports` ports of the level below.
std::string reexport_chain(int depth, int ports) {
  std::string text = "package deep\n  port type Sig()\n  atom type A()\n    export port Sig ";
  for (int j = 0; j < ports; ++j) text += (j ? ", p" : "p") + std::to_string(j) + "()";
  text += "\n    place S\n    initial to S\n";
  for (int j = 0; j < ports; ++j) text += "    on p" + std::to_string(j) + " from S to S\n";
  text += "  end\n";
  std::string below = "A";
  for (int i = 0; i < depth; ++i) {
    text += "  compound type C" + std::to_string(i) + "()\n    component " + below + " c()\n";
    for (int j = 0; j < ports; ++j) {
      text += "    export port c.p" + std::to_string(j) + " as p" + std::to_string(j) + "\n";
    }
    text += "  end\n";
    below = "C" + std::to_string(i);
  }
  text += "  connector type R(Sig a)\n    define a\n  end\n";
  text +=
      "  compound type Top()\n    component " + below + " t()\n    connector R r(t.p0)\n  end\n";
  return text + "end\n";
}

struct FrontendRun {
  Diagnostics diags;
  std::optional<ir::System> system;
  bool has(const std::string& phrase) const {
    for (const Diagnostic& d : diags.all()) {
      if (d.message.find(phrase) != std::string::npos) return true;
    }
    return false;
  }
};

FrontendRun run_text(const std::string& text) {
  FrontendRun run;
  LoadedModel model;
  const std::uint32_t file = model.files.add("deep.bip");
  model.packages.push_back(parse_package(text, file, run.diags));
  model.main = model.packages.back().get();
  if (!check(model, run.diags)) return run;
  std::optional<ast::ComponentDecl> root = parse_root("Top()", file, run.diags);
  if (root && check_root(model, *root, run.diags)) {
    run.system = instantiate(model, *root, run.diags);
  }
  return run;
}

// Interfaces of re-exported components were recomputed per exported port at every level:
// 2^30 steps for this model before they were memoised.
TEST(Limits, NestedReexportsCheckWithoutExponentialWork) {
  const FrontendRun run = run_text(reexport_chain(30, 2));
  EXPECT_FALSE(run.diags.has_errors());
  EXPECT_TRUE(run.system.has_value());
}

// Instantiation recursed once per nesting level and overflowed the stack near 7,000 levels.
TEST(Limits, CompoundNestingBeyondTheLimitIsAnError) {
  EXPECT_TRUE(run_text(reexport_chain(998, 1)).system.has_value());  // 1,000 levels with Top
  const FrontendRun too_deep = run_text(reexport_chain(1000, 1));
  EXPECT_FALSE(too_deep.system.has_value());
  EXPECT_TRUE(too_deep.has("more than 1000 levels deep"));
}

// Packages were loaded one stack frame per `use` and a long chain overflowed the stack.
TEST(Limits, UseChainBeyondTheLimitIsAnError) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("bipc_use_chain_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const int packages = 300;
  for (int i = 0; i < packages; ++i) {
    std::ofstream out(dir / ("p" + std::to_string(i) + ".bip"));
    out << "package p" << i << "\n";
    if (i + 1 < packages) out << "  use p" << i + 1 << "\n";
    out << "  port type T" << i << "()\nend\n";
  }
  Diagnostics diags;
  load((dir / "p0.bip").string(), {}, diags);
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(diags.has_errors());
  bool reported = false;
  for (const Diagnostic& d : diags.all()) {
    reported = reported || d.message.find("nested more than 256 levels") != std::string::npos;
  }
  EXPECT_TRUE(reported) << diags.format(SourceFiles{});
}

}  // namespace
}  // namespace smcbip::bipc
