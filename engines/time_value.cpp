// Model time: formatting and interval arithmetic.
#include "engines/api/time_value.h"

#include <algorithm>

namespace smcbip::engines {

TimeValue nanoseconds_per(bipc::TimeUnit unit) {
  switch (unit) {
    case bipc::TimeUnit::Nanosecond:
      return 1;
    case bipc::TimeUnit::Microsecond:
      return 1'000;
    case bipc::TimeUnit::Millisecond:
      return 1'000'000;
    case bipc::TimeUnit::Second:
      return 1'000'000'000;
    case bipc::TimeUnit::Minute:
      return 60'000'000'000;
    case bipc::TimeUnit::Hour:
      return 3'600'000'000'000;
    case bipc::TimeUnit::Day:
      return 86'400'000'000'000;
  }
  return 1'000'000;
}

std::string format_time(TimeValue t) {
  if (t == kPlusInfinity) return "+INFTY";
  if (t == kMinusInfinity) return "-INFTY";
  if (t == 0) return "0";
  std::string text = t < 0 ? "-" : "";
  // Magnitude as unsigned: -t overflows for the smallest value, which is -INFTY anyway.
  std::uint64_t rest =
      t < 0 ? static_cast<std::uint64_t>(-(t + 1)) + 1 : static_cast<std::uint64_t>(t);
  static constexpr struct {
    std::uint64_t ns;
    const char* unit;
  } kParts[] = {{86'400'000'000'000, "day"},
                {3'600'000'000'000, "hr"},
                {60'000'000'000, "min"},
                {1'000'000'000, "s"},
                {1'000'000, "ms"},
                {1'000, "us"},
                {1, "ns"}};
  for (const auto& part : kParts) {
    const std::uint64_t count = rest / part.ns;
    rest %= part.ns;
    if (count != 0) text += std::to_string(count) + part.unit;
  }
  return text;
}

std::string format_interval(const Interval& interval) {
  std::string text = interval.left_open ? "] " : "[ ";
  text += format_time(interval.left);
  text += ", ";
  text += format_time(interval.right);
  text += interval.right_open ? " [" : " ]";
  return text;
}

const char* urgency_name(bipc::Urgency urgency) {
  switch (urgency) {
    case bipc::Urgency::Lazy:
      return "lazy";
    case bipc::Urgency::Delayable:
      return "delayable";
    case bipc::Urgency::Eager:
      return "eager";
  }
  return "lazy";
}

}  // namespace smcbip::engines
