// The truth of a subformula along a run, as the online monitor computes it: runs of equal
// values over positions, appended as they become known and read by the parent subformulas.
//
// Why whole positions are exact for continuous reading: timestamps and bounds are whole ticks
// and bounds are closed, so the set of times where a subformula holds is a union of intervals
// with whole ends, open or closed. Its value at a tick k and on the open (k, k+1) then decide
// it everywhere: position time 2k stands for the tick k, 2k + 1 for the open interval after it
// (`half ticks`), and windows of [a, b] ticks become [2a, 2b]. Several steps may share a
// timestamp: a position is a time and a rank among the positions at that time.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace smcbip::monitors::online {

/// Time in whole ticks (the caller's choice: nanoseconds for runs), or half ticks in positions.
using Tick = std::int64_t;
/// Later than every time of a run; far enough from the limits that bounds added or
/// subtracted never overflow.
inline constexpr Tick kNever = std::numeric_limits<Tick>::max() / 4;
/// The rank that stands for "the last position at its time".
inline constexpr std::int64_t kLastRank = std::numeric_limits<std::int64_t>::max();

struct Pos {
  Tick t = 0;          // in half ticks: even for a tick, odd for the open interval after it
  std::int64_t n = 0;  // rank among the positions at time t; kLastRank: the last of them
  friend auto operator<=>(const Pos&, const Pos&) = default;
};

/// The position right after `p`. A run only ends at (t, n) with n < kLastRank when another
/// position at time t follows, so this is exact.
inline Pos after(Pos p) { return p.n == kLastRank ? Pos{p.t + 1, 0} : Pos{p.t, p.n + 1}; }
/// The position right before `p`, for `p` the first of its run.
inline Pos before(Pos p) { return p.n == 0 ? Pos{p.t - 1, kLastRank} : Pos{p.t, p.n - 1}; }

inline constexpr Pos kFirst{0, 0};
inline constexpr Pos kNothing{-1, kLastRank};  // before the first position
inline constexpr Pos kForever{kNever, kLastRank};

/// `value` holds on every position after the previous run's end up to `end` included.
struct Run {
  Pos end;
  bool value = false;
};

/// A queue of values in a ring of power-of-two capacity: the signals' storage, cheaper than a
/// deque for the one push and one pop most steps make.
template <class T>
class Ring {
 public:
  std::size_t size() const { return tail_ - head_; }
  bool empty() const { return tail_ == head_; }
  T& operator[](std::size_t i) { return items_[(head_ + i) & mask_]; }
  const T& operator[](std::size_t i) const { return items_[(head_ + i) & mask_]; }
  T& back() { return (*this)[size() - 1]; }
  const T& back() const { return (*this)[size() - 1]; }
  void push_back(const T& item) {
    if (size() == items_.size()) grow();
    items_[tail_++ & mask_] = item;
  }
  void pop_front() { ++head_; }
  /// Empties the ring, keeping its storage.
  void clear() { head_ = tail_ = 0; }

 private:
  void grow() {
    std::vector<T> bigger(std::max<std::size_t>(8, 2 * items_.size()));
    for (std::size_t i = 0; i < size(); ++i) bigger[i] = (*this)[i];
    tail_ = size();
    head_ = 0;
    items_ = std::move(bigger);
    mask_ = items_.size() - 1;
  }

  std::vector<T> items_;
  std::size_t head_ = 0, tail_ = 0, mask_ = 0;
};

/// A subformula's truth from the first position on, as far as it is known. Each reader (a
/// parent) has a cursor; runs every cursor has passed are dropped, so a signal holds only what
/// lies between its slowest reader and what is known.
class Signal {
 public:
  /// A new reader, starting at the first run.
  std::size_t add_reader() {
    cursors_.push_back(base_);
    return cursors_.size() - 1;
  }

  /// Appends `value` up to `end` (after the last end). It extends the last run when no reader
  /// has passed it yet.
  void emit(Pos end, bool value) {
    if (!runs_.empty() && runs_.back().value == value && passed_ < base_ + runs_.size()) {
      runs_.back().end = end;
    } else {
      runs_.push_back({end, value});
    }
    frontier_ = end;
  }

