// Estimates of the probability p that a run satisfies a formula that stop as soon as they are
// precise enough: a confidence interval that keeps its coverage under that optional stopping,
// and Bayesian interval estimation (Zuliani, Platzer and Clarke, 2013).
#pragma once

#include <cstdint>

namespace smcbip::smc {

struct Interval {
  double low = 0, high = 1;
};

/// The Clopper-Pearson interval of x successes in n runs at level 1 - alpha (exact, two-sided).
Interval clopper_pearson(std::uint64_t x, std::uint64_t n, double alpha);

/// Looks at the runs after first_look * 2^k of them, the k-th look (from 0) at level
/// alpha / 2^(k+1): the levels sum to less than alpha, so the interval it stops with covers p
/// with probability at least 1 - alpha whenever it stops (a union bound), unlike a
/// Clopper-Pearson interval recomputed after every run. It stops at the first look whose
/// interval is at most 2 delta wide.
class SequentialInterval {
 public:
  SequentialInterval(double delta, double alpha, std::uint64_t first_look = 32);
  /// One run's outcome; true once the estimate is done.
  bool add(bool satisfied);
  bool done() const { return done_; }
  Interval interval() const { return interval_; }
  double estimate() const;
  std::uint64_t samples() const { return samples_; }
  std::uint64_t successes() const { return successes_; }

 private:
  double delta_, alpha_;
  std::uint64_t next_look_;
  int looks_ = 0;
  std::uint64_t samples_ = 0, successes_ = 0;
  Interval interval_;
  bool done_ = false;
};

/// Bayesian estimation with a Beta(a, b) prior: it stops once the posterior gives the interval
/// of width 2 delta around the posterior mean (moved inside [0, 1]) at least `coverage`.
class BayesianInterval {
 public:
  BayesianInterval(double delta, double coverage, double a = 1, double b = 1);
  bool add(bool satisfied);
  bool done() const { return done_; }
  Interval interval() const { return interval_; }
  double estimate() const;  // the posterior mean
  /// The posterior probability of interval().
  double posterior() const { return posterior_; }
  std::uint64_t samples() const { return samples_; }

 private:
  double delta_, coverage_, a_, b_;
  std::uint64_t samples_ = 0, successes_ = 0;
  Interval interval_;
  double posterior_ = 0;
  bool done_ = false;
};

}  // namespace smcbip::smc
