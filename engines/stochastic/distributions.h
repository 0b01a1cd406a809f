// Firing-date distributions of stochastic ports: parameter checks, CDFs, empirical CDF files and
// exact, reproducible (truncated) inverse-transform sampling over GSL's CDFs.
//
// Samples are plain doubles in the unit of the port's clock; the caller converts them to model
// time. Every sample consumes exactly one uniform of the run's RandomStream (inverse-transform
// sampling, Devroye, "Non-Uniform Random Variate Generation", 1986, ch. II.2), so a run's dates
// depend only on its stream, not on a distribution-specific rejection loop.
#pragma once

#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

/// The name used in `@stochastic(dist=...)`: "normal", "exponential", ..., "custom".
const char* distribution_name(bipc::ir::Distribution distribution);

/// A piecewise-linear CDF read from a file of `value cdf` points (the `custom` distribution).
///
/// Points (v_0, F_0) ... (v_n, F_n) with v strictly increasing and F non-decreasing in [0, 1],
/// F_n = 1. The CDF is 0 below v_0, F_0 at v_0 (so F_0 is a point mass at v_0: the mass "at or
/// below" the first value), linear between consecutive points, and 1 from v_n on.
class EmpiricalCdf {
 public:
  struct Point {
    double value = 0.0;
    double cdf = 0.0;
  };

  /// Reads and checks the file at `path`: one point per line, value and cdf separated by
  /// whitespace and/or a comma, `#` starts a comment, blank lines are skipped. A last cdf within
  /// 1e-9 of 1 is taken as 1. Errors read "path:line: message" ("path: message" for the whole
  /// file).
  static std::variant<EmpiricalCdf, std::string> load(const std::string& path);

  /// As load(), from text already read; `path` only names the source in error messages.
  static std::variant<EmpiricalCdf, std::string> parse(std::string_view text,
                                                       const std::string& path);

  /// P(X <= x) for the piecewise-linear CDF described above.
  double cdf(double x) const;

  /// The generalised inverse inf{x | cdf(x) >= u} for u in [0, 1]: v_0 for u <= F_0, linear
  /// interpolation between the points bracketing u otherwise.
  double inverse(double u) const;

  /// The checked points, in file order (never empty; the last cdf is exactly 1).
  const std::vector<Point>& points() const { return points_; }

 private:
  explicit EmpiricalCdf(std::vector<Point> points) : points_(std::move(points)) {}
  std::vector<Point> points_;
};

/// A firing-date distribution with checked parameters. Parametrisations (BIP.md, GSL's):
/// normal(mean, sd > 0), exponential(mean > 0), gamma(shape > 0, scale > 0), chi2(k > 0),
/// uniform(a < b), lognormal(zeta, sigma > 0) (log X ~ normal(zeta, sigma)),
/// weibull(scale a > 0, shape b > 0) (CDF 1 - exp(-(x/a)^b)), custom (an EmpiricalCdf, no numbers).
///
/// Cheap to build and copy (no allocation), immutable, safe to share between threads. A custom
/// distribution refers to its EmpiricalCdf, which must outlive it.
///
/// The first distribution built switches GSL's error handler off for the whole process: GSL's
/// default handler aborts on benign underflows and on non-convergence of its iterative inverses;
/// we check GSL's results instead (see quantile()).
class DateDistribution {
 public:
  /// The distribution `kind` with `params`, or a message saying which parameter is wrong
  /// ("normal(mean, sd): sd must be > 0, got -1"). `custom` is required for Custom, ignored
  /// otherwise.
  static std::variant<DateDistribution, std::string> make(bipc::ir::Distribution kind,
                                                          std::span<const double> params,
                                                          const EmpiricalCdf* custom = nullptr);
  /// As above, for a braced list of parameters.
  static std::variant<DateDistribution, std::string> make(bipc::ir::Distribution kind,
                                                          std::initializer_list<double> params,
                                                          const EmpiricalCdf* custom = nullptr) {
    return make(kind, std::span<const double>(params.begin(), params.size()), custom);
  }

  /// Sampling refuses a truncation whose upper tail P(X > lower) is below this (a missed support).
  static constexpr double kMinTailMass = 1e-300;

  bipc::ir::Distribution kind() const { return kind_; }

  /// P(X <= x), from GSL's gsl_cdf_*_P functions (0 below the support).
  double cdf(double x) const;

  /// P(X > x), from GSL's gsl_cdf_*_Q functions: accurate in the upper tail where 1 - cdf(x)
  /// would cancel.
  double survival(double x) const;

  /// The masses on either side of a point.
  struct Masses {
    double below = 0.0;  // P(X <= x)
    double above = 1.0;  // P(X > x)
  };
  /// P(X <= x) and P(X > x) as cdf() and survival() give them, but for the cost of one where
  /// the CDF is at most 1/2: then 1 - cdf(x) is at least 1/2 and within an ulp of survival(x),
  /// its relative error as small as the survival function's own.
  Masses masses(double x) const;

