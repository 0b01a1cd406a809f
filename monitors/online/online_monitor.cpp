#include "monitors/online/online_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace smcbip::monitors {

using online::kForever;
using online::kLastRank;
using online::Pos;
using online::Tick;

namespace {

std::vector<std::unique_ptr<online::Node>> clone_all(
    const std::vector<std::unique_ptr<online::Node>>& nodes) {
  std::vector<std::unique_ptr<online::Node>> copy;
  copy.reserve(nodes.size());
  for (const auto& node : nodes) copy.push_back(node->clone());
  return copy;
}

double seconds_per(TimeUnit unit) {
  switch (unit) {
    case TimeUnit::Seconds:
      return 1.0;
    case TimeUnit::Milliseconds:
      return 1e-3;
    case TimeUnit::Microseconds:
      return 1e-6;
    case TimeUnit::Nanoseconds:
      return 1e-9;
    case TimeUnit::None:
      break;
  }
  return 0.0;
}

/// `v` times `scale`, which must come to a whole number at least 0.
std::int64_t whole(const Value& v, double scale, const Bindings& bindings) {
  double number = v.number;
  if (v.is_name()) {
    const auto it = bindings.find(v.name);
    if (it == bindings.end()) throw MonitorError(v.at, "no value given for '" + v.name + "'");
    number = it->second;
  }
  const double x = number * scale;
  if (!(x >= 0)) throw MonitorError(v.at, "a bound must not be negative");
  if (x >= static_cast<double>(online::kNever / 2)) return online::kNever / 2;
  const double rounded = std::round(x);
  if (std::abs(x - rounded) > 1e-6 * std::max(1.0, x)) {
    throw MonitorError(v.at, "the bound " + (v.is_name() ? v.name : v.text) +
                                 " is finer than the run's time resolution");
  }
  return static_cast<std::int64_t>(rounded);
}

}  // namespace

double divide(const Expr& at, double x, double y) {
  if (y == 0) throw MonitorError(at.at, "division by zero in '" + to_string(at) + "'");
  return x / y;
}

double remainder(const Expr& at, double x, double y) {
  // Whole numbers as C's % takes them, which must fit 64 bits.
  constexpr double kLimit = 9223372036854775808.0;  // 2^63
  if (!(std::abs(x) < kLimit) || !(std::abs(y) < kLimit)) {
    throw MonitorError(
        at.at, "an operand of '" + to_string(at) + "' is beyond the 64-bit integers % takes");
  }
  const auto divisor = static_cast<std::int64_t>(y);
  if (divisor == 0) throw MonitorError(at.at, "remainder by zero in '" + to_string(at) + "'");
  if (divisor == -1) return 0;  // INT64_MIN % -1 overflows
  return static_cast<double>(static_cast<std::int64_t>(x) % divisor);
}

double evaluate(const Expr& e, const StateView& state, const Bindings& bindings) {
  using K = Expr::Kind;
  auto operand = [&](std::size_t k) { return evaluate(*e.operands[k], state, bindings); };
  switch (e.kind) {
    case K::Number:
      return e.value.number;
    case K::Bool:
      return e.boolean ? 1 : 0;
    case K::Name: {
      if (!bindings.empty() && (e.reference.kind == Reference::Kind::Constant ||
                                e.reference.kind == Reference::Kind::Unresolved)) {
        const auto it = bindings.find(e.path);
        if (it != bindings.end()) return it->second;
      }
      return state.value(e);
    }
    case K::Fired:
      return state.fired(e) ? 1 : 0;
    case K::Negate:
      return -operand(0);
    case K::Add:
      return operand(0) + operand(1);
    case K::Subtract:
      return operand(0) - operand(1);
    case K::Multiply:
      return operand(0) * operand(1);
    case K::Divide:
      return divide(e, operand(0), operand(1));
    case K::Modulo:
      return remainder(e, operand(0), operand(1));
    case K::Less:
      return operand(0) < operand(1) ? 1 : 0;
    case K::LessEqual:
      return operand(0) <= operand(1) ? 1 : 0;
    case K::Greater:
      return operand(0) > operand(1) ? 1 : 0;
    case K::GreaterEqual:
      return operand(0) >= operand(1) ? 1 : 0;
    case K::Equal:
      return operand(0) == operand(1) ? 1 : 0;
    case K::NotEqual:
      return operand(0) != operand(1) ? 1 : 0;
    case K::Call:
      if (e.path == "abs") return std::abs(operand(0));
      if (e.path == "min") return std::min(operand(0), operand(1));
      return std::max(operand(0), operand(1));
  }
  return 0;
}

