// Bookkeeping of the optimised scheduler: which connectors' interaction values are stale after
// an execution, so that Runtime::compute_items recomputes only those.
#pragma once

#include <cstdint>
#include <queue>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/time_value.h"
#include "engines/semantics/index_set.h"
#include "engines/semantics/layout.h"

namespace smcbip::engines {

/// Tracks, between two computations of the enabled items, the atoms an execution touched and
/// derives the connectors whose values may differ from the kept ones. A connector's values are a
/// function of its bound atoms' offers and data, its sub-connectors' values and its own data
/// (written only when it executes, which fires its atoms); connectors whose guard or `up` may
/// read anything else (extern calls, which may draw from the run's random stream) are always
/// stale. Priorities: see needs_priorities.
class ConnectorCache {
 public:
  ConnectorCache(const bipc::ir::System& system, const Layout& layout);

  /// Forgets every kept value: the next computation is a full one (initialize, restore).
  void invalidate_all() { all_stale_ = true; }
  /// Whether the next computation must be a full one.
  bool all_stale() const { return all_stale_; }
  /// The atom's marking, data, resume state or offers may have changed.
  [[gnu::always_inline]] void touch_atom(bipc::ir::Index atom) {
    if (touched_[atom]) return;
    touched_[atom] = 1;
    touched_list_.push_back(atom);
  }
  /// The atoms touched since the last begin().
  const std::vector<bipc::ir::Index>& touched_atoms() const { return touched_list_; }

  /// Starts a computation at date `now`: collects the stale connectors (everything when `full`),
  /// closed upwards over the connectors binding them. A connector of a touched atom for which
  /// `keeps_no_values(connector)` holds (it had no values and still can have none) stays as it
  /// is: neither it nor its binders become stale on its account.
  template <class KeepsNoValues>
  void begin(TimeValue now, bool full, KeepsNoValues keeps_no_values) {
    if (!start(now, full)) {
      ++generation_;
      for (bipc::ir::Index atom : touched_list_) {
        for (bipc::ir::Index k : atom_connectors_[atom]) {
          if (stale_[k] || checked_[k] == generation_) continue;
          checked_[k] = generation_;
          if (keeps_no_values(k)) continue;
          if (direct_[k]) {
            direct_work_.push_back(k);
          } else {
            mark_stale_with_binders(k);
          }
        }
      }
      queue_unchanged_work();
    }
    for (bipc::ir::Index atom : touched_list_) touched_[atom] = 0;
    touched_list_.clear();
  }
  /// Tells that the connector's values depend on its atoms' offers alone (no guard, no `up`, no
  /// sub-connector). If no connector binds it and its compound has no priority rules, no other
  /// connector's values depend on it or it on them: it becomes direct, computed apart from the
  /// compound order, and a begin() that is not full lists it in direct_work() instead of
  /// marking it stale.
  void note_offers_only(bipc::ir::Index connector) {
    if (parents_[connector].empty() && !ruled_[connector]) direct_[connector] = 1;
  }
  /// After a begin() that was not full: the direct connectors whose values must be computed
  /// (the others go through next_compound). Valid until end().
  const std::vector<bipc::ir::Index>& direct_work() const { return direct_work_; }
  /// After a begin() that was not full: the next compound, deepest (largest index) first, with
  /// connectors to compute or whose priorities to evaluate; false when there is none left.
  /// Processing a compound may add enclosing compounds (priorities_changed), never deeper ones.
  bool next_compound(bipc::ir::Index& compound);
  /// The connectors of the compound next_compound gave that may need computing or their
  /// priorities evaluating, in the compound's order: its stale and date-dependent ones, or all
  /// of them when it has priority rules. Valid until end().
  const std::vector<bipc::ir::Index>& work(bipc::ir::Index compound);
  bool stale(bipc::ir::Index connector) const { return stale_[connector] != 0; }
  /// Whether the connector's values must be computed now: true once per computation for each
  /// stale connector.
  bool claim(bipc::ir::Index connector) {
    if (!stale_[connector] || computed_[connector]) return false;
    computed_[connector] = 1;
    return true;
  }
  /// Whether the priorities (the `after` constraints) of the connector's values must be
  /// evaluated again: its values are new; its compound has priority rules (their guards read
  /// any atom's data and their closure spans other connectors); or time passed and maximal
  /// progress restricted one of its values (restrictions depend on the date).
  bool needs_priorities(bipc::ir::Index connector) const {
    return stale_[connector] || ruled_[connector] ||
           (time_passed_ && time_dependent_.contains(connector));
  }
  /// Whether the connector's compound has priority rules.
  bool ruled(bipc::ir::Index connector) const { return ruled_[connector] != 0; }
  /// Maximal progress restricted a value of the connector: its priorities depend on the date.
  void note_time_dependent(bipc::ir::Index connector) { time_dependent_.insert(connector); }
  void clear_time_dependent(bipc::ir::Index connector) { time_dependent_.erase(connector); }
  /// The connectors some value of which, with priorities applied, is urgent (not lazy): only
  /// those bound the time that may pass, so Runtime::wait_interval visits only them.
  const IndexSet& urgent() const { return urgent_; }
  void set_urgent(bipc::ir::Index connector, bool urgent) { urgent_.assign(connector, urgent); }
  /// The connector's `after` constraints were evaluated again: connectors of enclosing compounds
  /// that bind its export see them, so become stale (they come later in the bottom-up order).
  void priorities_changed(bipc::ir::Index connector);
  /// Ends a successful computation: every connector's values are up to date.
  void end();

