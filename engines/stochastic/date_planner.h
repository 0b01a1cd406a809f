// Stochastic scheduling (BIP.md, "Stochastic real-time extension"): every enabled item gets a
// planned firing date and the earliest date wins the race. Dates follow the generalised
// semi-Markov reading of SBIP (Nouri et al., 2017): a date stays planned while its item stays
// enabled with the same constraint, and is drawn afresh once the item was disabled or its
// constraint changed.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/semantics/runtime.h"
#include "engines/stochastic/clock_dates.h"
#include "engines/stochastic/distributions.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

/// The empirical CDFs of a system's `custom` ports, by file.
using CustomDistributions = std::map<std::string, EmpiricalCdf>;

/// Reads the empirical CDF files of `system`'s custom ports into `out`; a message naming the
/// file on failure.
std::string load_custom_distributions(const bipc::ir::System& system, CustomDistributions& out);

/// A date uniform over the integer nanoseconds of a bounded window.
TimeValue uniform_date(const Interval& window, RandomStream& random);

/// Whether some port of `system` carries a @stochastic annotation.
bool has_stochastic_ports(const bipc::ir::System& system);

class DatePlanner {
 public:
  /// The planned date of one item: kept while the item stays enabled with the same constraint.
  struct Plan {
    Constraint offered;
    TimeValue date = 0;
    std::uint64_t seen = 0;  // the last race that found the item enabled
  };

  /// `unbounded_mean`: the mean delay (ns) of the exponential date of an item whose window has
  /// no right end.
  DatePlanner(const bipc::ir::System& system, const CustomDistributions& custom,
              RandomStream& random, TimeValue unbounded_mean);

  /// A date for each item of `runtime`, in item order: the item's stochastic port decides it
  /// when it has one, its urgency and window otherwise. False with `error` set when a date
  /// cannot be drawn (a missed support or invalid distribution parameters).
  bool plan(Runtime& runtime, std::vector<TimeValue>& dates, std::string& error);

  /// When no planned date falls in its item's current window (deadlines of invariants or
  /// resumes cut them all), the timed items draw again within their current windows.
  void replan_within_windows(const Runtime& runtime, std::vector<TimeValue>& dates);

  /// Forgets every planned date: the next plan() draws them all (a new run).
  void forget() { ++generation_; }

  /// Brings `plan` to race `race` (races counted from 2; a plan seen in none is new) for an
  /// item enabled with constraint `offered`: its date is kept when the item was enabled in the
  /// race before with the same constraint, drawn afresh by draw_date otherwise, with the
  /// @stochastic port `stochastic_port()` returns (called only then). plan() keeps its plans so;
  /// a caller that keeps its own (the compiled step path) does too. False with `error` set as
  /// plan().
  template <class StochasticPort>
  [[gnu::always_inline]] bool renew(Runtime& runtime, Plan& plan, std::uint64_t race,
                                    const Constraint& offered, StochasticPort stochastic_port,
                                    std::string& error) {
    const bool kept = plan.seen + 1 == race && plan.offered.urgency == offered.urgency &&
                      plan.offered.interval == offered.interval;
    if (!kept) {
      if (!draw_date(runtime, stochastic_port(), offered, plan.date, error)) return false;
      plan.offered = offered;
    }
    plan.seen = race;
    return true;
  }

  /// The item chosen by the last race fires: its date is used up, so it draws afresh when it
  /// is offered again (a self-loop does not fire again at the same date).
  static void fired(Plan& plan) { plan.seen = 0; }
  void fired(const Runtime& runtime, const Item& item) { fired(plan_of(runtime, item)); }

