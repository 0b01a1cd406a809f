// The choice of a timed step on the compiled step path (flat_steps.h), on a timed layout or in
// stochastic mode: the enabled items cut to the waiting window (as Runtime::compute_items lists
// them), then the reference race (random_race) or the stochastic race of planned dates
// (earliest_in_window, dates kept per position as DatePlanner keeps them per item), as
// Runtime::wait_interval and the Scheduler make them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "engines/api/model.h"
#include "engines/semantics/compiled_steps.h"
#include "engines/semantics/detail/runtime_shared.h"
#include "engines/semantics/item_race.h"
#include "engines/stochastic/date_planner.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

/// A flag per position of the compiled step path. Not std::uint8_t: a store through a
/// character type may alias anything, so the compiler would reload every table's address
/// after each.
enum class FlatFlag : std::uint8_t { Off, On };

class FlatTimedChoice {
 public:
  /// The step's outcome; when Fired, the position to fire and its date.
  struct Choice {
    CompiledSteps::Outcome outcome = CompiledSteps::Outcome::Deadlock;
    std::uint32_t position = 0;
    TimeValue date = 0;
  };
  /// Per position whether its item is enabled and its constraint (the step path keeps them),
  /// and the @stochastic port each fires.
  /// Pointers, not vectors or spans: values the step keeps in registers, where a vector's
  /// start would be loaded again after every store to the listed items.
  struct Items {
    std::uint32_t positions = 0;
    const FlatFlag* enabled = nullptr;
    const Constraint* raw = nullptr;
    const std::optional<std::pair<Index, Index>>* stochastic = nullptr;
  };
  /// The run's draws: `planner` (stochastic mode, else null) races planned dates.
  struct Run {
    Runtime* runtime = nullptr;
    RandomStream* random = nullptr;
    DatePlanner* planner = nullptr;
    bool asap = false, first_enabled = false;
  };

  /// A new run over `positions` positions: the race count goes on from the last run's, one
  /// race skipped, so no plan of that run is seen in the race before this run's first: none is
  /// kept, and they need no reset.
  void new_run(std::size_t positions) {
    if (items_.size() != positions) items_.resize(positions);
    if (plans_.size() != positions) plans_.assign(positions, DatePlanner::Plan{});
    ++generation_;
  }

  /// The step at `now`: Deadlock or Timelock when no item is listed, else Limit when
  /// `at_limit`, Beyond when a date cannot be drawn, else the item to fire.
  [[gnu::always_inline]] Choice choose(TimeValue now, bool at_limit, const Items& at,
                                       const Run& run) {
    Interval waiting;
    const std::size_t listed = list(now, at, waiting);
    if (listed == 0) {
      return {waiting.right == kPlusInfinity ? CompiledSteps::Outcome::Deadlock
                                             : CompiledSteps::Outcome::Timelock};
    }
    if (at_limit) return {CompiledSteps::Outcome::Limit};
    const auto window = [&](std::size_t i) -> const Interval& { return items_[i].window; };
    std::optional<std::pair<std::size_t, TimeValue>> choice;
    if (run.planner == nullptr) {
      choice = random_race(count_, window, now, run.asap, run.first_enabled, *run.random);
    } else {
      try {
        if (!race(at, run, choice)) return {CompiledSteps::Outcome::Beyond};
      } catch (const CodeFault&) {
        return {CompiledSteps::Outcome::Beyond};
      }
      if (!choice) return {CompiledSteps::Outcome::Timelock};
    }
    return {CompiledSteps::Outcome::Fired, items_[choice->first].position, choice->second};
  }

  /// choose() in stochastic mode (`run.planner`) when every item is lazy and holds at all dates: no
  /// window is cut, and every planned date lies in its item's window (from now on, as a drawn date
  /// does, and a kept one, which lost a race won at now or later). One pass over the enabled
  /// positions renews their plans, as race() does in the same order, and finds the earliest date;
  /// only a tie is broken afterwards, with earliest_in_window's draws.
  [[gnu::always_inline]] Choice choose_lazy(bool at_limit, const Items& at, const Run& run) {
    std::uint32_t p = 0;
    while (p < at.positions && at.enabled[p] == FlatFlag::Off) ++p;
    if (p == at.positions) return {CompiledSteps::Outcome::Deadlock};
    if (at_limit) return {CompiledSteps::Outcome::Limit};
    if (draws_of_ != run.planner) index_fixed_draws(at, run);
    ++generation_;
    std::uint32_t chosen = p;
    TimeValue best = kPlusInfinity;
    bool tied = false;
    try {
      for (; p < at.positions; ++p) {
        if (at.enabled[p] == FlatFlag::Off) continue;
        DatePlanner::Plan& plan = plans_[p];
        // DatePlanner::renew, whose constraints compare equal here: every item's is the whole
        // time line, lazy. Drawn out of line, which leaves the loop its registers.
        if (plan.seen + 1 != generation_ && !draw(plan, p, at, run)) {
          return {CompiledSteps::Outcome::Beyond};
        }
        plan.seen = generation_;
        if (plan.date < best || p == chosen) {
          best = plan.date;
          chosen = p;
        } else {
          tied = tied || plan.date == best;
        }
      }
    } catch (const CodeFault&) {
      return {CompiledSteps::Outcome::Beyond};
    }
    if (tied) chosen = break_tie(at, *run.random);
    DatePlanner::fired(plans_[chosen]);
    return {CompiledSteps::Outcome::Fired, chosen, best};
  }

 private:
  /// An item of a timed step: its position and its window cut to the waiting window.
  struct Listed {
    std::uint32_t position = 0;
    Interval window;
    TimeValue date = 0;  // stochastic mode: its planned date
  };

