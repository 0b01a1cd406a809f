// Model time: exact integer nanoseconds, intervals with open or closed ends, and the reference
// engine's printed forms ("1s500ms", "[ 0, +INFTY [").
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "bipc/timing.h"

namespace smcbip::engines {

/// A point of model time in nanoseconds. The extreme values stand for -INFTY and +INFTY.
using TimeValue = std::int64_t;
inline constexpr TimeValue kPlusInfinity = std::numeric_limits<TimeValue>::max();
inline constexpr TimeValue kMinusInfinity = std::numeric_limits<TimeValue>::min();

/// Nanoseconds in one unit of a clock.
TimeValue nanoseconds_per(bipc::TimeUnit unit);

/// The reference engine's form: non-zero components `<d>day<h>hr<m>min<s>s<ms>ms<us>us<ns>ns`,
/// `0` for zero, a leading `-` when negative, `-INFTY` / `+INFTY` for the infinities.
std::string format_time(TimeValue t);

/// A set of time points {t | left (<|<=) t (<|<=) right}; empty when left > right or when they
/// are equal with an open end.
struct Interval {
  TimeValue left = kMinusInfinity;
  TimeValue right = kPlusInfinity;
  bool left_open = false;
  bool right_open = false;

  static Interval all() { return {}; }
  static Interval none() { return {0, -1, false, false}; }
  static Interval point(TimeValue t) { return {t, t, false, false}; }
  static Interval from(TimeValue t) { return {t, kPlusInfinity, false, false}; }

  bool empty() const {
    if (left > right) return true;
    if (left == right) return left_open || right_open;
    // On integer nanoseconds ]t, t+1[ holds no point.
    return left_open && right_open && right - left == 1;
  }
  bool contains(TimeValue t) const {
    if (left_open ? t <= left : t < left) return false;
    return !(right_open ? t >= right : t > right);
  }
  bool bounded() const { return right != kPlusInfinity; }
  /// The smallest point of the set (for an open left end, the next nanosecond).
  TimeValue first() const {
    return left_open && left != kMinusInfinity && left != kPlusInfinity ? left + 1 : left;
  }
  /// The largest point of the set (for an open right end, the previous nanosecond).
  TimeValue last() const {
    return right_open && right != kPlusInfinity && right != kMinusInfinity ? right - 1 : right;
  }
  Interval intersect(const Interval& other) const {
    Interval result = *this;
    if (other.left > left || (other.left == left && other.left_open)) {
      result.left = other.left;
      result.left_open = other.left_open;
    }
    if (other.right < right || (other.right == right && other.right_open)) {
      result.right = other.right;
      result.right_open = other.right_open;
    }
    return result;
  }
  bool operator==(const Interval&) const = default;
};

/// a = a.intersect(b), field by field. Inlined so that `a` stays in registers: through
/// memory, each call stalled on store forwarding.
[[gnu::always_inline]] inline void narrow(Interval& a, const Interval& b) {
  if (b.left > a.left || (b.left == a.left && b.left_open)) {
    a.left = b.left;
    a.left_open = b.left_open;
  }
  if (b.right < a.right || (b.right == a.right && b.right_open)) {
    a.right = b.right;
    a.right_open = b.right_open;
  }
}

/// `[ left, right ]` with `]`/`[` turned for open ends, as the reference engine prints it.
std::string format_interval(const Interval& interval);

/// `lazy`, `delayable` or `eager`.
const char* urgency_name(bipc::Urgency urgency);

}  // namespace smcbip::engines
