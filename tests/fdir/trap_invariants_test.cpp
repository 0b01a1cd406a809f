// Traps of small Petri nets, checked against the definition by enumerating every place set.
#include "fdir/invariants/trap_invariants.h"

#include <gtest/gtest.h>

#include <random>

namespace smcbip::fdir {
namespace {

/// Whether `set` (per place) is a trap: every transition taking from it puts into it.
bool is_trap(const PetriNet& net, const std::vector<std::uint8_t>& set) {
  for (const NetTransition& t : net.transitions) {
    bool takes = false, puts = false;
    for (Index p : t.pre) takes = takes || set[p];
    for (Index p : t.post) puts = puts || set[p];
    if (takes && !puts) return false;
  }
  return true;
}

PetriNet random_net(std::mt19937& random, std::size_t places, std::size_t transitions) {
  PetriNet net;
  net.places.resize(places);
  net.initial.resize(places);
  std::bernoulli_distribution coin(0.3);
  for (std::size_t p = 0; p < places; ++p) net.initial[p] = coin(random);
  for (std::size_t k = 0; k < transitions; ++k) {
    NetTransition t;
    for (Index p = 0; p < places; ++p) {
      if (coin(random)) t.pre.push_back(p);
      if (coin(random)) t.post.push_back(p);
    }
    net.transitions.push_back(t);
  }
  return net;
}

TEST(Traps, TheLargestTrapInsideASetIsATrapContainingEveryOther) {
  std::mt19937 random(7);
  for (int round = 0; round < 200; ++round) {
    const std::size_t places = 6;
    const PetriNet net = random_net(random, places, 5);
    std::vector<std::uint8_t> allowed(places);
    for (auto& a : allowed) a = std::bernoulli_distribution(0.7)(random);
    std::vector<std::uint8_t> largest(places);
    for (Index p : largest_trap(net, allowed)) largest[p] = 1;
    EXPECT_TRUE(is_trap(net, largest));
    for (unsigned mask = 0; mask < (1u << places); ++mask) {
      std::vector<std::uint8_t> set(places);
      bool inside = true;
      for (std::size_t p = 0; p < places; ++p) {
        set[p] = (mask >> p) & 1;
        inside = inside && (!set[p] || allowed[p]);
      }
      if (!inside || !is_trap(net, set)) continue;
      for (std::size_t p = 0; p < places; ++p) EXPECT_TRUE(!set[p] || largest[p]);
    }
  }
}

TEST(Traps, ATrapGrownAroundAPlaceIsATrapInsideTheLargest) {
  std::mt19937 random(11);
  for (int round = 0; round < 200; ++round) {
    const std::size_t places = 7;
    const PetriNet net = random_net(random, places, 6);
    const std::vector<std::uint8_t> all(places, 1);
    std::vector<std::uint8_t> largest(places);
    for (Index p : largest_trap(net, all)) largest[p] = 1;
    for (Index p = 0; p < places; ++p) {
      if (!largest[p]) continue;
      std::vector<std::uint8_t> grown(places);
      for (Index q : trap_around(net, largest, p)) grown[q] = 1;
      EXPECT_TRUE(grown[p]);
      EXPECT_TRUE(is_trap(net, grown));
      for (Index q = 0; q < places; ++q) EXPECT_TRUE(!grown[q] || largest[q]);
    }
  }
}

TEST(Traps, AMarkingIsExcludedOnlyByAnInitiallyMarkedTrapItLeavesEmpty) {
  // Two places exchanging one token: {a, b} is a trap, marked initially through a.
  PetriNet net;
  net.places = {"a", "b", "c"};
  net.initial = {1, 0, 0};
  net.transitions = {{0, {}, {0}, {1}}, {0, {}, {1}, {0}}, {0, {}, {2}, {2}}};
  const auto traps = excluding_traps(net, {0, 0, 1}, 10);
  ASSERT_EQ(traps.size(), 1u);
  EXPECT_EQ(traps.front(), (std::vector<Index>{0, 1}));
  EXPECT_TRUE(excluding_traps(net, {0, 1, 0}, 10).empty());  // b marked: {a, b} excludes nothing
}

}  // namespace
}  // namespace smcbip::fdir
