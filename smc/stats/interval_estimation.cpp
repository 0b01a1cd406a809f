#include "smc/stats/interval_estimation.h"

#include <algorithm>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>

namespace smcbip::smc {

Interval clopper_pearson(std::uint64_t x, std::uint64_t n, double alpha) {
  const auto xs = static_cast<double>(x), ns = static_cast<double>(n);
  Interval i;
  // Boost's inverse of the incomplete beta converges where GSL's fails (small alpha).
  if (x > 0) i.low = boost::math::ibeta_inv(xs, ns - xs + 1, alpha / 2);
  if (x < n) i.high = boost::math::ibeta_inv(xs + 1, ns - xs, 1 - alpha / 2);
  return i;
}

SequentialInterval::SequentialInterval(double delta, double alpha, std::uint64_t first_look)
    : delta_(delta), alpha_(alpha), next_look_(std::max<std::uint64_t>(first_look, 1)) {}

bool SequentialInterval::add(bool satisfied) {
  if (done_) return true;
  ++samples_;
  successes_ += satisfied ? 1 : 0;
  if (samples_ < next_look_) return false;
  const double level = alpha_ / std::ldexp(1.0, looks_ + 1);
  interval_ = clopper_pearson(successes_, samples_, level);
  ++looks_;
  next_look_ *= 2;
  done_ = interval_.high - interval_.low <= 2 * delta_;
  return done_;
}

double SequentialInterval::estimate() const {
  return samples_ == 0 ? 0.0 : static_cast<double>(successes_) / static_cast<double>(samples_);
}

BayesianInterval::BayesianInterval(double delta, double coverage, double a, double b)
    : delta_(delta), coverage_(coverage), a_(a), b_(b) {}

double BayesianInterval::estimate() const {
  return (static_cast<double>(successes_) + a_) / (static_cast<double>(samples_) + a_ + b_);
}

bool BayesianInterval::add(bool satisfied) {
  if (done_) return true;
  ++samples_;
  successes_ += satisfied ? 1 : 0;
  const double mean = estimate();
  double low = mean - delta_, high = mean + delta_;
  if (low < 0) {
    high = std::min(1.0, 2 * delta_);
    low = 0;
  }
  if (high > 1) {
    low = std::max(0.0, 1 - 2 * delta_);
    high = 1;
  }
  const double pa = static_cast<double>(successes_) + a_;
  const double pb = static_cast<double>(samples_ - successes_) + b_;
  interval_ = {low, high};
  posterior_ = boost::math::ibeta(pa, pb, high) - boost::math::ibeta(pa, pb, low);
  done_ = posterior_ >= coverage_;
  return done_;
}

}  // namespace smcbip::smc
