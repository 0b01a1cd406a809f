// The compiled step path: the optimised engine's steps on the systems flat_tables covers, over a
// model's code known at compile time. Instantiated by generated code on its own (final) code
// class, every call into the model's guards, actions and atom steps is direct and may be
// inlined, and the step keeps to compact tables: what a step costs is the atoms it fires and
// the connectors next to them.
//
// It makes the Runtime's and Scheduler's choices with the same draws. Items sit at positions
// (the listed connectors in listing order, then the internal ports). On an untimed layout they
// are kept in EnabledPositions (the order of ItemIndex's counts) and chosen by SharedWindowChooser;
// on a timed one (or in stochastic mode) each has its constraint, and FlatTimedChoice chooses
// among them as the Scheduler does (flat_timed_choice.h). The firing is that of
// InteractionExecution::execute_in_sequence and AtomFiring::fire_port.
// Whatever the Runtime would report as an error (1-safety, non-determinism, code faults) ends
// the path as Beyond: the engines then replay the run, which tells the error as they do.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/api/run_observer.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/compiled_steps.h"
#include "engines/semantics/detail/runtime_shared.h"
#include "engines/semantics/enabled_positions.h"
#include "engines/semantics/flat_connector_code.h"
#include "engines/semantics/flat_tables.h"
#include "engines/semantics/flat_timed_choice.h"
#include "engines/semantics/item_race.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime.h"
#include "engines/semantics/shared_window.h"
#include "engines/semantics/written_slices.h"
#include "engines/stochastic/date_planner.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

/// `Code`: the model's ModelCode class, final so that its calls bind statically. When it has
/// `atom_fire_and_offer` (CompiledAtomSteps::fire_and_offer's arguments after the type), a
/// fired port calls that alone instead of atom_fire, atom_internal and atom_offers.
template <class Code>
class FlatSteps final : public CompiledSteps {
 public:
  FlatSteps(Code& code, const bipc::ir::System& system, const Layout& layout, FlatTables tables)
      : code_(code),
        layout_(layout),
        t_(std::move(tables)),
        connector_count_(static_cast<std::uint32_t>(t_.connectors.size())),
        position_count_(static_cast<std::uint32_t>(t_.positions())),
        connector_code_(code, system, t_) {
    offers_.resize(t_.offer_count);
    value_data_.resize(t_.value_data_size);
    touched_.assign(t_.atoms.size(), 0);
    chosen_.assign(t_.ports.size(), Flag::Off);
    recomputed_.assign(t_.positions(), 0);
  }

  bool begin(const Run& run) override {
    runtime_ = &run.runtime;
    state_ = &run.runtime.state();
    random_ = &run.random;
    planner_ = run.planner;
    asap_ = run.asap;
    first_enabled_ = run.first_enabled;
    timed_ = planner_ != nullptr || !layout_.untimed;
    if (timed_ && t_.has_triggered) return false;
    checks_kept_ = false;
    if (run.checks_kept_state) check_kept_state();
    timed_choice_.new_run(t_.positions());
    if (run.kept_start && start_ && start_->timed == timed_) {
      restore(*start_);
      return true;
    }
    if (!compute_start()) return false;
    if (run.kept_start) start_ = save();
    return true;
  }

  Outcome step(bool at_limit, StepInfo& info) override {
    if (timed_) return timed_step(at_limit, info);
    const std::size_t n = index_.total();
    if (n == 0) return Outcome::Deadlock;
    if (at_limit) return Outcome::Limit;
    const SharedWindowChoice choice =
        shared_window_.choose(n, state_->now, eager_count_ == 0, asap_, first_enabled_, *random_);
    return fire_and_check<Recompute::Untimed>(
        static_cast<std::uint32_t>(index_.find(choice.chosen)), choice.date, info);
  }

  bool step_kept_state() const override { return kept_; }
  void check_kept_state() override {
    checks_kept_ = true;
    if (!written_) written_.emplace(t_);
  }

 private:
  // The flags of positions and ports (not std::uint8_t: see FlatFlag).
  using Flag = FlatFlag;
  static Flag flag(bool on) { return on ? Flag::On : Flag::Off; }

