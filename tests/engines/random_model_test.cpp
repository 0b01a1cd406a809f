// The random model generator: its packages pass the front end, are reproducible and vary.
#include "random_model.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>

#include "bipc/bipc.h"

namespace smcbip::tests {
namespace {

constexpr std::uint64_t kSeeds = 200;

/// Options varied by seed so that every switch is both on and off across the seeds.
RandomModelOptions options_for(std::uint64_t seed) {
  RandomModelOptions options;
  options.seed = seed;
  options.atoms = 1 + static_cast<int>(seed % 8);
  options.max_places = 1 + static_cast<int>(seed % 5);
  options.max_ports = 1 + static_cast<int>(seed % 4);
  options.connectors = static_cast<int>(seed % 7);
  options.priorities = seed % 3 != 0;
  options.clocks = seed % 2 == 0;
  options.data = seed % 5 != 0;
  options.hierarchy = seed % 4 != 1;
  return options;
}

std::string package_name(std::uint64_t seed) { return "random_" + std::to_string(seed); }

using Marking = std::uint64_t;

Marking mask(const std::vector<bipc::ir::Index>& places) {
  Marking m = 0;
  for (bipc::ir::Index p : places) m |= Marking{1} << p;
  return m;
}

/// What the generator promises of each atom net, checked with every guard taken as true (so
/// over every run): no transition puts a second token in a place; at most one transition per
/// port is enabled, or two guarded ones (the generator makes such guards complementary); the
/// same for unlabelled internal transitions; and these never form a cycle (the engines run them
/// until none is enabled). Returns the first problem found, or "".
std::string net_problem(const bipc::ir::AtomType& type) {
  if (type.places.size() > 64) return type.name + ": more than 64 places";
  std::map<Marking, std::vector<Marking>> internal_steps;  // reachable marking -> internal targets
  std::vector<Marking> unvisited{mask(type.initial_places)};
  internal_steps[unvisited.back()];
  while (!unvisited.empty()) {
    const Marking m = unvisited.back();
    unvisited.pop_back();
    std::map<bipc::ir::Index, std::vector<const bipc::ir::Transition*>> enabled;  // by port
    for (const bipc::ir::Transition& t : type.transitions) {
      const Marking from = mask(t.from), to = mask(t.to);
      if ((m & from) != from) continue;
      enabled[t.port].push_back(&t);
      const Marking rest = m & ~from;
      if ((rest & to) != 0) return type.name + ": a transition puts a second token in a place";
      const Marking next = rest | to;
      if (t.port == bipc::ir::kNone) internal_steps[m].push_back(next);
      if (internal_steps.emplace(next, std::vector<Marking>{}).second) unvisited.push_back(next);
    }
    for (const auto& [port, ts] : enabled) {
      if (ts.size() > 2 || (ts.size() == 2 && (ts[0]->guard.empty() || ts[1]->guard.empty()))) {
        return type.name + ": " + std::to_string(ts.size()) + " transitions of " +
               (port == bipc::ir::kNone ? std::string("the internal step")
                                        : "port " + type.ports[port].name) +
               " enabled at once";
      }
    }
  }
  // Depth-first search for a cycle of internal steps: 1 = on the stack, 2 = done.
  std::map<Marking, int> state;
  std::function<bool(Marking)> cyclic = [&](Marking m) {
    state[m] = 1;
    for (Marking next : internal_steps[m]) {
      if (state[next] == 1 || (state[next] == 0 && cyclic(next))) return true;
    }
    state[m] = 2;
    return false;
  };
  for (const auto& [m, steps] : internal_steps) {
    if (state[m] == 0 && cyclic(m)) return type.name + ": internal steps form a cycle";
  }
  return "";
}

/// A scratch directory of this test, removed at the end.
class RandomModelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("smcbip_random_model_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  std::filesystem::path dir_;
};

TEST_F(RandomModelTest, EveryPackagePassesTheFrontEndWithSafeNets) {
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const RandomModelOptions options = options_for(seed);
    const std::string text = random_bip_package(options, package_name(seed));
    const std::filesystem::path file = dir_ / (package_name(seed) + ".bip");
    {
      std::ofstream out(file);
      out << text;
      ASSERT_TRUE(out.good()) << "cannot write " << file;
    }
    bipc::FrontendResult result = bipc::run_frontend({file.string(), {}, "Root()"}, true);
    EXPECT_FALSE(result.diags.has_errors()) << "seed " << seed << ":\n"
                                            << result.diags.format(result.model.files) << text;
    ASSERT_TRUE(result.system.has_value()) << "seed " << seed << ": no system\n" << text;
    for (const bipc::ir::AtomType& type : result.system->atom_types) {
      EXPECT_EQ(net_problem(type), "") << "seed " << seed << ":\n" << text;
    }
    if (HasFailure()) return;  // one full report is enough
  }
}

TEST(RandomModel, SameSeedSameText) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    EXPECT_EQ(random_bip_package(options_for(seed), "p"),
              random_bip_package(options_for(seed), "p"));
  }
}

