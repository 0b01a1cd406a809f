// The reader of empirical CDF files driven from memory, for the fuzzer and its regression replay.
#include "fuzz_cdf.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "engines/stochastic/distributions.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines::fuzz {

namespace {

/// Longer messages echo too much of the input to be read.
constexpr std::size_t kMaxMessage = 300;

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "empirical CDF: %s\n", what.c_str());
  std::abort();
}

void check_message(const std::string& message) {
  if (!message.starts_with("fuzz.cdf:")) broken("message does not name the file: " + message);
  if (message.size() > kMaxMessage)
    broken("message of " + std::to_string(message.size()) + " bytes");
  if (message.find('\n') != std::string::npos || message.find('\0') != std::string::npos) {
    broken("message holds a newline or NUL byte");
  }
}

void check_cdf(const EmpiricalCdf& cdf) {
  const std::vector<EmpiricalCdf::Point>& points = cdf.points();
  if (points.empty() || points.back().cdf != 1.0) broken("no points, or a last cdf other than 1");
  const double low = points.front().value, high = points.back().value;
  std::vector<double> xs{-std::numeric_limits<double>::infinity(), std::nextafter(low, -INFINITY)};
  for (std::size_t i = 0; i < points.size(); ++i) {
    xs.push_back(points[i].value);
    if (i + 1 < points.size()) xs.push_back(points[i].value / 2 + points[i + 1].value / 2);
  }
  xs.push_back(std::nextafter(high, INFINITY));
  xs.push_back(std::numeric_limits<double>::infinity());
  double previous = 0.0;
  for (const double x : xs) {
    const double f = cdf.cdf(x);
    if (!(f >= previous && f <= 1.0)) {
      broken("cdf(" + std::to_string(x) + ") = " + std::to_string(f) + " after " +
             std::to_string(previous));
    }
    previous = f;
  }
  double last = low;
  for (int i = 0; i <= 64; ++i) {
    const double u = i / 64.0;
    const double x = cdf.inverse(u);
    if (!(x >= last && x <= high)) {
      broken("inverse(" + std::to_string(u) + ") = " + std::to_string(x) + " after " +
             std::to_string(last) + ", values up to " + std::to_string(high));
    }
    last = x;
  }
  const auto made = DateDistribution::make(bipc::ir::Distribution::Custom, {}, &cdf);
  if (!std::holds_alternative<DateDistribution>(made)) broken(std::get<std::string>(made));
  const DateDistribution& d = std::get<DateDistribution>(made);
  RandomStream random(1, 0);
  for (int i = 0; i < 4; ++i) (void)d.sample(random);
  for (const double lower : {low, (low + high) / 2, high}) (void)d.sample_above(lower, random);
}

}  // namespace

void run_cdf_on(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto parsed = EmpiricalCdf::parse(text, "fuzz.cdf");
  if (const auto* message = std::get_if<std::string>(&parsed)) return check_message(*message);
  check_cdf(std::get<EmpiricalCdf>(parsed));
}

}  // namespace smcbip::engines::fuzz