Moment::Moment(const StateView& state, Tick ticks, const TimeScale& scale, bool initial,
               RunEnd end_here)
    : state_(state),
      time_(static_cast<double>(ticks) / scale.ticks_per_unit),
      time_slope_(1.0 / scale.ticks_per_unit),
      initial_(initial),
      end_(end_here) {}

double Moment::value(const Expr& name) const {
  switch (name.reference.kind) {
    case Reference::Kind::Time:
      return time_;
    case Reference::Kind::Initial:
      return initial_ ? 1 : 0;
    case Reference::Kind::Deadlock:
      return end_ == RunEnd::Deadlock ? 1 : 0;
    case Reference::Kind::Timelock:
      return end_ == RunEnd::Timelock ? 1 : 0;
    default:
      return state_.value(name);
  }
}

double Moment::slope(const Expr& name) const {
  if (name.reference.kind == Reference::Kind::Time) return time_slope_;
  return is_builtin(name.reference) ? 0 : state_.slope(name);
}

bool reads_run_end(const Expr& e) {
  if (e.kind == Expr::Kind::Name) {
    return e.reference.kind == Reference::Kind::Deadlock ||
           e.reference.kind == Reference::Kind::Timelock;
  }
  return std::any_of(e.operands.begin(), e.operands.end(),
                     [](const auto& operand) { return reads_run_end(*operand); });
}

bool reads_places_and_data_only(const Expr& e) {
  if (e.kind == Expr::Kind::Fired) return false;
  if (e.kind == Expr::Kind::Name) {
    const Reference::Kind k = e.reference.kind;
    return k != Reference::Kind::Clock && k != Reference::Kind::Time &&
           k != Reference::Kind::Deadlock && k != Reference::Kind::Timelock;
  }
  return std::all_of(e.operands.begin(), e.operands.end(),
                     [](const auto& operand) { return reads_places_and_data_only(*operand); });
}

Tick bound_ticks(const Value& v, const TimeScale& scale, const Bindings& bindings) {
  const double per = v.unit == TimeUnit::None ? scale.ticks_per_unit
                                              : scale.ticks_per_second * seconds_per(v.unit);
  return whole(v, per, bindings);
}

std::int64_t bound_steps(const Value& v, const Bindings& bindings) {
  return whole(v, 1.0, bindings);
}

/// Builds the monitor's nodes from a formula: negations pushed to the leaves, equal
/// subformulas shared (by their signature), and the unit, idempotence and absorption laws of
/// && and || applied.
class OnlineMonitor::Builder {
 public:
  Builder(OnlineMonitor& monitor, const TimeScale& scale, Reading reading)
      : m_(monitor), scale_(scale), pointwise_(reading == Reading::Pointwise) {
    // Pointwise windows find the steps whose times they hold.
    if (pointwise_) m_.reads_steps_ = true;
  }

  std::size_t build(const Formula& f, bool negated) {
    using K = Formula::Kind;
    auto operand = [&](std::size_t k, bool neg) { return build(*f.operands[k], neg); };
    switch (f.kind) {
      case K::True:
      case K::False:
        return constant((f.kind == K::True) != negated);
      case K::Atom:
        return literal(*f.atom, negated);
      case K::Not:
        return operand(0, !negated);
      case K::And:
        return junction(negated, operand(0, negated), operand(1, negated));
      case K::Or:
        return junction(!negated, operand(0, negated), operand(1, negated));
      case K::Implies:
        return junction(!negated, operand(0, !negated), operand(1, negated));
      case K::Iff:  // a <-> b = (a && b) || (!a && !b); negated: (a && !b) || (!a && b)
        return junction(true, junction(false, operand(0, false), operand(1, negated)),
                        junction(false, operand(0, true), operand(1, !negated)));
      case K::Next:
        return next(operand(0, negated));
      case K::Finally:  // !F phi = G !phi
        return finally(window(f.bound), operand(0, negated), negated);
      case K::Globally:
        return finally(window(f.bound), operand(0, negated), !negated);
      case K::Until:  // !(a U b) = !a R !b
        return until(window(f.bound), operand(0, negated), operand(1, negated), negated);
      case K::Release:
        return until(window(f.bound), operand(0, negated), operand(1, negated), !negated);
    }
    return constant(false);
  }

 private:
  struct Shape {
    char kind = 0;  // 'c' constant, 'l' literal, '&', '|', 't' temporal
    std::size_t x = 0, y = 0;
    bool value = false;  // a constant's
  };

