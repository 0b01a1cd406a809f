// Fixed-size plans: the single sampling plan of a hypothesis test, computed exactly from the
// binomial distribution (Younes 2005), and the Chernoff-Hoeffding sample size of an estimate.
#pragma once

#include <cstdint>

namespace smcbip::smc {

/// n runs; accept p >= theta when more than c of them satisfy the formula.
struct SamplingPlan {
  std::uint64_t n = 0;
  std::uint64_t c = 0;
};

/// The smallest n (with its c) such that, with p0 = theta + delta and p1 = theta - delta,
/// P[X <= c | p0] <= alpha and P[X > c | p1] <= beta for X binomial(n, p).
SamplingPlan single_sampling_plan(double theta, double delta, double alpha, double beta);

/// PESTIM: N = ceil(ln(2 / alpha) / (2 delta^2)) runs estimate p within delta with confidence
/// 1 - alpha (Chernoff-Hoeffding).
std::uint64_t chernoff_samples(double delta, double alpha);

/// DKW's band: the half-width eps = sqrt(ln(2 / alpha) / (2 n)) within which the empirical
/// distribution function of n runs stays everywhere at once, with probability 1 - alpha
/// (Dvoretzky-Kiefer-Wolfowitz with Massart's constant). For one point it is Hoeffding's.
double dkw_half_width(std::uint64_t runs, double alpha);

}  // namespace smcbip::smc
