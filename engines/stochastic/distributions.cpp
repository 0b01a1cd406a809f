// Firing-date distributions: parameter checks, GSL CDFs, checked inverses, empirical CDF files.
#include "engines/stochastic/distributions.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <system_error>

namespace smcbip::engines {

using bipc::ir::Distribution;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Relative agreement required between the target probability and the CDF at GSL's inverse.
constexpr double kInverseTolerance = 1e-9;

// How far from 1 the last cdf of an empirical CDF file may be (rounded decimal files).
constexpr double kLastCdfTolerance = 1e-9;

std::string number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// The smallest non-negative double x with pred(x), for pred monotone (false then true) on
// [0, DBL_MAX]: bisection over the bit patterns, which are ordered like the non-negative doubles,
// so at most 63 steps reach the exact boundary.
template <class Pred>
double smallest_nonnegative(Pred pred) {
  std::uint64_t lo = 0;
  std::uint64_t hi = std::bit_cast<std::uint64_t>(std::numeric_limits<double>::max());
  while (lo < hi) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    if (pred(std::bit_cast<double>(mid))) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return std::bit_cast<double>(lo);
}

// GSL's lower-tail inverse `guess` of an iterative solver, accepted when `forward` (the P
// function) agrees with the target w; else the exact boundary by bisection.
template <class Forward>
double checked_lower_inverse(double w, double guess, Forward forward) {
  if (std::isfinite(guess) && guess >= 0.0 &&
      std::abs(forward(guess) - w) <= kInverseTolerance * w) {
    return guess;
  }
  return smallest_nonnegative([&](double x) { return forward(x) >= w; });
}

// The same for an upper-tail inverse, `forward` being the Q function and t the target.
template <class Forward>
double checked_upper_inverse(double t, double guess, Forward forward) {
  if (std::isfinite(guess) && guess >= 0.0 &&
      std::abs(forward(guess) - t) <= kInverseTolerance * t) {
    return guess;
  }
  return smallest_nonnegative([&](double x) { return forward(x) <= t; });
}

bool nonnegative_support(Distribution kind) {
  switch (kind) {
    case Distribution::Exponential:
    case Distribution::Gamma:
    case Distribution::Chi2:
    case Distribution::Lognormal:
    case Distribution::Weibull:
      return true;
    case Distribution::Normal:
    case Distribution::Uniform:
    case Distribution::Custom:
      return false;
  }
  return false;
}

// The written form of each parametric distribution and the names of its parameters.
struct Signature {
  const char* written;
  std::size_t count;
  std::array<const char*, 2> names;
};

Signature signature(Distribution kind) {
  switch (kind) {
    case Distribution::Normal:
      return {"normal(mean, sd)", 2, {"mean", "sd"}};
    case Distribution::Exponential:
      return {"exponential(mean)", 1, {"mean", ""}};
    case Distribution::Gamma:
      return {"gamma(shape, scale)", 2, {"shape", "scale"}};
    case Distribution::Chi2:
      return {"chi2(k)", 1, {"k", ""}};
    case Distribution::Uniform:
      return {"uniform(a, b)", 2, {"a", "b"}};
    case Distribution::Lognormal:
      return {"lognormal(zeta, sigma)", 2, {"zeta", "sigma"}};
    case Distribution::Weibull:
      return {"weibull(scale, shape)", 2, {"scale", "shape"}};
    case Distribution::Custom:
      return {"custom", 0, {"", ""}};
  }
  return {"?", 0, {"", ""}};
}

// Which parameters must be strictly positive.
std::array<bool, 2> positive_params(Distribution kind) {
  switch (kind) {
    case Distribution::Normal:
    case Distribution::Lognormal:
      return {false, true};
    case Distribution::Exponential:
    case Distribution::Chi2:
      return {true, false};
    case Distribution::Gamma:
    case Distribution::Weibull:
      return {true, true};
    case Distribution::Uniform:
    case Distribution::Custom:
      return {false, false};
  }
  return {false, false};
}

}  // namespace