  std::size_t constant(bool value) {
    const std::size_t id = add(value ? "true" : "false", {'c', 0, 0, value},
                               [] { return std::make_unique<online::Leaf>(); });
    if (fresh_) m_.leaves_.push_back({id, nullptr, value, false, false});
    return id;
  }

  std::size_t literal(const Expr& predicate, bool negated) {
    const std::size_t id = add((negated ? "!" : "") + to_string(predicate), {'l'},
                               [] { return std::make_unique<online::Leaf>(); });
    if (fresh_) {
      m_.leaves_.push_back({id, &predicate, negated, !pointwise_ && reads_growing(predicate),
                            reads_run_end(predicate)});
      if (!reads_places_and_data_only(predicate)) m_.places_and_data_only_ = false;
    }
    return id;
  }

  std::size_t junction(bool disjunction, std::size_t x, std::size_t y) {
    const char kind = disjunction ? '|' : '&';
    for (auto [a, b] : {std::pair{x, y}, std::pair{y, x}}) {
      if (shapes_[a].kind == 'c') return shapes_[a].value == disjunction ? a : b;
      // a && (a || c) = a, a || (a && c) = a
      const Shape& other = shapes_[b];
      if (other.kind == (disjunction ? '&' : '|') && (other.x == a || other.y == a)) return a;
    }
    if (x == y) return x;
    if (y < x) std::swap(x, y);
    return add(kind + std::to_string(x) + "," + std::to_string(y), {kind, x, y}, [&] {
      return std::make_unique<online::Junction>(self(), operand(x), operand(y), disjunction);
    });
  }

  std::size_t next(std::size_t phi) {
    m_.reads_steps_ = true;
    return add("X" + std::to_string(phi), {'t'},
               [&] { return std::make_unique<online::Next>(self(), operand(phi)); });
  }

  std::size_t finally(online::Window w, std::size_t phi, bool dual) {
    return add(signature(dual ? "G" : "F", w) + std::to_string(phi), {'t'},
               [&] { return std::make_unique<online::Finally>(self(), operand(phi), w, dual); });
  }

  std::size_t until(online::Window w, std::size_t hold, std::size_t goal, bool dual) {
    return add(signature(dual ? "R" : "U", w) + std::to_string(hold) + "," + std::to_string(goal),
               {'t'}, [&] {
                 return std::make_unique<online::Until>(self(), operand(hold), operand(goal), w,
                                                        dual);
               });
  }

  static std::string signature(const char* op, const online::Window& w) {
    return std::string(op) + (w.axis == online::Axis::Steps ? "#" : "") + "[" +
           std::to_string(w.low) + "," + std::to_string(w.high) + "]";
  }

  /// The node of `signature`, made by `make` unless an equal one exists.
  template <class Make>
  std::size_t add(const std::string& signature, Shape shape, Make make) {
    const auto [it, inserted] = ids_.try_emplace(signature, m_.blank_nodes_.size());
    fresh_ = inserted;
    if (!inserted) return it->second;
    m_.blank_signals_.of.emplace_back();
    m_.blank_nodes_.push_back(make());
    shapes_.push_back(shape);
    return it->second;
  }
  std::size_t self() const { return m_.blank_nodes_.size(); }
  online::Operand operand(std::size_t node) {
    return {node, m_.blank_signals_.of[node].add_reader()};
  }

  online::Window window(const Bound& b) const {
    switch (b.kind) {
      case Bound::Kind::None:
        return {online::Axis::Time, 0, online::kNever, pointwise_};
      case Bound::Kind::Steps:
        m_.reads_steps_ = true;
        return {online::Axis::Steps, 0, bound_steps(b.high, m_.bindings_)};
      case Bound::Kind::Time:  // in half ticks
        return {online::Axis::Time, 2 * ticks(b.low), 2 * ticks(b.high), pointwise_};
    }
    return {};
  }

  Tick ticks(const Value& v) const { return bound_ticks(v, scale_, m_.bindings_); }

  OnlineMonitor& m_;
  TimeScale scale_;
  bool pointwise_;
  std::map<std::string, std::size_t> ids_;
  std::vector<Shape> shapes_;
  bool fresh_ = false;  // the last add made a node
};

