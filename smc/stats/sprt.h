// Wald's sequential probability ratio test for P>=theta queries (Wald 1945; Younes 2005): the
// indifference region [theta - delta, theta + delta], strength (alpha, beta), in log space.
#pragma once

#include <cstdint>

namespace smcbip::smc {

/// The outcome of a hypothesis test on the probability p that a run satisfies the formula.
enum class Decision : std::uint8_t { Undecided, AtLeast, Below };  // p >= theta, p < theta

class Sprt {
 public:
  /// H0: p >= theta + delta against H1: p <= theta - delta; alpha bounds the chance to decide
  /// Below under H0, beta to decide AtLeast under H1. Bounds outside [0, 1] are clipped.
  Sprt(double theta, double delta, double alpha, double beta);

  /// One run's outcome; returns the decision once the ratio crosses a threshold.
  Decision add(bool satisfied);
  Decision decision() const { return decision_; }
  std::uint64_t samples() const { return samples_; }
  std::uint64_t successes() const { return successes_; }
  /// log(L1 / L0) so far, and the thresholds it is compared with (for progress reports).
  double log_ratio() const { return log_ratio_; }
  double accept_threshold() const { return accept_; }  // at or below: AtLeast
  double reject_threshold() const { return reject_; }  // at or above: Below

 private:
  double p0_, p1_;
  double on_success_, on_failure_;  // log-ratio increments
  double accept_, reject_;
  double log_ratio_ = 0;
  std::uint64_t samples_ = 0, successes_ = 0;
  Decision decision_ = Decision::Undecided;
};

}  // namespace smcbip::smc