const char* distribution_name(Distribution distribution) {
  switch (distribution) {
    case Distribution::Normal:
      return "normal";
    case Distribution::Exponential:
      return "exponential";
    case Distribution::Gamma:
      return "gamma";
    case Distribution::Chi2:
      return "chi2";
    case Distribution::Uniform:
      return "uniform";
    case Distribution::Lognormal:
      return "lognormal";
    case Distribution::Weibull:
      return "weibull";
    case Distribution::Custom:
      return "custom";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
// DateDistribution

std::variant<DateDistribution, std::string> DateDistribution::make(Distribution kind,
                                                                   std::span<const double> params,
                                                                   const EmpiricalCdf* custom) {
  // Once per process, before any GSL call of ours (thread-safe static initialisation).
  static const bool gsl_handler_off = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  static_cast<void>(gsl_handler_off);

  if (kind == Distribution::Custom) {
    if (!params.empty()) {
      return "custom takes no numeric parameters (its CDF comes from a file), got " +
             std::to_string(params.size());
    }
    if (custom == nullptr) return std::string("custom: no empirical CDF given");
    return DateDistribution(kind, {0.0, 0.0}, custom);
  }
  const Signature sig = signature(kind);
  if (params.size() != sig.count) {
    return std::string(sig.written) + " takes " + std::to_string(sig.count) + " parameter" +
           (sig.count == 1 ? "" : "s") + ", got " + std::to_string(params.size());
  }
  const std::array<bool, 2> positive = positive_params(kind);
  std::array<double, 2> values{0.0, 0.0};
  for (std::size_t i = 0; i < params.size(); ++i) {
    values[i] = params[i];
    const char* wrong = !std::isfinite(params[i])           ? " must be a finite number, got "
                        : positive[i] && !(params[i] > 0.0) ? " must be > 0, got "
                                                            : nullptr;
    if (wrong != nullptr) {
      return std::string(sig.written) + ": " + sig.names[i] + wrong + number(params[i]);
    }
  }
  if (kind == Distribution::Uniform && !(values[0] < values[1])) {
    return std::string(sig.written) + ": needs a < b, got a = " + number(values[0]) +
           ", b = " + number(values[1]);
  }
  return DateDistribution(kind, values, nullptr);
}

double DateDistribution::cdf(double x) const {
  const double a = params_[0];
  const double b = params_[1];
  if (nonnegative_support(kind_) && x <= 0.0) return 0.0;
  switch (kind_) {
    case Distribution::Normal:
      return gsl_cdf_gaussian_P(x - a, b);
    case Distribution::Exponential:
      return gsl_cdf_exponential_P(x, a);
    case Distribution::Gamma:
      return gsl_cdf_gamma_P(x, a, b);
    case Distribution::Chi2:
      return gsl_cdf_chisq_P(x, a);
    case Distribution::Uniform:
      return gsl_cdf_flat_P(x, a, b);
    case Distribution::Lognormal:
      return gsl_cdf_lognormal_P(x, a, b);
    case Distribution::Weibull:
      return gsl_cdf_weibull_P(x, a, b);
    case Distribution::Custom:
      return custom_->cdf(x);
  }
  return 0.0;
}

double DateDistribution::survival(double x) const {
  const double a = params_[0];
  const double b = params_[1];
  if (nonnegative_support(kind_) && x <= 0.0) return 1.0;
  switch (kind_) {
    case Distribution::Normal:
      return gsl_cdf_gaussian_Q(x - a, b);
    case Distribution::Exponential:
      return gsl_cdf_exponential_Q(x, a);
    case Distribution::Gamma:
      return gsl_cdf_gamma_Q(x, a, b);
    case Distribution::Chi2:
      return gsl_cdf_chisq_Q(x, a);
    case Distribution::Uniform:
      return gsl_cdf_flat_Q(x, a, b);
    case Distribution::Lognormal:
      return gsl_cdf_lognormal_Q(x, a, b);
    case Distribution::Weibull:
      return gsl_cdf_weibull_Q(x, a, b);
    case Distribution::Custom:
      return 1.0 - custom_->cdf(x);
  }
  return 0.0;
}

double DateDistribution::lower_quantile(double w) const {
  const double a = params_[0];
  const double b = params_[1];
  switch (kind_) {
    case Distribution::Normal:
      return a + gsl_cdf_gaussian_Pinv(w, b);
    case Distribution::Exponential:
      return gsl_cdf_exponential_Pinv(w, a);
    case Distribution::Gamma:
      return checked_lower_inverse(w, gsl_cdf_gamma_Pinv(w, a, b),
                                   [a, b](double x) { return gsl_cdf_gamma_P(x, a, b); });
    case Distribution::Chi2:
      return checked_lower_inverse(w, gsl_cdf_chisq_Pinv(w, a),
                                   [a](double x) { return gsl_cdf_chisq_P(x, a); });
    case Distribution::Uniform:
      return gsl_cdf_flat_Pinv(w, a, b);
    case Distribution::Lognormal:
      return gsl_cdf_lognormal_Pinv(w, a, b);
    case Distribution::Weibull:
      return gsl_cdf_weibull_Pinv(w, a, b);
    case Distribution::Custom:
      return custom_->inverse(w);
  }
  return 0.0;
}

double DateDistribution::upper_quantile(double t) const {
  const double a = params_[0];
  const double b = params_[1];
  switch (kind_) {
    case Distribution::Normal:
      return a + gsl_cdf_gaussian_Qinv(t, b);
    case Distribution::Exponential:
      return gsl_cdf_exponential_Qinv(t, a);
    case Distribution::Gamma:
      return checked_upper_inverse(t, gsl_cdf_gamma_Qinv(t, a, b),
                                   [a, b](double x) { return gsl_cdf_gamma_Q(x, a, b); });
    case Distribution::Chi2:
      return checked_upper_inverse(t, gsl_cdf_chisq_Qinv(t, a),
                                   [a](double x) { return gsl_cdf_chisq_Q(x, a); });
    case Distribution::Uniform:
      return gsl_cdf_flat_Qinv(t, a, b);
    case Distribution::Lognormal:
      return gsl_cdf_lognormal_Qinv(t, a, b);
    case Distribution::Weibull:
      return gsl_cdf_weibull_Qinv(t, a, b);
    case Distribution::Custom:
      return custom_->inverse(1.0 - t);
  }
  return 0.0;
}

double DateDistribution::quantile_of(double w, double t) const {
  return w <= t ? lower_quantile(w) : upper_quantile(t);
}

double DateDistribution::quantile(double p) const {
  if (p <= 0.0) {
    if (kind_ == Distribution::Normal) return -kInfinity;
    if (kind_ == Distribution::Uniform) return params_[0];
    if (kind_ == Distribution::Custom) return custom_->points().front().value;
    return 0.0;
  }
  if (p >= 1.0) {
    if (kind_ == Distribution::Uniform) return params_[1];
    if (kind_ == Distribution::Custom) return custom_->inverse(1.0);
    return kInfinity;
  }
  return quantile_of(p, 1.0 - p);
}

double DateDistribution::sample(RandomStream& random) const {
  return inverse_of_uniform(random.uniform01_open());
}

DateDistribution::Masses DateDistribution::masses(double x) const {
  const double below = cdf(x);
  return {below, below <= 0.5 ? 1.0 - below : survival(x)};
}

std::optional<double> DateDistribution::sample_in_tail(double lower, double u, double x,
                                                       Masses at_lower) const {
  const auto [below, above] = at_lower;
  if (!(below > 0.0)) return x;  // nothing below `lower` to condition away
  if (!(above >= kMinTailMass)) return std::nullopt;
  // u lies below F(lower) (up to rounding, hence the bound): v is uniform in (0, 1).
  const double v = std::min(u / below, 1.0 - 0x1p-53);
  // The conditional law of X given X > lower has cumulative mass F(lower) + v·P(X > lower) at
  // F^-1 of that; its distance to 1 is computed from the tail itself, not by cancellation.
  double y = quantile_of(below + above * v, above * (1.0 - v));
  // Rounding can land on `lower` itself when the tail is a sliver of the support.
  if (!(y > lower)) y = std::nextafter(lower, kInfinity);
  return y;
}

std::string DateDistribution::describe() const {
  if (kind_ == Distribution::Custom) return "custom";
  std::string out = std::string(distribution_name(kind_)) + "(" + number(params_[0]);
  if (signature(kind_).count == 2) out += ", " + number(params_[1]);
  return out + ")";
}

// ---------------------------------------------------------------------------------------------
// EmpiricalCdf

namespace {

// The fields of one line: split at whitespace and commas, up to a `#` comment.
std::vector<std::string_view> fields(std::string_view line) {
  if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> out;
  const auto is_separator = [](char c) {
    return c == ',' || c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  };
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_separator(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_separator(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// A field of the file as an error message quotes it: its first 24 bytes, those that are not
// printable ASCII as \xNN, so that a field of binary bytes or of a megabyte stays one short line.
std::string shown(std::string_view field) {
  constexpr std::size_t kShown = 24;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < field.size() && i < kShown; ++i) {
    const auto c = static_cast<unsigned char>(field[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      out += {'\\', 'x', kHex[c >> 4], kHex[c & 0xf]};
    }
  }
  return field.size() > kShown ? out + "..." : out;
}

std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

std::variant<EmpiricalCdf, std::string> EmpiricalCdf::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return path + ": cannot open the empirical CDF file";
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return path + ": cannot read the empirical CDF file";
  return parse(text, path);
}

std::variant<EmpiricalCdf, std::string> EmpiricalCdf::parse(std::string_view text,
                                                            const std::string& path) {
  std::vector<Point> points;
  std::size_t line_number = 0;
  std::size_t last_point_line = 0;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    const std::string_view line = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view() : text.substr(newline + 1);
    ++line_number;
    const auto error = [&](const std::string& message) {
      return path + ":" + std::to_string(line_number) + ": " + message;
    };

    const std::vector<std::string_view> parts = fields(line);
    if (parts.empty()) continue;
    if (parts.size() != 2) {
      return error("expected two numbers 'value cdf', got " + std::to_string(parts.size()) +
                   " field" + (parts.size() == 1 ? "" : "s"));
    }
    Point point;
    for (int i = 0; i < 2; ++i) {
      const std::optional<double> value = parse_number(parts[i]);
      const char* what = i == 0 ? "value" : "cdf";
      if (!value) return error(std::string(what) + " '" + shown(parts[i]) + "' is not a number");
      if (!std::isfinite(*value)) return error(std::string(what) + " must be finite");
      (i == 0 ? point.value : point.cdf) = *value;
    }
    if (point.cdf < 0.0 || point.cdf > 1.0) {
      return error("cdf must lie in [0, 1], got " + number(point.cdf));
    }
    if (!points.empty() && !(point.value > points.back().value)) {
      return error("values must be strictly increasing: " + number(point.value) + " after " +
                   number(points.back().value));
    }
    if (!points.empty() && point.cdf < points.back().cdf) {
      return error("cdf must be non-decreasing: " + number(point.cdf) + " after " +
                   number(points.back().cdf));
    }
    points.push_back(point);
    last_point_line = line_number;
  }
  if (points.empty()) return path + ": no points (expected lines 'value cdf')";
  if (std::abs(points.back().cdf - 1.0) > kLastCdfTolerance) {
    return path + ":" + std::to_string(last_point_line) + ": the last cdf must be 1, got " +
           number(points.back().cdf);
  }
  points.back().cdf = 1.0;
  return EmpiricalCdf(std::move(points));
}

double EmpiricalCdf::cdf(double x) const {
  if (x < points_.front().value) return 0.0;
  if (x >= points_.back().value) return 1.0;
  // The first point beyond x; it exists and is not the first (x >= v_0, x < v_n).
  const auto next = std::upper_bound(points_.begin(), points_.end(), x,
                                     [](double v, const Point& p) { return v < p.value; });
  const Point& lo = *std::prev(next);
  const Point& hi = *next;
  const double fraction = (x - lo.value) / (hi.value - lo.value);
  return std::min(hi.cdf, lo.cdf + fraction * (hi.cdf - lo.cdf));
}

double EmpiricalCdf::inverse(double u) const {
  // The first point whose cdf reaches u.
  const auto reach = std::lower_bound(points_.begin(), points_.end(), u,
                                      [](const Point& p, double v) { return p.cdf < v; });
  if (reach == points_.begin()) return points_.front().value;
  if (reach == points_.end()) return points_.back().value;
  const Point& lo = *std::prev(reach);  // lo.cdf < u <= reach->cdf, so the slope is positive
  const double fraction = (u - lo.cdf) / (reach->cdf - lo.cdf);
  return std::min(reach->value, lo.value + fraction * (reach->value - lo.value));
}

}  // namespace smcbip::engines
