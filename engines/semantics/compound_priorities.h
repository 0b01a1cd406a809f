// The compound priority rules of one run and maximal progress: their cycle check, and the
// restriction of each connector's interaction values by the values that dominate them.
#pragma once

#include <cstddef>
#include <deque>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/connector_cache.h"
#include "engines/semantics/connector_values.h"
#include "engines/semantics/index_list.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

/// Applies the priorities of a run to its connectors' interaction values. It reads the state,
/// the values and their lists per connector, which its owner keeps, and notes in the
/// connector cache which results depend on time and which connectors are urgent. A rule's high
/// side may name a connector not computed yet: `connectors` computes it.
class CompoundPriorities {
 public:
  CompoundPriorities(const bipc::ir::System& system, const Layout& layout, bool maximal_progress,
                     ModelCode& eval, RunState& state, ModelError& error,
                     ConnectorValues& connectors, ConnectorCache& cache, const Interval& time_bound)
      : system_(system),
        layout_(layout),
        maximal_progress_(maximal_progress),
        eval_(eval),
        state_(state),
        error_(error),
        connectors_(connectors),
        values_(connectors.values()),
        connector_values_(connectors.connector_values()),
        cache_(cache),
        time_bound_(time_bound) {}

  /// False with error 3 set when the active rules of a compound form a cycle.
  bool check_cycles();
  /// Each value's `after` from its `raw` constraint, restricted by maximal progress and by the
  /// rules; notes the connector's urgency (and, when it was not stale, that its binders must
  /// see the change) in the cache.
  void recompute(Index connector);

 private:
  /// An interaction named by a priority rule: its connector and port set.
  using RuleNode = std::pair<Index, PortSet>;

  /// Where a rule's guard finds the data of the atoms it reads (Frame::instance_slot).
  static Val* instance_slot(const void* context, Index atom, std::uint16_t slot);
  bool rule_guard(const PriorityRule& rule);
  bool applies_low(const PriorityRule& rule, const RuleNode& interaction) const;
  /// The interactions of the rule's high (low) side, into `out`.
  void high_side(const PriorityRule& rule, std::vector<RuleNode>& out) const;
  void low_side(const PriorityRule& rule, std::vector<RuleNode>& out) const;
  void add_defined(Index connector, std::vector<RuleNode>& out) const;
  /// Whether the chains of active rules from `path`'s last node close a cycle (then in `cycle`).
  bool find_cycle(const std::vector<PriorityRule>& rules, const std::vector<RuleNode>& path,
                  int depth, std::vector<RuleNode>& cycle);
  bool dominated_locally(const InteractionValue& low, const InteractionValue& high) const;
  void restrict_by(Constraint& c, const Constraint& dominator) const;
  void apply(InteractionValue& value, Index connector);
  /// Restricts `value` by the dominators of every high side reached from `low` through active
  /// rules of `rules` (apply; `depth`: of this recursion).
  void dominate(InteractionValue& value, const std::vector<PriorityRule>& rules,
                const RuleNode& low, std::size_t depth);

  const bipc::ir::System& system_;
  const Layout& layout_;
  bool maximal_progress_;
  ModelCode& eval_;
  RunState& state_;
  ModelError& error_;
  ConnectorValues& connectors_;
  std::vector<InteractionValue>& values_;
  const std::vector<IndexList>& connector_values_;
  ConnectorCache& cache_;
  const Interval& time_bound_;  // the owner's bound of the state the items are computed in
  // Per compound: the sets of active priority rules already found free of cycles.
  std::vector<std::set<std::vector<bool>>> acyclic_rule_sets_;
  std::vector<bool> active_rules_;  // check_cycles' buffer
  // apply's buffers: the rule nodes visited (sorted), the high sides per depth.
  std::vector<RuleNode> visited_rule_nodes_;
  std::deque<std::vector<RuleNode>> high_sides_;
};

}  // namespace smcbip::engines