  /// The end of the last run: everything up to it is known.
  Pos frontier() const { return frontier_; }

  /// The reader's current run, or null when it has read every run.
  const Run* peek(std::size_t reader) const {
    const std::size_t at = cursors_[reader];
    return at < base_ + runs_.size() ? &runs_[at - base_] : nullptr;
  }
  void pop(std::size_t reader) {
    const std::size_t at = ++cursors_[reader];
    passed_ = std::max(passed_, at);
  }

  /// Drops the runs every reader has passed.
  void trim() {
    if (cursors_.empty()) return;
    std::size_t low = cursors_[0];
    for (std::size_t c : cursors_) low = std::min(low, c);
    while (base_ < low) {
      runs_.pop_front();
      ++base_;
    }
  }

  std::size_t size() const { return runs_.size(); }

  /// Becomes a copy of `blank`, a signal of the same readers that holds no run yet, keeping
  /// its storage.
  void restart(const Signal& blank) {
    runs_.clear();
    base_ = blank.base_;
    passed_ = blank.passed_;
    cursors_ = blank.cursors_;
    frontier_ = blank.frontier_;
  }

 private:
  Ring<Run> runs_;
  std::size_t base_ = 0;    // the index of runs_[0] since the first run
  std::size_t passed_ = 0;  // the furthest cursor: runs before it were read whole
  std::vector<std::size_t> cursors_;
  Pos frontier_ = kNothing;
};

/// The starts of the run's steps (segments), for the operators that count steps (X, step
/// bounds). It keeps those that some reader may still ask about.
class Segments {
 public:
  void push(Pos start) { starts_.push_back(start); }
  /// No step follows the last one: it lasts forever. `unknown`: it stands for the unknown
  /// rest of a run cut short, whose steps may come at any later time.
  void finish(bool unknown = false) {
    finished_ = true;
    unknown_tail_ = unknown;
  }
  bool unknown_tail() const { return unknown_tail_; }
  /// No segment yet, keeping the storage.
  void restart() {
    starts_.clear();
    base_ = 0;
    finished_ = unknown_tail_ = false;
  }

  std::int64_t count() const { return base_ + static_cast<std::int64_t>(starts_.size()); }
  /// Whether segment `i` is the last and lasts forever.
  bool is_last(std::int64_t i) const { return finished_ && i == count() - 1; }
  /// The first position of segment `i`; segments dropped already read as the oldest kept.
  Pos start(std::int64_t i) const {
    return starts_[static_cast<std::size_t>(std::clamp<std::int64_t>(i - base_, 0, size() - 1))];
  }
  /// The segment holding `p`, as far as the segments are known.
  std::int64_t index_of(Pos p) const {
    // The last start at or before p, by bisection over the kept starts.
    std::size_t low = 0, high = starts_.size();
    while (high - low > 1) {
      const std::size_t middle = low + (high - low) / 2;
      (starts_[middle] <= p ? low : high) = middle;
    }
    return base_ + static_cast<std::int64_t>(low);
  }

  /// The first kept segment starting at half tick `t` or later, count() when none does.
  std::int64_t first_from(Tick t) const {
    std::size_t low = 0, high = starts_.size();  // the answer lies in [low, high]
    while (low < high) {
      const std::size_t middle = low + (high - low) / 2;
      if (starts_[middle].t >= t) {
        high = middle;
      } else {
        low = middle + 1;
      }
    }
    return base_ + static_cast<std::int64_t>(low);
  }

  /// Drops the segments before `i` (keeping at least the last).
  void drop_before(std::int64_t i) {
    while (base_ < i && starts_.size() > 1) {
      starts_.pop_front();
      ++base_;
    }
  }

 private:
  std::int64_t size() const { return static_cast<std::int64_t>(starts_.size()); }

  Ring<Pos> starts_;
  std::int64_t base_ = 0;
  bool finished_ = false, unknown_tail_ = false;
};

}  // namespace smcbip::monitors::online
