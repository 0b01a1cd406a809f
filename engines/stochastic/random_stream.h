// The reproducible random stream of one simulation run: a counter-based generator keyed by
// (seed, run index), so a run draws the same numbers whichever thread runs it and in any order.
#pragma once

#include <cstdint>
#include <limits>

namespace smcbip::engines {

// 2^64 / golden ratio, rounded to odd: SplitMix64's Weyl increment.
inline constexpr std::uint64_t kStreamGamma = 0x9E3779B97F4A7C15u;

// SplitMix64's finaliser (Stafford's "Mix13" variant of MurmurHash3's fmix64): a bijection of
// 64-bit words with full avalanche.
constexpr std::uint64_t stream_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
  return z ^ (z >> 31);
}

/// The random numbers of one run. The i-th draw is a pure function of (seed, run_index, i):
/// creating a stream costs O(1) whatever the run index, streams share no state, and a stream may
/// be copied to replay its future draws. Satisfies std::uniform_random_bit_generator.
///
/// Construction: the 128-bit key (k0, k1) is derived from (seed, run_index) by the SplitMix64
/// finaliser (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014).
/// The i-th output is stream_mix(stream_mix(k0 + (i+1)·γ) ⊕ k1), γ the golden-ratio odd constant:
/// the inner part is SplitMix64 started at k0; the outer keyed mix makes two runs whose Weyl
/// sequences happen to overlap still produce unrelated outputs (a counter-based design after Salmon
/// et al., "Parallel random numbers: as easy as 1, 2, 3", SC 2011).
class RandomStream {
  // Arbitrary odd constants separating the uses of the mixer (run index hash, second key word).
  static constexpr std::uint64_t kRunSalt = 0xD1B54A32D192ED03u;
  static constexpr std::uint64_t kKeySalt = 0x8CB92BA72F3D8DD7u;

 public:
  using result_type = std::uint64_t;

  /// The stream of run `run_index` under `seed`; equal arguments give equal streams. Inline:
  /// a statistical check makes one per run, and its runs can be a few steps long.
  RandomStream(std::uint64_t seed, std::uint64_t run_index) {
    // For a fixed seed, k0 is a bijective function of run_index (xor with a constant, then a
    // bijection), so two runs of one seed never share a key.
    const std::uint64_t seed_hash = stream_mix(seed + kStreamGamma);
    const std::uint64_t run_hash = stream_mix(run_index * kStreamGamma + kRunSalt);
    key0_ = stream_mix(seed_hash ^ run_hash);
    key1_ = stream_mix(key0_ ^ kKeySalt);
  }

  /// The next 64 uniformly distributed bits. Inline: the draws of consecutive items do not
  /// depend on each other, so the processor can overlap them.
  std::uint64_t next_u64() {
    ++counter_;
    return stream_mix(stream_mix(key0_ + counter_ * kStreamGamma) ^ key1_);
  }

  /// A uniform double k·2^-53 with k uniform in [1, 2^53 - 1]: never 0 or 1, so it can be fed
  /// to inverse CDFs and logarithms. Uses one draw except with probability 2^-53.
  double uniform01_open() {
    constexpr double kUlp = 1.0 / 9007199254740992.0;  // 2^-53
    for (;;) {
      // The top 53 bits; k = 0 is redrawn, and k·2^-53 <= 1 - 2^-53 is exact, so never 0 or 1.
      const std::uint64_t k = next_u64() >> 11;
      if (k != 0) return static_cast<double>(k) * kUlp;
    }
  }

  /// A uniform integer in [0, n), without bias, by multiplication (D. Lemire, "Fast random
  /// integer generation in an interval", ACM TOMACS 29(1), 2019): the high word of x·n for the
  /// first draw x whose low word is not in the block [0, 2^64 mod n), so that each result
  /// comes of floor(2^64 / n) draws. The block lies below n, so its end (a division) is computed
  /// only for a low word below n, rare unless n is huge: a step's uniform choices and dates
  /// cost a multiplication, not a 64-bit division. n must be positive; n == 0 aborts.
  std::uint64_t below(std::uint64_t n) {
    if (n == 0) [[unlikely]]
      below_zero();
    __extension__ using Wide = unsigned __int128;
    while (true) {
      const Wide product = Wide{next_u64()} * n;
      const auto low = static_cast<std::uint64_t>(product);
      if (low < n && low < (0 - n) % n) [[unlikely]] {
        continue;
      }
      return static_cast<std::uint64_t>(product >> 64);
    }
  }

  /// Skips `n` draws in O(1), as if next_u64() had been called n times.
  void discard(std::uint64_t n) { counter_ += n; }

  /// How many 64-bit draws this stream has made (or skipped) so far.
  std::uint64_t draws() const { return counter_; }

  /// UniformRandomBitGenerator interface, for the standard distributions.
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
  result_type operator()() { return next_u64(); }

 private:
  std::uint64_t key0_;
  std::uint64_t key1_;
  std::uint64_t counter_ = 0;
  [[noreturn]] static void below_zero();
};

}  // namespace smcbip::engines
