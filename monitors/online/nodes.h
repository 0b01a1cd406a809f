// The operators of the online monitor. Each reads its operands' signals and appends to its own
// what has become certain: every position's value is final once emitted, so a verdict read
// from the root never changes. Negation is pushed to the leaves (G, R and the duals of F, U
// are the same operators with values flipped on the way in and out), which is what lets a
// run cut short be finished twice, once with unknown leaves read as false, once as true.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "monitors/online/signal.h"

namespace smcbip::monitors::online {

/// The signals of a monitor's subformulas (one per node, operands first) and its segments.
struct Signals {
  std::vector<Signal> of;
  Segments segments;
};

/// A subformula: `advance` reads what its operands' signals gained and emits into its own.
class Node {
 public:
  virtual ~Node() = default;
  virtual std::unique_ptr<Node> clone() const = 0;
  /// Becomes a copy of `blank`, a node of the same type, without allocating.
  virtual void restart(const Node& blank) = 0;
  virtual void advance(Signals& s) = 0;
  /// The oldest segment it may still ask about (X and step bounds), or -1.
  virtual std::int64_t segment_needed(const Signals&) const { return -1; }
  /// The run is observed up to `end` only: positions after it do not exist for the windows
  /// (what is not found by then never is).
  virtual void close(Pos /*end*/) {}
  /// F and G: the first position of the run that decides them at the start (holds phi for
  /// F, fails it for G), kForever when none has been read.
  virtual Pos first_hit() const { return kForever; }
};

/// A reader of an operand's signal.
struct Operand {
  std::size_t node = 0;
  std::size_t reader = 0;
};

/// Leaves (predicates, constants) are fed by the monitor; their signal is all they have.
class Leaf final : public Node {
 public:
  std::unique_ptr<Node> clone() const override { return std::make_unique<Leaf>(*this); }
  void restart(const Node& blank) override { *this = static_cast<const Leaf&>(blank); }
  void advance(Signals&) override {}
};

/// x && y, or x || y: positions known on both sides, or where the side ahead already decides
/// (false for &&, true for ||).
class Junction final : public Node {
 public:
  Junction(std::size_t self, Operand x, Operand y, bool disjunction)
      : self_(self), x_(x), y_(y), decisive_(disjunction) {}
  std::unique_ptr<Node> clone() const override { return std::make_unique<Junction>(*this); }
  void restart(const Node& blank) override { *this = static_cast<const Junction&>(blank); }
  void advance(Signals& s) override;

 private:
  std::size_t self_;
  Operand x_, y_;
  bool decisive_;  // the value that decides alone
};

/// X phi: on the positions of a step, phi at the first position of the next; on the last step
/// of a run that ends there (it lasts forever), phi itself.
class Next final : public Node {
 public:
  Next(std::size_t self, Operand phi) : self_(self), phi_(phi) {}
  std::unique_ptr<Node> clone() const override { return std::make_unique<Next>(*this); }
  void restart(const Node& blank) override { *this = static_cast<const Next&>(blank); }
  void advance(Signals& s) override;
  std::int64_t segment_needed(const Signals&) const override { return segment_; }

 private:
  std::size_t self_;
  Operand phi_;
  std::int64_t segment_ = 0;  // the step whose positions are emitted next
};

/// How a bound counts: time (ticks) or steps.
enum class Axis : std::uint8_t { Time, Steps };

/// The window [low, high] of a bounded operator, on its axis. `pointwise`: time is read at
/// steps only, every position of a step taking the step's time (the positions of the unknown
/// rest of a run cut short keep their own).
struct Window {
  Axis axis = Axis::Time;
  Tick low = 0, high = kNever;
  bool pointwise = false;
};

/// What the bounded operators share: the window, the emission of found and settled spans,
/// and the translation between positions and the axis.
class Bounded : public Node {
 public:
  std::int64_t segment_needed(const Signals& s) const override;
  void close(Pos end) override { end_ = end; }

 protected:
  Bounded(std::size_t self, Window window, bool dual) : self_(self), w_(window), dual_(dual) {}

  /// The axis value of position `p`.
  Tick key(Pos p, const Signals& s) const;
  /// The first position whose axis value is at least `k` (k clamped to the run).
  Pos first_at(Tick k, const Signals& s) const;
  /// The last position whose axis value is at most `k` (time axis only).
  Pos last_at(Tick k, const Signals& s) const;

  /// The positions `from`..`to` found (a witness lies in their window); those between the
  /// last emitted and `from` are certain not to be.
  void found(Signals& s, Pos from, Pos to) const;
  /// The positions from..to hold what the operator looks for: every position from `floor` on
  /// whose window holds one of them is found.
  void witnesses(Signals& s, Pos from, Pos to, Pos floor) const;
  /// The positions whose windows hold an axis value of [first, last], from `floor` on, are
  /// found (kNever: no last).
  void reach(Signals& s, Tick first, Tick last, Pos floor) const;
  /// Every position up to `to` not found yet never will be.
  void settle(Signals& s, Pos to) const;
  /// The positions whose window starts at or after `from` (for `from` the first position a
  /// future witness may have): the last before them is settled.
  Pos settled_before(Pos from, const Signals& s) const;

  std::size_t self_;
  Window w_;
  bool dual_;           // values flipped on the way in and out: G from F, R from U
  Pos end_ = kForever;  // the last position observed
};

/// F[a,b] phi: some position of the window holds phi; dual: G[a,b] phi.
class Finally final : public Bounded {
 public:
  Finally(std::size_t self, Operand phi, Window window, bool dual)
      : Bounded(self, window, dual), phi_(phi) {}
  std::unique_ptr<Node> clone() const override { return std::make_unique<Finally>(*this); }
  void restart(const Node& blank) override { *this = static_cast<const Finally&>(blank); }
  void advance(Signals& s) override;
  Pos first_hit() const override { return first_hit_; }

 private:
  Operand phi_;
  Pos read_ = kNothing;  // the end of the last run of phi read
  Pos first_hit_ = kForever;
};

/// hold U[a,b] goal (non-strict): a position of the window holds goal and every position
/// from here to it (excluded) holds hold; dual: hold R[a,b] goal.
class Until final : public Bounded {
 public:
  Until(std::size_t self, Operand hold, Operand goal, Window window, bool dual)
      : Bounded(self, window, dual), hold_(hold), goal_(goal) {}
  std::unique_ptr<Node> clone() const override { return std::make_unique<Until>(*this); }
  void restart(const Node& blank) override { *this = static_cast<const Until&>(blank); }
  void advance(Signals& s) override;

 private:
  /// One span of positions over which both operands are constant.
  void piece(Signals& s, Pos from, Pos to, bool hold, bool goal);

  Operand hold_, goal_;
  Pos read_ = kNothing;   // the end of the last span read
  bool stretch_ = false;  // the positions from stretch_start_ to read_ all hold `hold`
  Pos stretch_start_;
};

}  // namespace smcbip::monitors::online