OnlineMonitor::OnlineMonitor(const Formula& formula, const TimeScale& scale,
                             const Bindings& bindings, const Bound& run, Reading reading)
    : bindings_(bindings), scale_(scale), pointwise_(reading == Reading::Pointwise) {
  Builder builder(*this, scale, reading);
  root_ = builder.build(formula, false);
  root_reader_ = blank_signals_.of[root_].add_reader();
  if (run.kind == Bound::Kind::Time) {
    time_bound_ = 2 * bound_ticks(run.high, scale, bindings);
    // Beyond the time bound nothing exists, from the start on.
    for (const auto& node : blank_nodes_) node->close({time_bound_, kLastRank});
  } else if (run.kind == Bound::Kind::Steps) {
    step_bound_ = bound_steps(run.high, bindings);
  }
  reset();
}

OnlineMonitor::OnlineMonitor(const OnlineMonitor& other)
    : blank_nodes_(clone_all(other.blank_nodes_)),
      blank_signals_(other.blank_signals_),
      leaves_(other.leaves_),
      root_(other.root_),
      root_reader_(other.root_reader_),
      bindings_(other.bindings_),
      scale_(other.scale_),
      pointwise_(other.pointwise_),
      reads_steps_(other.reads_steps_),
      places_and_data_only_(other.places_and_data_only_),
      time_bound_(other.time_bound_),
      step_bound_(other.step_bound_),
      nodes_(clone_all(other.nodes_)),
      signals_(other.signals_),
      pending_(other.pending_),
      started_(other.started_),
      steps_(other.steps_),
      origin_(other.origin_),
      last_(other.last_),
      verdict_(other.verdict_),
      decided_(other.decided_),
      sure_hit_(other.sure_hit_),
      possible_hit_(other.possible_hit_) {}

OnlineMonitor& OnlineMonitor::operator=(const OnlineMonitor& other) {
  if (this != &other) *this = OnlineMonitor(other);
  return *this;
}

OnlineMonitor::~OnlineMonitor() = default;

void OnlineMonitor::reset() {
  // After the first run, the nodes and signals are restored in place: a run allocates only
  // when its signals outgrow every earlier run's.
  if (nodes_.size() == blank_nodes_.size() && signals_.of.size() == blank_signals_.of.size()) {
    for (std::size_t i = 0; i < nodes_.size(); ++i) nodes_[i]->restart(*blank_nodes_[i]);
    for (std::size_t i = 0; i < signals_.of.size(); ++i) {
      signals_.of[i].restart(blank_signals_.of[i]);
    }
    signals_.segments.restart();
  } else {
    nodes_ = clone_all(blank_nodes_);
    signals_ = blank_signals_;
  }
  pending_.assign(leaves_.size(), Pending{});
  started_ = false;
  steps_ = 0;
  origin_ = 0;
  last_ = {};
  verdict_ = Verdict::Undecided;
  decided_ = false;
  sure_hit_ = possible_hit_ = kForever;
}

Verdict OnlineMonitor::step(const StateView& state, Tick time) {
  if (decided_) return verdict_;
  Pos at = online::kFirst;
  if (!started_) {
    started_ = true;
    origin_ = time;
  } else {
    const Tick t = 2 * (time - origin_);  // half ticks
    if (t < last_.t) throw std::invalid_argument("online monitor: a step earlier than the last");
    at = t == last_.t ? Pos{t, last_.n + 1} : Pos{t, 0};
    if (t > time_bound_) {
      finish_observation({time_bound_, kLastRank});
      return verdict_;
    }
    if (steps_ > step_bound_) {
      finish_observation(online::before(at));
      return verdict_;
    }
    // The last step held up to this one: an instant when they share the time.
    emit_leaves(online::before(at));
  }
  const bool initial = steps_ == 0;
  last_ = at;
  ++steps_;
  if (reads_steps_) signals_.segments.push(at);
  const Moment going_on(state, time, scale_, initial);
  for (std::size_t i = 0; i < leaves_.size(); ++i) {
    const Leaf& leaf = leaves_[i];
    Pending& pending = pending_[i];
    compute(leaf, going_on, time, RunEnd::Cut, pending.going_on);
    if (!leaf.reads_end) continue;
    compute(leaf, Moment(state, time, scale_, initial, RunEnd::Deadlock), time, RunEnd::Deadlock,
            pending.deadlock);
    compute(leaf, Moment(state, time, scale_, initial, RunEnd::Timelock), time, RunEnd::Timelock,
            pending.timelock);
  }
  advance();
  if (const online::Run* run = root_run()) decide(run->value ? Verdict::True : Verdict::False);
  return verdict_;
}