  /// A new date for an item offered `offered`, as plan() draws one: from the @stochastic
  /// annotation of the atom port `stochastic` when the item fires one, from its urgency and
  /// window otherwise. False with `error` set as plan().
  /// Inline down to the draw from a port's fixed distribution: the draw of every step of a
  /// Markovian model, whose calls would otherwise cost a third of it.
  [[gnu::always_inline]] bool draw_date(Runtime& runtime,
                                        const std::optional<std::pair<Index, Index>>& stochastic,
                                        const Constraint& offered, TimeValue& date,
                                        std::string& error) {
    // The item's own window from now: the dates other items' deadlines cut off stay possible,
    // as the race decides whether the item gets there.
    const Interval window = offered.interval.intersect(Interval::from(runtime.state().now));
    if (!stochastic) {
      date = draw_timed(offered.urgency, window);
      return true;
    }
    const auto [atom, port] = *stochastic;
    if (std::optional<Fixed>& fixed = fixed_distributions_[first_port_[atom] + port]) {
      return draw_from(runtime, atom, port, fixed->distribution, &*fixed, window, date, error);
    }
    return draw_made(runtime, atom, port, window, date, error);
  }
  /// What draws the dates of an item whose @stochastic port has a fixed distribution (its
  /// parameters are valid numbers): that distribution and the port's clock.
  class FixedDraw;
  /// The FixedDraw of atom port (atom, port), if its distribution is fixed.
  std::optional<FixedDraw> fixed_draw(const Runtime& runtime, Index atom, Index port);
  /// draw_date for an item of `draw` offered at all dates from now on, lazily.
  [[gnu::always_inline]] bool draw_from_now(Runtime& runtime, FixedDraw& draw, TimeValue& date,
                                            std::string& error);

  /// A date for an item without a @stochastic port: its window's first date when eager, else
  /// uniform in a bounded window, exponential after an unbounded one's first date.
  TimeValue draw_timed(bipc::Urgency urgency, const Interval& window);

 private:
  // A distribution made once, and its last truncation point with the masses either side: a
  // clock reset when its port is offered truncates at 0 every time.
  struct Fixed {
    explicit Fixed(const DateDistribution& made) : distribution(made) {}
    DateDistribution distribution;
    double lower = std::numeric_limits<double>::quiet_NaN();  // equal to nothing at first
    DateDistribution::Masses at_lower;
    /// distribution.masses(x), computed again only for a new x.
    DateDistribution::Masses masses(double x);
  };
  /// An interaction item's identity: (connector, defined interaction), then the (atom, port)
  /// pairs it fires.
  using Key = std::vector<std::pair<Index, Index>>;
  // Transparent: items are looked up by a span over a reused buffer, without allocating.
  struct KeyHash {
    using is_transparent = void;
    std::size_t operator()(std::span<const std::pair<Index, Index>> key) const;
  };
  struct KeyEqual {
    using is_transparent = void;
    bool operator()(std::span<const std::pair<Index, Index>> a,
                    std::span<const std::pair<Index, Index>> b) const {
      return std::equal(a.begin(), a.end(), b.begin(), b.end());
    }
  };
  using Plans = std::unordered_map<Key, Plan, KeyHash, KeyEqual>;