TEST(RandomModel, SeedsChangeTheText) {
  RandomModelOptions first = options_for(6), second = options_for(6);
  second.seed = 6 + 7 * 8 * 5 * 4 * 3;  // same options, other seed
  EXPECT_NE(random_bip_package(first, "p"), random_bip_package(second, "p"));
}

bool has(const std::string& line, const std::string& part) {
  return line.find(part) != std::string::npos;
}

/// Whether `line` is an atom transition from (or to) a main place and an auxiliary one.
bool moves_two_places(const std::string& line, bool from_side) {
  const std::size_t from = line.find(" from L"), to = line.find(" to L");
  if (from == std::string::npos || to == std::string::npos) return false;
  const std::string side = from_side ? line.substr(from, to - from) : line.substr(to);
  return has(side, ", M");
}

// The features the differential tests rely on appear in some of the packages (the generator
// could otherwise silently lose one and the engines' cross-runs would no longer cover it).
TEST(RandomModel, SeedsCoverTheLanguage) {
  using Line = const std::string&;
  const std::map<std::string, std::function<bool(Line)>> features = {
      {"exported port with data", [](Line l) { return has(l, "export port IntPort p"); }},
      {"port with two parameters", [](Line l) { return has(l, "export port PairPort p"); }},
      {"internal port", [](Line l) { return l.rfind("    port ", 0) == 0; }},
      {"unlabelled internal transition", [](Line l) { return has(l, "internal from L"); }},
      {"guard over data", [](Line l) { return has(l, " from L") && has(l, "provided (x"); }},
      {"action", [](Line l) { return has(l, " from L") && has(l, "do { x"); }},
      {"complementary guards", [](Line l) { return has(l, " from L") && has(l, "(!("); }},
      {"multi-place from (join)", [](Line l) { return moves_two_places(l, true); }},
      {"multi-place to (fork)", [](Line l) { return moves_two_places(l, false); }},
      {"rendezvous", [](Line l) { return has(l, "define p0 p1"); }},
      {"broadcast", [](Line l) { return has(l, "define p0' p1 p2"); }},
      {"all triggers", [](Line l) { return has(l, "define p0' p1'"); }},
      {"connector guard", [](Line l) { return has(l, "    on p") && has(l, "provided (p"); }},
      {"down action", [](Line l) { return has(l, "    on p") && has(l, "down { "); }},
      {"up action", [](Line l) { return has(l, "up { d = "); }},
      {"connector exported port", [](Line l) { return has(l, "export port IntPort top(d)"); }},
      {"hierarchical binding", [](Line l) { return has(l, "connector K") && has(l, ".top"); }},
      {"sub-compound", [](Line l) { return has(l, "component S"); }},
      {"sub-compound port export", [](Line l) { return has(l, "export port a"); }},
      {"sub-compound connector export", [](Line l) { return has(l, ".top as x"); }},
      {"sub-compound data export", [](Line l) { return has(l, "export data a"); }},
      {"compound priority", [](Line l) { return has(l, "priority r") && has(l, ":* < c"); }},
      {"guarded compound priority",
       [](Line l) { return has(l, "priority r") && has(l, "provided ("); }},
      {"named interaction", [](Line l) { return has(l, "priority r") && has(l, ":a"); }},
      {"wildcard priority", [](Line l) { return has(l, "*:* < c"); }},
      {"atom priority", [](Line l) { return has(l, "priority ap0 p"); }},
      {"guarded atom priority", [](Line l) { return has(l, "priority ap") && has(l, "provided"); }},
      {"clock", [](Line l) { return has(l, "clock t0"); }},
      {"eager", [](Line l) { return has(l, " eager"); }},
      {"delayable", [](Line l) { return has(l, " delayable"); }},
      {"clock window", [](Line l) { return has(l, "t0 >= ") && has(l, "&& t0 <= "); }},
      {"clock reset", [](Line l) { return has(l, "t0 = 0;") && has(l, " from L"); }},
  };
  std::map<std::string, int> seen;
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    std::istringstream text(random_bip_package(options_for(seed), package_name(seed)));
    for (std::string line; std::getline(text, line);) {
      for (const auto& [name, present] : features) {
        if (present(line)) ++seen[name];
      }
    }
  }
  for (const auto& [name, present] : features) {
    EXPECT_GT(seen[name], 0) << name << " never generated";
  }
}

}  // namespace
}  // namespace smcbip::tests
