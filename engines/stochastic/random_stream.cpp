// The counter-based random stream of one run (see random_stream.h for the construction).
#include "engines/stochastic/random_stream.h"

#include <cstdio>
#include <cstdlib>

namespace smcbip::engines {

namespace {

// 2^64 / golden ratio, rounded to odd: SplitMix64's Weyl increment.
constexpr std::uint64_t kGamma = 0x9E3779B97F4A7C15u;
// Arbitrary odd constants separating the uses of the mixer (run index hash, second key word).
constexpr std::uint64_t kRunSalt = 0xD1B54A32D192ED03u;
constexpr std::uint64_t kKeySalt = 0x8CB92BA72F3D8DD7u;

// SplitMix64's finaliser (Stafford's "Mix13" variant of MurmurHash3's fmix64): a bijection of
// 64-bit words with full avalanche.
constexpr std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
  return z ^ (z >> 31);
}

}  // namespace

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t run_index) {
  // For a fixed seed, k0 is a bijective function of run_index (xor with a constant, then a
  // bijection), so two runs of one seed never share a key.
  const std::uint64_t seed_hash = mix(seed + kGamma);
  const std::uint64_t run_hash = mix(run_index * kGamma + kRunSalt);
  key0_ = mix(seed_hash ^ run_hash);
  key1_ = mix(key0_ ^ kKeySalt);
}

std::uint64_t RandomStream::next_u64() {
  ++counter_;
  return mix(mix(key0_ + counter_ * kGamma) ^ key1_);
}

double RandomStream::uniform01_open() {
  constexpr double kUlp = 1.0 / 9007199254740992.0;  // 2^-53
  while (true) {
    // The top 53 bits; k = 0 is redrawn, and k·2^-53 <= 1 - 2^-53 is exact, so never 0 or 1.
    const std::uint64_t k = next_u64() >> 11;
    if (k != 0) return static_cast<double>(k) * kUlp;
  }
}

std::uint64_t RandomStream::below(std::uint64_t n) {
  if (n == 0) {
    std::fputs("smcbip: internal error: RandomStream::below(0)\n", stderr);
    std::abort();
  }
  // 2^64 mod n: draws below it fall in the incomplete block [0, 2^64 mod n) and are redrawn;
  // the rest cover each residue exactly floor(2^64 / n) times.
  const std::uint64_t threshold = (0 - n) % n;
  while (true) {
    const std::uint64_t x = next_u64();
    if (x >= threshold) return x % n;
  }
}

}  // namespace smcbip::engines