  /// Lists the enabled items from `now` on, cut to the waiting window (written to `waiting`);
  /// how many. One pass lists them and gathers the window; only when an item is not lazy (the
  /// window may then be cut) does a second pass over the listed ones cut them.
  [[gnu::always_inline]] std::size_t list(TimeValue now, const Items& at, Interval& waiting) {
    const Interval from_now = Interval::from(now);
    waiting = from_now;
    bool waits = false;
    // items_ has room for every position (new_run): an item is written in place and kept when
    // its window is not empty.
    std::size_t listed = 0;
    for (std::uint32_t p = 0; p < at.positions; ++p) {
      if (at.enabled[p] == FlatFlag::Off) continue;
      const Constraint& raw = at.raw[p];
      if (raw.urgency != bipc::Urgency::Lazy) {
        narrow(waiting, detail::wait(raw, now));
        waits = true;
      }
      // Copied field by field: an Interval built and copied whole stalled on store forwarding.
      Listed& item = items_[listed];
      item.position = p;
      item.window.left = raw.interval.left;
      item.window.right = raw.interval.right;
      item.window.left_open = raw.interval.left_open;
      item.window.right_open = raw.interval.right_open;
      narrow(item.window, from_now);
      listed += item.window.empty() ? 0 : 1;
    }
    // Intersections commute: cutting by now and then by the waiting window is cutting by both.
    if (waits) listed = cut_to(waiting, listed);
    count_ = listed;
    return listed;
  }

  /// Cuts the first `listed` items' windows to `waiting`, keeping the non-empty ones in order;
  /// how many are kept.
  std::size_t cut_to(const Interval& waiting, std::size_t listed) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < listed; ++i) {
      narrow(items_[i].window, waiting);
      if (items_[i].window.empty()) continue;
      if (kept != i) items_[kept] = items_[i];
      ++kept;
    }
    return kept;
  }

  std::span<Listed> listed_items() { return {items_.data(), count_}; }

  /// A new date for the plan of the item at position `p`, as DatePlanner::renew draws one;
  /// false when it cannot be drawn.
  [[gnu::noinline]] bool draw(DatePlanner::Plan& plan, std::uint32_t p, const Items& at,
                              const Run& run) {
    if (std::optional<DatePlanner::FixedDraw>& fixed = fixed_draws_[p]) {
      if (!run.planner->draw_from_now(*run.runtime, *fixed, plan.date, problem_)) return false;
    } else if (!run.planner->draw_date(*run.runtime, at.stochastic[p], at.raw[p], plan.date,
                                       problem_)) {
      return false;
    }
    plan.offered = at.raw[p];
    return true;
  }

  /// Per position, the planner's FixedDraw of its @stochastic port, if it has one.
  void index_fixed_draws(const Items& at, const Run& run) {
    fixed_draws_.assign(at.positions, std::nullopt);
    for (std::uint32_t p = 0; p < at.positions; ++p) {
      if (const std::optional<std::pair<Index, Index>>& port = at.stochastic[p]) {
        fixed_draws_[p] = run.planner->fixed_draw(*run.runtime, port->first, port->second);
      }
    }
    draws_of_ = run.planner;
  }

  /// The enabled position earliest_in_window chooses among their planned dates, ties
  /// included (every date lies in its window here).
  std::uint32_t break_tie(const Items& at, RandomStream& random) {
    std::size_t n = 0;
    for (std::uint32_t p = 0; p < at.positions; ++p) {
      if (at.enabled[p] == FlatFlag::Off) continue;
      items_[n].position = p;
      items_[n++].date = plans_[p].date;
    }
    const Interval all = Interval::all();
    const auto window = [&](std::size_t) -> const Interval& { return all; };
    const auto date = [&](std::size_t i) { return items_[i].date; };
    return items_[earliest_in_window(n, window, date, random)->first].position;
  }

  /// Scheduler::race over the listed items: DatePlanner::plan's kept or new dates, then the
  /// earliest in its window, or after replan_within_windows; false when a date cannot be drawn.
  [[gnu::always_inline]] bool race(const Items& at, const Run& run,
                                   std::optional<std::pair<std::size_t, TimeValue>>& choice) {
    ++generation_;
    for (Listed& item : listed_items()) {
      DatePlanner::Plan& plan = plans_[item.position];
      const auto stochastic = [&] { return at.stochastic[item.position]; };
      if (!run.planner->renew(*run.runtime, plan, generation_, at.raw[item.position], stochastic,
                              problem_)) {
        return false;
      }
      item.date = plan.date;
    }
    const auto window = [&](std::size_t i) -> const Interval& { return items_[i].window; };
    const auto date = [&](std::size_t i) { return items_[i].date; };
    choice = earliest_in_window(count_, window, date, *run.random);
    if (!choice) {
      for (Listed& item : listed_items()) {
        if (at.stochastic[item.position]) continue;
        item.date = run.planner->draw_timed(at.raw[item.position].urgency, item.window);
        plans_[item.position].date = item.date;
      }
      choice = earliest_in_window(count_, window, date, *run.random);
    }
    if (choice) DatePlanner::fired(plans_[items_[choice->first].position]);
    return true;
  }

  std::vector<Listed> items_;  // one per position; the first count_ are the step's
  std::size_t count_ = 0;
  std::vector<DatePlanner::Plan> plans_;  // per position, as DatePlanner keeps them per item
  std::uint64_t generation_ = 1;
  std::string problem_;  // a draw's error (the engines' replay reports it)
  // The lazy race's draws: per position, from the planner draws_of_.
  std::vector<std::optional<DatePlanner::FixedDraw>> fixed_draws_;
  const DatePlanner* draws_of_ = nullptr;
};

}  // namespace smcbip::engines
