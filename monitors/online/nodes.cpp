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
  if (w_.axis == Axis::Time) return -1;
  const Pos next = after(s.of[self_].frontier());
  if (next > kForever) return s.segments.count() - 1;
  return std::max<std::int64_t>(0, key(next, s) - w_.high);
}

Tick Bounded::key(Pos p, const Signals& s) const {
  if (p >= kForever) return kNever;
  return w_.axis == Axis::Time ? p.t : s.segments.index_of(p);
}

Pos Bounded::first_at(Tick k, const Signals& s) const {
  if (k <= 0) return kFirst;
  if (k >= kNever) return kForever;
  return w_.axis == Axis::Time ? Pos{k, 0} : s.segments.start(k);
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

void Finally::advance(Signals& s) {
  Signal& phi = s.of[phi_.node];
  while (const Run* run = phi.peek(phi_.reader)) {
    const Pos from = after(read_);
    if (run->value != dual_ && from <= end_) {
      first_hit_ = std::min(first_hit_, from);
      // Witnesses from `from` to the run's end: found wherever the window reaches them.
      Pos to = std::min(run->end, end_);
      if (to != kForever && w_.low > 0) to = last_at(key(to, s) - w_.low);
      found(s, first_at(key(from, s) - w_.high, s), to);
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
    if (goal) {
      // Witnesses from..to, reached from anywhere in the stretch through positions that hold.
      Pos end = to;
      if (to != kForever && w_.low > 0) end = last_at(key(to, s) - w_.low);
      found(s, std::max(stretch_start_, first_at(key(from, s) - w_.high, s)), end);
    }
    return;
  }
  if (stretch_) {
    // The stretch ends: its positions can still reach `from` as a witness, and nothing beyond;
    // but not an open interval (odd), part of which they would have to hold over.
    if (goal && from.t % 2 == 0) {
      Pos end = before(from);
      if (w_.low > 0) end = std::min(end, last_at(key(from, s) - w_.low));
      found(s, std::max(stretch_start_, first_at(key(from, s) - w_.high, s)), end);
    }
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