Verdict OnlineMonitor::end(RunEnd how) {
  if (decided_ || !started_) return verdict_;
  if (how == RunEnd::Absorbing) how = places_and_data_only_ ? RunEnd::Deadlock : RunEnd::Cut;
  if (how == RunEnd::Deadlock) {
    emit_leaves(kForever, how);
    signals_.segments.finish();
    advance();
  } else {
    // A time-lock shows its last state (where timelock holds) at its instant, and no more:
    // what the windows beyond would have seen is unknown, as for a run cut short.
    emit_leaves(last_, how);
    advance();
  }
  if (const online::Run* run = root_run()) {
    decide(run->value ? Verdict::True : Verdict::False);
  } else {
    // Kleene's value: true if true whatever follows reads, false if false whatever it reads.
    Pos sure_hit, possible_hit;
    auto nodes = clone_all(nodes_);
    online::Signals signals = signals_;
    const Verdict sure = finish_cut(false, sure_hit);
    nodes_ = std::move(nodes);  // the run as it was cut, for the second reading
    signals_ = std::move(signals);
    const Verdict maybe = finish_cut(true, possible_hit);
    decide(sure == Verdict::True     ? Verdict::True
           : maybe == Verdict::False ? Verdict::False
                                     : Verdict::Undecided);
    sure_hit_ = sure_hit;
    possible_hit_ = possible_hit;
  }
  return verdict_;
}

Verdict OnlineMonitor::finish_cut(bool unknown, Pos& hit) {
  for (const Leaf& leaf : leaves_) signals_.of[leaf.node].emit(kForever, unknown);
  signals_.segments.push(online::after(last_));
  signals_.segments.finish(/*unknown=*/true);
  advance();
  const online::Run* run = root_run();
  const Verdict verdict = run == nullptr ? Verdict::Undecided
                          : run->value   ? Verdict::True
                                         : Verdict::False;
  hit = nodes_[root_]->first_hit();
  return verdict;
}

void OnlineMonitor::finish_observation(Pos end) {
  emit_leaves(kForever);
  for (const auto& node : nodes_) node->close(end);
  signals_.segments.finish();
  advance();
  const online::Run* run = root_run();
  decide(run == nullptr ? Verdict::Undecided : run->value ? Verdict::True : Verdict::False);
}

void OnlineMonitor::decide(Verdict verdict) {
  verdict_ = verdict;
  decided_ = true;
  sure_hit_ = possible_hit_ = nodes_[root_]->first_hit();
}

void OnlineMonitor::compute(const Leaf& leaf, const StateView& state, Tick /*time*/, RunEnd /*how*/,
                            std::vector<TruthChange>& out) const {
  if (leaf.predicate == nullptr) {  // a constant: its value
    out.assign(1, {0, leaf.negated});
    return;
  }
  if (leaf.grows) {
    truth_changes(*leaf.predicate, state, bindings_, out);
    if (leaf.negated) {
      for (TruthChange& change : out) change.value = !change.value;
    }
    return;
  }
  out.assign(1, {0, (evaluate(*leaf.predicate, state, bindings_) != 0) != leaf.negated});
}

void OnlineMonitor::emit_leaves(Pos end, RunEnd how) {
  for (std::size_t i = 0; i < leaves_.size(); ++i) {
    const Pending& pending = pending_[i];
    const std::vector<TruthChange>& changes = !leaves_[i].reads_end     ? pending.going_on
                                              : how == RunEnd::Deadlock ? pending.deadlock
                                              : how == RunEnd::Timelock ? pending.timelock
                                                                        : pending.going_on;
    online::Signal& signal = signals_.of[leaves_[i].node];
    // Each change holds up to the position before the next one's start, or `end`.
    for (std::size_t k = 0; k < changes.size(); ++k) {
      Pos until = end;
      if (k + 1 < changes.size()) {
        const Pos next_start{last_.t + changes[k + 1].offset, 0};
        if (next_start <= end) until = online::before(next_start);
      }
      signal.emit(until, changes[k].value);
      if (until == end) break;
    }
  }
}

void OnlineMonitor::advance() {
  for (const auto& node : nodes_) node->advance(signals_);
  for (online::Signal& signal : signals_.of) signal.trim();
  if (!reads_steps_) return;
  std::int64_t needed = signals_.segments.count() - 1;
  for (const auto& node : nodes_) {
    const std::int64_t n = node->segment_needed(signals_);
    if (n >= 0) needed = std::min(needed, n);
  }
  signals_.segments.drop_before(needed);
}

const online::Run* OnlineMonitor::root_run() { return signals_.of[root_].peek(root_reader_); }

std::size_t OnlineMonitor::held_runs() const {
  std::size_t runs = 0;
  for (const online::Signal& signal : signals_.of) runs += signal.size();
  return runs;
}

}  // namespace smcbip::monitors