  /// What begin() computes from a run's start state: kept for runs from the same state.
  struct Start {
    std::vector<std::optional<AtomPortValue>> offers;
    std::vector<Val> value_data;
    EnabledPositions index;
    std::vector<Flag> eager, enabled, chosen;
    std::ptrdiff_t eager_count = 0;
    std::vector<Constraint> raw;
    bool timed = false;  // the mode it was computed in, whose arrays restore() copies
  };
  Start save() const {
    return {offers_, value_data_, index_, eager_, enabled_, chosen_, eager_count_, raw_, timed_};
  }
  // Assigned in place: the vectors keep their storage. Only what the run's mode reads: the
  // timed step's items on a timed layout, the untimed step's otherwise (a run of a few steps
  // would spend a tenth of its time copying the others).
  void restore(const Start& start) {
    copy_over(start.offers, offers_);
    copy_over(start.value_data, value_data_);
    if (timed_) {
      copy_over(start.enabled, enabled_);
      copy_over(start.raw, raw_);
    } else {
      index_ = start.index;
      copy_over(start.eager, eager_);
      eager_count_ = start.eager_count;
      copy_over(start.chosen, chosen_);
    }
    beyond_ = false;
  }

  /// The offers and items of the run's start state, afresh; false when it is not covered.
  bool compute_start() {
    beyond_ = false;
    index_.reset(t_.positions());
    eager_.assign(t_.positions(), Flag::Off);
    eager_count_ = 0;
    enabled_.assign(t_.positions(), Flag::Off);
    raw_.assign(t_.positions(), Constraint{});
    try {
      for (Index a = 0; a < t_.atoms.size(); ++a) {
        if (!update_atom(a, atom_frame(a))) return false;
      }
      for (std::uint32_t p = 0; p < position_count_; ++p) recompute(p);
    } catch (const CodeFault&) {
      return false;
    }
    return !beyond_;
  }

  /// A step on a timed layout or in stochastic mode (FlatTimedChoice).
  Outcome timed_step(bool at_limit, StepInfo& info) {
    if (planner_ != nullptr && t_.lazy_unbounded) return lazy_step(at_limit, info);
    const FlatTimedChoice::Choice choice =
        timed_choice_.choose(state_->now, at_limit, items(), run_draws());
    if (choice.outcome != Outcome::Fired) return choice.outcome;
    return fire_and_check<Recompute::Timed>(choice.position, choice.date, info);
  }

  /// timed_step in stochastic mode when every offer is lazy at all dates: the race in one pass
  /// (FlatTimedChoice::choose_lazy), the items recomputed without constraints. Out of line: the
  /// other modes' step keeps its registers.
  [[gnu::noinline]] Outcome lazy_step(bool at_limit, StepInfo& info) {
    const FlatTimedChoice::Choice choice =
        timed_choice_.choose_lazy(at_limit, items(), run_draws());
    if (choice.outcome != Outcome::Fired) return choice.outcome;
    return fire_and_check<Recompute::Lazy>(choice.position, choice.date, info);
  }

  FlatTimedChoice::Items items() const {
    return {position_count_, enabled_.data(), raw_.data(), t_.stochastic.data()};
  }
  FlatTimedChoice::Run run_draws() const {
    return {runtime_, random_, planner_, asap_, first_enabled_};
  }

  /// How a step recomputes the items its firing touched: whether they are enabled (and eager),
  /// with their constraints too, or, when every offer is lazy at all dates (the constraints
  /// stay the whole time line), whether they are enabled alone.
  enum class Recompute { Untimed, Timed, Lazy };

  /// Fires the item at position `p` at `date`, then recomputes the items of the atoms it
  /// touched. Instantiated per mode, so that each has its recomputation inline.
  template <Recompute Mode>
  Outcome fire(std::uint32_t p, TimeValue date, StepInfo& info) {
    state_->now = date;
    info = StepInfo{};
    info.time = date;
    if (gathers_touched()) {
      ++stamp_;
      touched_list_.clear();
    }
    try {
      if (p < connector_count_) {
        info.fired = StepInfo::Fired::Interaction;
        info.connector = t_.connectors[p].index;
        if (!fire_connector(t_.connectors[p])) return Outcome::Beyond;
      } else {
        const FlatTables::Internal& internal = t_.internal[p - connector_count_];
        info.fired = StepInfo::Fired::Internal;
        info.atom = internal.atom;
        info.port = internal.port;
        if (!fire_port(internal)) return Outcome::Beyond;
      }
      if (gathers_touched()) {
        recompute_touched();
      } else {
        // Recomputing an item its firing left as it was gives it again: a superset of the
        // touched atoms' positions does, and needs no deduplication.
        // Inline: a call per position cost more than checking one that stays disabled.
        const std::uint32_t* q = t_.affected.data() + t_.first_affected[p];
        const std::uint32_t* const end = t_.affected.data() + t_.first_affected[p + 1];
        for (; q != end; ++q) {
          if constexpr (Mode == Recompute::Timed) {
            recompute_timed(*q);
          } else if constexpr (Mode == Recompute::Lazy) {
            enabled_[*q] = flag(offered(*q));
          } else {
            recompute_untimed(*q);
          }
        }
      }
    } catch (const CodeFault&) {
      return Outcome::Beyond;
    }
    return beyond_ ? Outcome::Beyond : Outcome::Fired;
  }

