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
 public:
  using result_type = std::uint64_t;

  /// The stream of run `run_index` under `seed`; equal arguments give equal streams.
  RandomStream(std::uint64_t seed, std::uint64_t run_index);

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

  /// A uniform integer in [0, n), without modulo bias (rejection of the incomplete last block,
  /// as OpenBSD's arc4random_uniform): x mod n of the first draw x not in that block
  /// [0, 2^64 mod n). n must be positive; n == 0 aborts. Inline, and without division where it
  /// can: the block lies below n, so only a draw below n (rare unless n is huge) needs its end;
  /// and from the fourth draw in a row below the same n, x mod n uses n's reciprocal, two
  /// multiplications where a 64-bit division is a good part of a scheduler's step. Computing
  /// the reciprocal costs a 128-bit division, which bounds that change from draw to draw (the
  /// planner's uniform dates) should not pay each time.
  std::uint64_t below(std::uint64_t n) {
    if (n != below_n_) [[unlikely]] {
      set_below(n);
    } else if (below_magic_ == 0 && ++below_repeats_ == kRepeatsBeforeReciprocal) [[unlikely]] {
      set_reciprocal(n);
    }
    while (true) {
      const std::uint64_t x = next_u64();
      if (x < n && x < (0 - n) % n) [[unlikely]] {
        continue;
      }
      return below_magic_ == 0 ? x % n : x - below_quotient(x) * n;
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
  // below(): the last n. Draws in the incomplete block [0, 2^64 mod n) are redrawn, the rest
  // cover each residue floor(2^64 / n) times.
  std::uint64_t below_n_ = 0;
  // floor(x / below_n_) by multiplication (Granlund and Montgomery, "Division by invariant
  // integers using multiplication", PLDI 1994, figure 4.1): exact for every 64-bit x. The
  // magic number is at least 1; 0 means not computed yet.
  std::uint64_t below_magic_ = 0;
  unsigned below_shift1_ = 0, below_shift2_ = 0;
  unsigned below_repeats_ = 0;  // draws below the same n without its reciprocal
  static constexpr unsigned kRepeatsBeforeReciprocal = 4;
  std::uint64_t below_quotient(std::uint64_t x) const {
    __extension__ using Wide = unsigned __int128;
    const auto high = static_cast<std::uint64_t>((Wide{below_magic_} * x) >> 64);
    return (high + ((x - high) >> below_shift1_)) >> below_shift2_;
  }
  /// Keeps n for below(); aborts on n == 0.
  void set_below(std::uint64_t n);
  void set_reciprocal(std::uint64_t n);
};

}  // namespace smcbip::engines