  /// Identifies an interaction item across steps: its connector and defined interaction and the
  /// atom ports it fires; written to key_.
  void key_of(const Runtime& runtime, const Item& item);
  /// Sizes the tables of plans kept without a key (port_plans_, connector_plans_), once.
  void index_connectors(const Runtime& runtime);
  /// The plan of the item (created empty when new).
  Plan& plan_of(const Runtime& runtime, const Item& item);
  /// draw_date's date from a distribution made for this draw: the port's parameters are not
  /// all numbers, or not valid ones (then false with `error` set).
  bool draw_made(Runtime& runtime, Index atom, Index port, const Interval& window, TimeValue& date,
                 std::string& error);
  /// draw_date's date from `distribution`, whose masses `fixed` keeps when it is the port's
  /// fixed one (null for a distribution made for this draw). The date is drawn on the clock's
  /// scale, conditioned on lying in the port's window: a clock that has already advanced
  /// truncates the distribution at its value. The clock is read from the state here, not
  /// through Runtime calls.
  [[gnu::always_inline]] bool draw_from(Runtime& runtime, Index atom, Index port,
                                        const DateDistribution& distribution, Fixed* fixed,
                                        const Interval& window, TimeValue& date,
                                        std::string& error) {
    const std::size_t slot =
        runtime.layout().atom_clocks[atom] + port_clocks_[first_port_[atom] + port];
    return draw_on_clock(runtime, slot, runtime.layout().clock_units[slot], atom, port,
                         distribution, fixed, window.first(), date, error);
  }
  /// draw_from on the port's clock `slot` (of unit `unit` ns), from the window's first date
  /// `first` on.
  [[gnu::always_inline]] bool draw_on_clock(Runtime& runtime, std::size_t slot, TimeValue unit,
                                            Index atom, Index port,
                                            const DateDistribution& distribution, Fixed* fixed,
                                            TimeValue first, TimeValue& date, std::string& error) {
    const ClockState& clock = runtime.state().clocks[slot];
    const double lower = clock_value_at(clock, unit, first);
    double sample = 0.0;
    if (!distribution.sample_above(
            lower, random_,
            [&] { return fixed ? fixed->masses(lower) : distribution.masses(lower); }, sample)) {
      return missed_support(runtime, atom, port, distribution, lower, error);
    }
    date = std::max(first, clock_reaches(clock, unit, runtime.state().now, sample));
    return true;
  }
  /// draw_from's error when the clock is beyond every date of the distribution: false.
  bool missed_support(const Runtime& runtime, Index atom, Index port,
                      const DateDistribution& distribution, double lower, std::string& error) const;
  /// The @stochastic annotation of an atom port that has one.
  const bipc::ir::Stochastic& annotation_of(Index atom, Index port) const;
  /// The port's name as error messages give it: "ROOT.a.p".
  std::string port_name(const Runtime& runtime, Index atom, Index port) const;
  /// The distribution of an annotation whose parameters are all numbers, when they are valid.
  std::optional<Fixed> fixed_distribution(const bipc::ir::Stochastic& annotation) const;
  /// The annotation's distribution with `params` (its custom CDF from those loaded), or why
  /// there is none.
  std::variant<DateDistribution, std::string> make_distribution(
      const bipc::ir::Stochastic& annotation, std::span<const double> params) const;
  /// The @stochastic atom port among those bound to `ports` of connector `k` (whose ports each
  /// bind one atom port), if any.
  std::optional<std::pair<Index, Index>> stochastic_port_of(Index k, PortSet ports) const;
  /// The @stochastic port among the atom ports the item fires (at most one), if any.
  std::optional<std::pair<Index, Index>> stochastic_port(const Runtime& runtime, const Item& item);

  const bipc::ir::System& system_;
  RandomStream& random_;
  TimeValue unbounded_mean_;
  const CustomDistributions& custom_;
  // Plans by item. An atom port's item, and an interaction of a connector whose ports each
  // bind one atom port (with few defined interactions), has a slot of its own: its key is
  // implied. Other interactions are found by key.
  static constexpr std::size_t kDirectPlans = 64;
  std::vector<Plan> port_plans_;                    // per flattened atom port
  std::vector<std::vector<Plan>> connector_plans_;  // per connector, per defined interaction
  // Likewise, the @stochastic atom port of each such interaction.
  std::vector<std::vector<std::optional<std::pair<Index, Index>>>> connector_stochastic_;
  Plans plans_;
  bool indexed_ = false;  // index_connectors() has sized the tables
  std::uint64_t generation_ =
      1;  // from 2 on at the first plan(): new entries (seen 0) are not kept
  Key key_;
  std::vector<std::pair<Index, Index>> ports_;  // the atom ports of the item being drawn
  std::vector<double> params_;                  // of the @stochastic annotation being drawn from
  // Per atom port, as stochastic_ports_: its distribution when its parameters are numbers and
  // valid.
  std::vector<std::optional<Fixed>> fixed_distributions_;
  // Per atom port, flattened by atom (first_port_), whether it carries a @stochastic annotation.
  std::vector<std::size_t> first_port_;
  std::vector<std::uint8_t> stochastic_ports_;
  // Likewise, the clock of its annotation (0 without one): read on every draw.
  std::vector<Index> port_clocks_;
};

class DatePlanner::FixedDraw {
 private:
  friend class DatePlanner;
  Fixed* fixed = nullptr;
  std::size_t clock = 0;  // the port's clock, in the state's clocks
  TimeValue unit = 0;
  Index atom = 0, port = 0;
};

inline bool DatePlanner::draw_from_now(Runtime& runtime, FixedDraw& draw, TimeValue& date,
                                       std::string& error) {
  // draw_from over the window [now, +infinity[, whose first date is now.
  return draw_on_clock(runtime, draw.clock, draw.unit, draw.atom, draw.port,
                       draw.fixed->distribution, draw.fixed, runtime.state().now, date, error);
}

}  // namespace smcbip::engines