  /// fire(), and under Run::checks_kept_state whether it kept the bytes it may write. The
  /// check stays out of fire(), whose code the runs without it would otherwise pay for.
  template <Recompute Mode>
  Outcome fire_and_check(std::uint32_t p, TimeValue date, StepInfo& info) {
    // One call of fire(): inlined here, as it was into the step.
    const bool compares = checks_kept_ && !written_->surely_changed(p, offers_.data());
    if (compares) written_->remember(*state_, p);
    const Outcome outcome = fire<Mode>(p, date, info);
    kept_ = compares && written_->kept(*state_, p);
    return outcome;
  }

  /// Whether a step gathers the atoms it touched, the tables listing no affected positions.
  bool gathers_touched() const { return t_.first_affected.empty(); }

  /// Recomputes the positions of the atoms the step touched, each once.
  void recompute_touched() {
    for (Index a : touched_list_) {
      const FlatTables::Atom& atom = t_.atoms[a];
      for (std::uint32_t i = atom.first_neighbour; i < atom.neighbours_end; ++i) {
        const std::uint32_t q = t_.neighbours[i];
        if (recomputed_[q] == stamp_) continue;
        recomputed_[q] = stamp_;
        recompute(q);
      }
    }
  }

  Frame atom_frame(Index a) { return atom_frame(t_.atoms[a]); }
  Frame atom_frame(const FlatTables::Atom& atom) {
    Frame f;
    f.atom_data = state_->data.data() + atom.data;
    f.atom_params = layout_.params.data() + atom.params;
    f.clocks = atom.has_clocks ? state_->clocks.data() + atom.clocks : nullptr;
    f.clock_units = layout_.clock_units.data() + atom.clocks;
    f.now = state_->now;
    return f;
  }

  /// Runtime::update_atom for a covered atom: its offers afresh; false on a non-deterministic
  /// choice.
  bool update_atom(Index a, const Frame& f) {
    const FlatTables::Atom& atom = t_.atoms[a];
    return update_atom(atom, f, state_->marking.data() + atom.places);
  }
  bool update_atom(const FlatTables::Atom& atom, const Frame& f, const std::uint8_t* marking) {
    std::optional<AtomPortValue>* offers = offers_.data() + atom.first_offer;
    for (std::uint32_t p = 0; p < atom.port_count; ++p) offers[p].reset();
    return code_.atom_offers(atom.type, marking, f, offers) == bipc::ir::kNone;
  }

  /// Runtime::fire_port: the offered transition, the internal transitions it enables, the new
  /// offers; false where the Runtime reports an error. The port's entry holds its offer's index
  /// and its atom's entry, so that firing it reads no other table first.
  bool fire_port(const FlatTables::AtomPort& bound) {
    const Index a = bound.atom;
    const std::optional<AtomPortValue>& offer = offers_[bound.offer];
    if (!offer) return true;
    const FlatTables::Atom& atom = bound.of;
    if (gathers_touched() && touched_[a] != stamp_) {
      touched_[a] = stamp_;
      touched_list_.push_back(a);
    }
    return fire_atom(atom, offer->transition);
  }