 private:
  /// The first part of begin(): true when the computation is a full one (all stale).
  bool start(TimeValue now, bool full);
  /// The last part of a begin() that is not full: volatile connectors become stale; date-
  /// dependent connectors (when time passed) and compounds with priority rules are queued.
  void queue_unchanged_work();
  void mark_stale(bipc::ir::Index connector) {
    if (!stale_[connector]) mark_stale_with_binders(connector);
  }
  void mark_stale_with_binders(bipc::ir::Index connector);
  /// Lists the connector in its compound's work and queues the compound.
  void add_work(bipc::ir::Index connector);
  void queue_compound(bipc::ir::Index compound);
  void clear_work();

  const bipc::ir::System& system_;
  std::vector<std::vector<bipc::ir::Index>> atom_connectors_;  // per atom: connectors binding it
  std::vector<std::vector<bipc::ir::Index>> parents_;  // per connector: connectors binding it
  std::vector<bipc::ir::Index> volatile_;              // connectors whose code is not cacheable
  std::vector<std::uint8_t> ruled_;    // per connector: its compound has priority rules
  std::vector<bipc::ir::Index> rank_;  // per connector: its position in its compound's list
  IndexSet time_dependent_, urgent_;   // connectors
  std::vector<std::uint8_t> stale_, computed_, direct_;
  std::vector<bipc::ir::Index> direct_work_;
  std::vector<bipc::ir::Index> stale_list_;
  // Per compound: the connectors to visit (listed once each: in_work_) and whether the
  // compound is queued; queued compounds wait in a max-heap, since enclosing compounds have
  // smaller indices and must come after the compounds they contain.
  std::vector<std::vector<bipc::ir::Index>> work_;
  std::vector<std::uint8_t> in_work_, queued_;
  std::priority_queue<bipc::ir::Index> queue_;
  std::vector<bipc::ir::Index> worked_;  // compounds given by next_compound since begin()
  std::vector<std::uint32_t> checked_;   // per connector: the last begin() that looked at it
  std::uint32_t generation_ = 0;
  std::vector<std::uint8_t> touched_;
  std::vector<bipc::ir::Index> touched_list_;
  const std::vector<bipc::ir::Index>& ruled_compounds_;  // Layout::ruled_compounds
  bool all_stale_ = true;
  bool time_passed_ = true;
  TimeValue last_now_ = 0;
};

}  // namespace smcbip::engines
