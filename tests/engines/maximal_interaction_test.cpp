// The largest enabled interaction found from a define tree against the enumeration of every
// interaction the tree defines, on random trees and random sets of enabled ports.
#include "engines/semantics/maximal_interaction.h"

#include <gtest/gtest.h>

#include <random>

#include "engines/semantics/layout.h"

namespace smcbip::engines {
namespace {

using bipc::ir::DefineNode;

/// A random define node over the ports from `next_port` on: a leaf, or 1 to 4 children of
/// which some may be triggers.
DefineNode random_node(std::mt19937_64& rng, Index& next_port, int depth) {
  DefineNode node;
  std::uniform_int_distribution<int> width(1, 4);
  if (depth == 0 || std::bernoulli_distribution(0.4)(rng)) {
    node.port = next_port++;
    return node;
  }
  const int children = width(rng);
  for (int c = 0; c < children; ++c) {
    node.children.push_back(random_node(rng, next_port, depth - 1));
    node.children.back().trigger = std::bernoulli_distribution(0.3)(rng);
  }
  return node;
}

std::vector<DefineNode> random_define(std::mt19937_64& rng, Index& ports) {
  ports = 0;
  std::vector<DefineNode> define = random_node(rng, ports, 3).children;
  if (define.empty()) define.push_back(DefineNode{0, {}, false});
  if (ports == 0) ports = 1;
  return define;
}

/// The defined port sets within `enabled` that no other such set strictly contains.
std::vector<PortSet> maximal_enabled(const std::vector<PortSet>& defined, PortSet enabled) {
  std::vector<PortSet> within, maximal;
  for (PortSet s : defined) {
    if ((s & ~enabled) == 0) within.push_back(s);
  }
  for (PortSet s : within) {
    bool dominated = false;
    for (PortSet t : within) dominated = dominated || (t != s && (s & ~t) == 0);
    if (!dominated) maximal.push_back(s);
  }
  return maximal;
}

TEST(LargestEnabledInteraction, IsTheOneMaximalDefinedSetWithinTheEnabledPorts) {
  std::mt19937_64 rng(20261121);
  int compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Index ports = 0;
    const std::vector<DefineNode> define = random_define(rng, ports);
    if (ports > 16) continue;  // keeps the enumeration small
    const std::optional<std::vector<PortSet>> defined = defined_interactions(define);
    ASSERT_TRUE(defined);
    const PortSet enabled_set =
        std::uniform_int_distribution<PortSet>(0, (PortSet{1} << ports) - 1)(rng);
    std::vector<std::uint8_t> enabled(ports);
    for (Index p = 0; p < ports; ++p) enabled[p] = (enabled_set >> p) & 1;
    std::vector<Index> largest;
    const bool found = largest_enabled_interaction(define, enabled, largest);
    const std::vector<PortSet> maximal = maximal_enabled(*defined, enabled_set);
    ASSERT_LE(maximal.size(), 1u) << "trial " << trial;
    ASSERT_EQ(found, maximal.size() == 1) << "trial " << trial;
    if (!found) continue;
    PortSet got = 0;
    for (std::size_t i = 0; i < largest.size(); ++i) {
      got |= PortSet{1} << largest[i];
      if (i > 0) {
        EXPECT_LT(largest[i - 1], largest[i]) << "ports in increasing order";
      }
    }
    EXPECT_EQ(got, maximal.front()) << "trial " << trial;
    ++compared;
  }
  EXPECT_GT(compared, 1000);  // the generator must produce enabled interactions often enough
}

}  // namespace
}  // namespace smcbip::engines