  /// Fires `transition` of `atom`, then the internal transitions it enables, then sets its
  /// offers afresh; false on an error. Inline, as it was when part of fire_port.
  [[gnu::always_inline]] bool fire_atom(const FlatTables::Atom& atom, Index transition) {
    const Frame f = atom_frame(atom);
    std::uint8_t* marking = state_->marking.data() + atom.places;
    if constexpr (requires { &Code::atom_fire_and_offer; }) {
      // Code that has the three in one call (generated code's table) saves the calls between.
      return code_.atom_fire_and_offer(atom.type, transition, marking, f,
                                       offers_.data() + atom.first_offer);
    } else {
      if (!code_.atom_fire(atom.type, transition, marking, f)) return false;
      if (atom.has_internal_transitions) {
        for (;;) {
          const Index t = code_.atom_internal(atom.type, marking, f);
          if (t == bipc::ir::kNone) break;
          if (t == ModelCode::kSeveralTransitions || !code_.atom_fire(atom.type, t, marking, f)) {
            return false;
          }
        }
      }
      return update_atom(atom, f, marking);
    }
  }

  /// InteractionExecution::execute_in_sequence for a rendezvous: `down` over the value, its data
  /// written back, then the ports in parameter order.
  [[gnu::always_inline]] bool fire_connector(const FlatTables::Connector& c) {
    if (c.has_down) connector_code_.down(c, *state_, value_data_.data());
    std::copy_n(value_data_.begin() + c.value_data, c.data_size, state_->data.begin() + c.data);
    for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) {
      if (c.triggered && chosen_[i] == Flag::Off) continue;
      if (!fire_port(t_.ports[i])) return false;
    }
    return true;
  }

  /// The item at position `p` as the Runtime computes it: a connector's value when all its ports
  /// offer and its guard holds (then its `up` runs), an internal port's offer.
  void recompute(std::uint32_t p) {
    if (timed_) {
      recompute_timed(p);
    } else {
      recompute_untimed(p);
    }
  }

  /// recompute on an untimed layout: whether the item is enabled, and eager.
  void recompute_untimed(std::uint32_t p) {
    bool enabled = true;
    bool eager = false;
    if (p < connector_count_ && t_.connectors[p].triggered) {
      enabled = recompute_broadcast(t_.connectors[p], eager);
    } else if (p < connector_count_) {
      const FlatTables::Connector& c = t_.connectors[p];
      for (std::uint32_t i = c.first_port; i < c.ports_end && enabled; ++i) {
        const std::optional<AtomPortValue>& offer = offers_[t_.ports[i].offer];
        enabled = offer.has_value();
        eager = eager || (enabled && offer->constraint.urgency == bipc::Urgency::Eager);
      }
      if (enabled) enabled = value_allowed(c);
    } else {
      const std::optional<AtomPortValue>& offer = offers_[t_.internal[p - connector_count_].offer];
      enabled = offer.has_value();
      eager = enabled && offer->constraint.urgency == bipc::Urgency::Eager;
    }
    index_.set(p, enabled);
    const bool now_eager = enabled && eager;
    if (now_eager != (eager_[p] == Flag::On)) {
      eager_[p] = flag(now_eager);
      eager_count_ += now_eager ? 1 : -1;
    }
  }

  /// Whether a broadcast is enabled: some trigger offers; the offering ports are its interaction
  /// (chosen_). Its offers must share one constraint (Runtime::add_largest_values), else the
  /// Runtime enumerates its interactions (priorities of maximal progress) or, when it cannot,
  /// fails: both beyond this path.
  bool recompute_broadcast(const FlatTables::Connector& c, bool& eager) {
    bool trigger = false, mixed = false;
    const AtomPortValue* first = nullptr;
    for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) {
      const std::optional<AtomPortValue>& offer = offers_[t_.ports[i].offer];
      chosen_[i] = flag(offer.has_value());
      if (!offer) continue;
      trigger = trigger || t_.ports[i].trigger;
      if (first == nullptr) first = &*offer;
      mixed = mixed || offer->constraint.urgency != first->constraint.urgency;
    }
    if (mixed && (trigger || !c.enumerated)) beyond_ = true;
    eager = first != nullptr && first->constraint.urgency == bipc::Urgency::Eager;
    return trigger;
  }

  /// recompute on a timed layout: the item's constraint too, the intersection of its ports'
  /// (Runtime::add_choice); a connector whose ports' windows do not meet is not enabled, and
  /// its guard not run (Runtime::keep_value_if_allowed).
  [[gnu::always_inline]] void recompute_timed(std::uint32_t p) {
    // Narrowed in place, field by field: a Constraint built on the stack and copied whole
    // stalled on store forwarding.
    Constraint& raw = raw_[p];
    raw.interval.left = kMinusInfinity;
    raw.interval.right = kPlusInfinity;
    raw.interval.left_open = raw.interval.right_open = false;
    raw.urgency = bipc::Urgency::Lazy;
    bool enabled = true;
    if (p < connector_count_) {
      const FlatTables::Connector& c = t_.connectors[p];
      for (std::uint32_t i = c.first_port; i < c.ports_end && enabled; ++i) {
        const std::optional<AtomPortValue>& offer = offers_[t_.ports[i].offer];
        enabled = offer.has_value();
        if (enabled) detail::add_offer_constraint(raw, offer->constraint);
      }
      enabled = enabled && !raw.interval.empty() && value_allowed(c);
    } else {
      const std::optional<AtomPortValue>& offer = offers_[t_.internal[p - connector_count_].offer];
      enabled = offer.has_value();
      if (enabled) detail::add_offer_constraint(raw, offer->constraint);
    }
    enabled_[p] = flag(enabled);
  }

  /// Whether the item at position `p` is enabled, its constraint aside: every port of its
  /// connector offers and the connector's value is allowed, or its internal port offers.
  [[gnu::always_inline]] bool offered(std::uint32_t p) {
    if (p >= connector_count_) return offers_[t_.internal[p - connector_count_].offer].has_value();
    const FlatTables::Connector& c = t_.connectors[p];
    for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) {
      if (!offers_[t_.ports[i].offer]) return false;
    }
    return value_allowed(c);
  }

  /// Runtime::connector_code_allows: the connector's data copied into its value, the guard, then
  /// `up` when it holds.
  /// Inline for a connector without data or code (the check), out of line otherwise.
  [[gnu::always_inline]] bool value_allowed(const FlatTables::Connector& c) {
    if (c.data_size == 0 && !c.guarded) return true;
    return connector_code_.allowed(c, *state_, value_data_.data());
  }

  Code& code_;
  const Layout& layout_;
  const FlatTables t_;
  // t_'s connectors and positions, counted once: a vector's size divides by its element's.
  const std::uint32_t connector_count_, position_count_;
  const FlatConnectorCode<Code> connector_code_;  // over t_
  Runtime* runtime_ = nullptr;
  RunState* state_ = nullptr;
  RandomStream* random_ = nullptr;
  DatePlanner* planner_ = nullptr;
  bool asap_ = false, first_enabled_ = false;
  bool timed_ = false;  // the items have windows of their own (timed_step)
  std::vector<std::optional<AtomPortValue>> offers_;
  std::vector<Val> value_data_;
  EnabledPositions index_;  // a position holds one item at most
  SharedWindowChooser shared_window_;
  std::vector<Flag> eager_;  // per position: its item is enabled and eager
  std::ptrdiff_t eager_count_ = 0;
  // The atoms a step fired, and the positions it recomputed, marked by the step's stamp.
  // Only where the tables list no affected positions (gathers_touched).
  std::uint64_t stamp_ = 0;
  std::vector<std::uint64_t> touched_, recomputed_;
  std::vector<Index> touched_list_;
  std::vector<Flag> chosen_;  // per port of a broadcast: it offers (its interaction's)
  bool beyond_ = false;       // a recomputed item is beyond this path: the step ends it
  // Timed steps: per position whether its item is enabled and its constraint; the choice.
  std::vector<Flag> enabled_;
  std::vector<Constraint> raw_;
  FlatTimedChoice timed_choice_;
  std::optional<Start> start_;  // Run::kept_start: what begin() computed from that state
  // Run::checks_kept_state: the bytes the step may write, before it; whether it kept them.
  bool checks_kept_ = false, kept_ = false;
  std::optional<WrittenSlices> written_;  // made by the first run that checks
};

/// The compiled step path over `code` for `system`, or nullptr when flat_tables does not cover
/// it.
template <class Code>
std::unique_ptr<CompiledSteps> make_flat_steps(Code& code, const bipc::ir::System& system,
                                               const Layout& layout) {
  std::optional<FlatTables> tables = flat_tables(system, layout, code);
  if (!tables) return nullptr;
  return std::make_unique<FlatSteps<Code>>(code, system, layout, std::move(*tables));
}

}  // namespace smcbip::engines
