#include "monitors/online/nodes.h"

#include <algorithm>

namespace smcbip::monitors::online {
namespace {

/// The operand's first run that ends at or after `from` (earlier ones are dropped), or null.
const Run* run_from(Signal& signal, std::size_t reader, Pos from) {
  const Run* run = signal.peek(reader);
  while (run != nullptr && run->end < from) {
    signal.pop(reader);
    run = signal.peek(reader);
  }
  return run;
}

}  // namespace

void Junction::advance(Signals& s) {
  Signal& out = s.of[self_];
  Signal& x = s.of[x_.node];
  Signal& y = s.of[y_.node];
  while (out.frontier() != kForever) {
    const Pos next = after(out.frontier());
    const Run* rx = run_from(x, x_.reader, next);
    const Run* ry = run_from(y, y_.reader, next);
    if (rx != nullptr && ry != nullptr) {
      const bool value = decisive_ ? rx->value || ry->value : rx->value && ry->value;  // || or &&
      out.emit(std::min(rx->end, ry->end), value);
    } else if (rx != nullptr && rx->value == decisive_) {
      out.emit(rx->end, decisive_);
    } else if (ry != nullptr && ry->value == decisive_) {
      out.emit(ry->end, decisive_);
    } else {
      break;
    }
  }
}

void Next::advance(Signals& s) {
  Signal& out = s.of[self_];
  Signal& phi = s.of[phi_.node];
  while (out.frontier() != kForever) {
    if (s.segments.is_last(segment_)) {
      // The last step lasts forever: the next state is the same one, position by position.
      const Run* run = run_from(phi, phi_.reader, after(out.frontier()));
      if (run == nullptr) return;
      out.emit(run->end, run->value);
      continue;
    }
    if (segment_ + 1 >= s.segments.count()) return;
    const Pos next_start = s.segments.start(segment_ + 1);
    const Run* run = run_from(phi, phi_.reader, next_start);
    if (run == nullptr) return;
    out.emit(before(next_start), run->value);
    ++segment_;
  }
}

std::int64_t Bounded::segment_needed(const Signals& s) const {
  if (w_.axis == Axis::Time && !w_.pointwise) return -1;
  const Pos next = after(s.of[self_].frontier());
  if (next > kForever) return s.segments.count() - 1;
  if (w_.axis == Axis::Steps) return std::max<std::int64_t>(0, key(next, s) - w_.high);
  const std::int64_t window = s.segments.first_from(key(next, s) - w_.high);
  return std::max<std::int64_t>(0, std::min(s.segments.index_of(next), window) - 1);
}

Tick Bounded::key(Pos p, const Signals& s) const {
  if (w_.axis == Axis::Steps || !w_.pointwise) {
    if (p >= kForever) return kNever;
    return w_.axis == Axis::Steps ? s.segments.index_of(p) : p.t;
  }
  // Pointwise: a step's time, also for the last step of a deadlocked run, which no later
  // time follows.
  const std::int64_t i = s.segments.index_of(p);
  if (s.segments.is_last(i) && s.segments.unknown_tail()) return p >= kForever ? kNever : p.t;
  return s.segments.start(i).t;
}

Pos Bounded::first_at(Tick k, const Signals& s) const {
  if (k <= 0) return kFirst;
  if (k >= kNever) return kForever;
  if (w_.axis == Axis::Steps) return s.segments.start(k);
  if (!w_.pointwise) return {k, 0};
  const std::int64_t i = s.segments.first_from(k);
  if (i < s.segments.count()) return s.segments.start(i);
  const Pos last = s.segments.start(s.segments.count() - 1);
  if (s.segments.unknown_tail()) return std::max(last, Pos{k, 0});
  return s.segments.is_last(s.segments.count() - 1) ? kForever : std::max(after(last), Pos{k, 0});
}

Pos Bounded::last_at(Tick k, const Signals& s) const {
  if (!w_.pointwise) return {k, kLastRank};
  const std::int64_t i = s.segments.first_from(k + 1);
  if (i < s.segments.count()) return before(s.segments.start(i));
  return s.segments.unknown_tail() ? Pos{k, kLastRank} : kForever;
}

void Bounded::found(Signals& s, Pos from, Pos to) const {
  Signal& out = s.of[self_];
  const Pos next = after(out.frontier());
  if (to < from || to < next) return;
  if (from > next) out.emit(before(from), dual_);
  out.emit(to, !dual_);
}

void Bounded::settle(Signals& s, Pos to) const {
  Signal& out = s.of[self_];
  if (to > out.frontier()) out.emit(to, dual_);
}

Pos Bounded::settled_before(Pos from, const Signals& s) const {
  return before(first_at(key(from, s) - w_.high, s));
}

void Bounded::witnesses(Signals& s, Pos from, Pos to, Pos floor) const {
  if (w_.low == 0) {
    // The witness nearest a position is the first one after it: from, or itself.
    found(s, std::max(floor, first_at(key(from, s) - w_.high, s)), to);
  } else if (!w_.pointwise) {
    reach(s, key(from, s), key(to, s), floor);
  } else {
    // Pointwise: the times of the steps in from..to, which the windows must hold themselves.
    const Segments& segments = s.segments;
    for (std::int64_t i = segments.index_of(from); i < segments.count(); ++i) {
      const Pos start = std::max(from, segments.start(i));
      if (start > to) break;
      if (segments.is_last(i) && segments.unknown_tail()) {
        reach(s, key(start, s), key(to, s), floor);
        break;
      }
      reach(s, key(start, s), key(start, s), floor);
    }
  }
}

void Bounded::reach(Signals& s, Tick first, Tick last, Pos floor) const {
  const Pos to = last >= kNever ? kForever : last_at(last - w_.low, s);
  found(s, std::max(floor, first_at(first - w_.high, s)), to);
}

void Finally::advance(Signals& s) {
  Signal& phi = s.of[phi_.node];
  while (const Run* run = phi.peek(phi_.reader)) {
    const Pos from = after(read_);
    if (run->value != dual_ && from <= end_) {
      first_hit_ = std::min(first_hit_, from);
      witnesses(s, from, std::min(run->end, end_), kFirst);
    }
    read_ = run->end;
    phi.pop(phi_.reader);
  }
  if (read_ == kForever) {
    settle(s, kForever);
  } else if (read_ != kNothing) {
    settle(s, settled_before(after(read_), s));
  }
}

void Until::advance(Signals& s) {
  Signal& hold = s.of[hold_.node];
  Signal& goal = s.of[goal_.node];
  for (;;) {
    const Run* rh = hold.peek(hold_.reader);
    const Run* rg = goal.peek(goal_.reader);
    if (rh == nullptr || rg == nullptr) break;
    const Pos to = std::min(rh->end, rg->end);
    const bool h = rh->value != dual_, g = rg->value != dual_;
    if (rh->end == to) hold.pop(hold_.reader);
    if (rg->end == to) goal.pop(goal_.reader);
    Pos from = after(read_);
    if (from <= end_ && to > end_) {  // no witness after the end of the observation
      piece(s, from, end_, h, g);
      from = after(end_);
    }
    piece(s, from, to, h, g && from <= end_);
    read_ = to;
  }
  if (read_ == kForever) {
    settle(s, kForever);
  } else if (stretch_ && read_ != kNothing) {
    settle(s, settled_before(after(read_), s));
  }
}

void Until::piece(Signals& s, Pos from, Pos to, bool hold, bool goal) {
  if (hold) {
    if (!stretch_) {
      stretch_ = true;
      stretch_start_ = from;
    }
    // Witnesses from..to, reached from anywhere in the stretch through positions that hold.
    if (goal) witnesses(s, from, to, stretch_start_);
    return;
  }
  if (stretch_) {
    // The stretch ends: its positions can still reach `from` as a witness, and nothing beyond;
    // but not an open interval (odd), part of which they would have to hold over.
    if (goal && from.t % 2 == 0) witnesses(s, from, from, stretch_start_);
    settle(s, before(from));
    stretch_ = false;
  }
  // Outside a stretch only a witness at the position itself counts.
  if (goal && w_.low == 0) {
    found(s, from, to);
  } else {
    settle(s, to);
  }
}

}  // namespace smcbip::monitors::online
