// The counter-based random stream of one run (see random_stream.h for the construction).
#include "engines/stochastic/random_stream.h"

#include <bit>
#include <cstdio>
#include <cstdlib>

namespace smcbip::engines {

namespace {

// Arbitrary odd constants separating the uses of the mixer (run index hash, second key word).
constexpr std::uint64_t kRunSalt = 0xD1B54A32D192ED03u;
constexpr std::uint64_t kKeySalt = 0x8CB92BA72F3D8DD7u;

}  // namespace

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t run_index) {
  // For a fixed seed, k0 is a bijective function of run_index (xor with a constant, then a
  // bijection), so two runs of one seed never share a key.
  const std::uint64_t seed_hash = stream_mix(seed + kStreamGamma);
  const std::uint64_t run_hash = stream_mix(run_index * kStreamGamma + kRunSalt);
  key0_ = stream_mix(seed_hash ^ run_hash);
  key1_ = stream_mix(key0_ ^ kKeySalt);
}

void RandomStream::set_below(std::uint64_t n) {
  if (n == 0) {
    std::fputs("smcbip: internal error: RandomStream::below(0)\n", stderr);
    std::abort();
  }
  below_n_ = n;
  below_magic_ = 0;
  below_repeats_ = 0;
}

void RandomStream::set_reciprocal(std::uint64_t n) {
  // l = ceil(log2 n); magic = floor(2^64 (2^l - n) / n) + 1, which fits 64 bits as 2^l - n < n.
  const unsigned l = n == 1 ? 0 : static_cast<unsigned>(64 - std::countl_zero(n - 1));
  const std::uint64_t excess = l == 64 ? 0 - n : (std::uint64_t{1} << l) - n;
  __extension__ using Wide = unsigned __int128;
  below_magic_ = static_cast<std::uint64_t>((Wide{excess} << 64) / n + 1);
  below_shift1_ = l < 1 ? l : 1;
  below_shift2_ = l > 1 ? l - 1 : 0;
}

}  // namespace smcbip::engines