  /// The smallest x with cdf(x) >= p, for p in (0, 1) (the lower end of the support for p <= 0,
  /// the upper end for p >= 1, possibly infinite). Uses GSL's Pinv for p < 1/2 and Qinv of
  /// 1 - p otherwise. GSL's iterative gamma/chi2 inverses fail or are inaccurate in places
  /// (small shapes, far tails): their results are checked against the CDF to a relative 1e-9
  /// and otherwise found by bisection over the doubles.
  double quantile(double p) const;

  /// One date X drawn from the distribution: X = F^-1(u) for one uniform u of the stream.
  double sample(RandomStream& random) const;

  /// One date drawn exactly from X conditioned on X > lower, from one uniform u: X = F^-1(u)
  /// when that lies above `lower`, which needs no CDF (the common case of a truncation in the
  /// lower tail). Otherwise u, uniform below F(lower) given that, is mapped to u / F(lower) and
  /// drawn from by inverse transform restricted to the upper tail: F^-1(F(lower) + v·P(X >
  /// lower)), evaluated as the inverse of the remaining tail mass when that is the smaller side,
  /// so truncations far in the upper tail stay accurate. The two cases together give each x above
  /// `lower` its density f(x) + F(lower)·f(x) / P(X > lower) = f(x) / P(X > lower). Always >
  /// lower, unless no mass lies below `lower` (then F^-1(u) as it is). nullopt when P(X >
  /// lower) < kMinTailMass: the date cannot lie beyond `lower` (a missed support, which the
  /// caller reports as a model error).
  std::optional<double> sample_above(double lower, RandomStream& random) const {
    return sample_above(lower, random, [&] { return masses(lower); });
  }
  /// As above, for a caller that keeps masses(lower): `masses_at()` gives them, called only
  /// when F^-1(u) does not lie above `lower`.
  template <class MassesAt>
  std::optional<double> sample_above(double lower, RandomStream& random, MassesAt masses_at) const {
    double x = 0.0;
    if (!sample_above(lower, random, masses_at, x)) return std::nullopt;
    return x;
  }
  /// As above, the date written to `x`, false for nullopt: a caller on the hot path stores no
  /// optional, whose flag and value the processor could not forward to a whole read. Always
  /// inline: the draw of every step of a Markovian model.
  template <class MassesAt>
  [[gnu::always_inline]] bool sample_above(double lower, RandomStream& random, MassesAt masses_at, double& x) const {
    const double u = random.uniform01_open();
    x = inverse_of_uniform(u);
    if (x > lower) return true;
    const std::optional<double> y = sample_in_tail(lower, u, x, masses_at());
    if (y) x = *y;
    return y.has_value();
  }

  /// The distribution as written in a model, e.g. "normal(10, 2)"; for error messages.
  std::string describe() const;

 private:
  DateDistribution(bipc::ir::Distribution kind, std::array<double, 2> params,
                   const EmpiricalCdf* custom)
      : kind_(kind), params_(params), custom_(custom) {}

  // The smallest x with cdf(x) >= w (lower-tail inverse, w in (0, 1)).
  double lower_quantile(double w) const;
  // The smallest x with survival(x) <= t (upper-tail inverse, t in (0, 1)).
  double upper_quantile(double t) const;
  // The inverse at cumulative mass w = 1 - t, through whichever of w and t is smaller.
  double quantile_of(double w, double t) const;
  // F^-1(u) for u in (0, 1). Inline for the exponential, the distribution of Markovian
  // models, whose draws are a large part of a run's cost; 1 - u is exact for u >= 1/2, the
  // only case where it is used.
  double inverse_of_uniform(double u) const {
    if (kind_ == bipc::ir::Distribution::Exponential) return exponential_inverse(u);
    return quantile_of(u, 1.0 - u);
  }
  // quantile_of(u, 1 - u) for the exponential: GSL's Pinv and Qinv (cdf/exponentialinv.c)
  // with their arithmetic, -mean·log1p(-w) and -mean·log(t), so that the dates are the same
  // to the bit as through GSL.
  double exponential_inverse(double u) const {
    const double t = 1.0 - u;
    return u <= t ? -params_[0] * std::log1p(-u) : -params_[0] * std::log(t);
  }
  // sample_above's second case: u drawn, x = F^-1(u) at or below `lower`.
  std::optional<double> sample_in_tail(double lower, double u, double x, Masses at_lower) const;

  bipc::ir::Distribution kind_;
  std::array<double, 2> params_;
  const EmpiricalCdf* custom_;
};

}  // namespace smcbip::engines
