#include "smc/stats/sprt.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace smcbip::smc {

Sprt::Sprt(double theta, double delta, double alpha, double beta)
    : p0_(std::min(1.0, theta + delta)), p1_(std::max(0.0, theta - delta)) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // At p0 = 1 a single failure refutes H0; at p1 = 0 a single success refutes H1.
  on_success_ = p1_ <= 0 ? -kInf : std::log(p1_ / p0_);
  on_failure_ = p0_ >= 1 ? kInf : std::log((1 - p1_) / (1 - p0_));
  accept_ = std::log(beta / (1 - alpha));
  reject_ = std::log((1 - beta) / alpha);
}

Decision Sprt::add(bool satisfied) {
  if (decision_ != Decision::Undecided) return decision_;
  ++samples_;
  successes_ += satisfied ? 1 : 0;
  log_ratio_ += satisfied ? on_success_ : on_failure_;
  if (log_ratio_ <= accept_) decision_ = Decision::AtLeast;
  if (log_ratio_ >= reject_) decision_ = Decision::Below;
  return decision_;
}

}  // namespace smcbip::smc
