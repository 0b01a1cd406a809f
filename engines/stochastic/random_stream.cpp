// The counter-based random stream of one run (see random_stream.h for the construction).
#include "engines/stochastic/random_stream.h"

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

void RandomStream::below_zero() {
  std::fputs("smcbip: internal error: RandomStream::below(0)\n", stderr);
  std::abort();
}

}  // namespace smcbip::engines
