// copy_bytes copies exactly the bytes asked for at every size its branches split (0 to 64 in
// fixed-size pieces, memcpy beyond), and no byte before or after them; copy_over copies
// vectors of equal and of different sizes.
#include "engines/semantics/copy_over.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace smcbip::engines {
namespace {

TEST(CopyBytes, CopiesEverySizeExactlyWithoutTouchingItsNeighbours) {
  constexpr std::size_t kGuard = 8;
  for (std::size_t n = 0; n <= 100; ++n) {
    std::vector<unsigned char> from(n + 2 * kGuard), to(n + 2 * kGuard, 0xEE);
    for (std::size_t i = 0; i < from.size(); ++i) from[i] = static_cast<unsigned char>(i + 1);
    copy_bytes(to.data() + kGuard, from.data() + kGuard, n);
    for (std::size_t i = 0; i < to.size(); ++i) {
      const bool inside = i >= kGuard && i < kGuard + n;
      EXPECT_EQ(to[i], inside ? from[i] : 0xEE) << "size " << n << ", byte " << i;
    }
  }
}

TEST(CopyOver, CopiesInPlaceOrResizes) {
  const std::vector<std::uint64_t> from = {1, 2, 3};
  std::vector<std::uint64_t> same(3, 0), shorter(1, 0), longer(5, 9);
  const std::uint64_t* storage = same.data();
  copy_over(from, same);
  copy_over(from, shorter);
  copy_over(from, longer);
  EXPECT_EQ(same, from);
  EXPECT_EQ(same.data(), storage);
  EXPECT_EQ(shorter, from);
  EXPECT_EQ(longer, from);
}

}  // namespace
}  // namespace smcbip::engines
