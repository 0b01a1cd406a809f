// The compiled step path's enabled positions: the bitset with its Fenwick tree over words
// against a plain array of flags, and the broadword selection within a word against a scan of
// its bits.
#include "engines/semantics/enabled_positions.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace smcbip::engines {
namespace {

/// Enables and disables random positions (some runs of changes fill or empty whole words) and
/// checks total() and every find against a scan of the flags.
void expect_finds_match_scan(std::size_t positions, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  EnabledPositions enabled;
  enabled.reset(positions);
  std::vector<bool> flags(positions, false);
  for (int round = 0; round < 60; ++round) {
    const bool fill = round % 10 == 3, empty = round % 10 == 7;
    for (std::size_t p = 0; p < positions && (fill || empty); ++p) {
      flags[p] = fill;
      enabled.set(p, fill);
    }
    for (int change = 0; change < 7 && positions > 0; ++change) {
      const std::size_t p = random() % positions;
      flags[p] = random() % 3 != 0;
      enabled.set(p, flags[p]);
    }
    std::size_t k = 0;
    for (std::size_t p = 0; p < positions; ++p) {
      ASSERT_EQ(enabled.enabled(p), flags[p]);
      if (!flags[p]) continue;
      ASSERT_EQ(enabled.find(k), p) << positions << " positions, k = " << k;
      ++k;
    }
    ASSERT_EQ(enabled.total(), k);
  }
}

TEST(EnabledPositions, FindsMatchAScanOfTheFlags) {
  for (std::size_t positions : {0, 1, 5, 63, 64, 65, 128, 129, 500, 1000, 4097}) {
    expect_finds_match_scan(positions, 40 + positions);
  }
}

TEST(EnabledPositions, SelectInWordMatchesAScanOfItsBits) {
  std::mt19937_64 random(41);
  std::vector<std::uint64_t> words = {1, std::uint64_t{1} << 63, 0xFFFFFFFFFFFFFFFFu,
                                      0x8000000000000001u, 0x00FF00FF00FF00FFu};
  for (int i = 0; i < 3000; ++i) {
    // Sparse, dense and mixed words.
    const std::uint64_t a = random(), b = random();
    words.push_back(i % 3 == 0 ? a & b : i % 3 == 1 ? a | b : a);
  }
  for (const std::uint64_t word : words) {
    unsigned r = 0;
    for (unsigned bit = 0; bit < 64; ++bit) {
      if ((word >> bit & 1) == 0) continue;
      ASSERT_EQ(EnabledPositions::select_in_word(word, r), bit) << std::hex << word << " r " << r;
      ++r;
    }
  }
}

}  // namespace
}  // namespace smcbip::engines
