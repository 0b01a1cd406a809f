// Priorities of one run: the compound priority rules (their closure and cycle check) and
// maximal progress, applied to the connectors' interaction values.
#include "engines/semantics/compound_priorities.h"

#include <algorithm>
#include <bit>

#include "engines/semantics/detail/runtime_shared.h"

namespace smcbip::engines {

using bipc::Urgency;
using bipc::ir::kNone;
using detail::subset;
using detail::wait;

Val* CompoundPriorities::instance_slot(const void* context, Index atom, std::uint16_t slot) {
  const auto& p = *static_cast<const CompoundPriorities*>(context);
  return &p.state_.data[p.layout_.atom_data[atom] + slot];
}

bool CompoundPriorities::rule_guard(const PriorityRule& rule) {
  const bipc::ir::Priority& p = system_.compounds[rule.compound].priorities[rule.rule];
  if (p.guard.empty()) return true;
  Frame f;
  f.instance_slot = &CompoundPriorities::instance_slot;
  f.instance_context = this;
  f.now = state_.now;
  return eval_.holds(p.guard, f);
}

namespace {

std::string interaction_name(const bipc::ir::System& system, Index connector, PortSet ports) {
  std::string text = bipc::ir::last_component(system.connectors[connector].path) + ":";
  const auto& type = system.connector_types[system.connectors[connector].type];
  for (std::size_t i = 0; i < type.ports.size(); ++i) {
    if (ports & (PortSet{1} << i)) text += " " + type.ports[i].first;
  }
  return text;
}

}  // namespace

bool CompoundPriorities::applies_low(const PriorityRule& rule, const RuleNode& x) const {
  if (rule.low_connector == kNone) {
    return layout_.top_level[x.first] && x.first != rule.high_connector;
  }
  return x.first == rule.low_connector &&
         (x.second == rule.low || (maximal_progress_ && subset(x.second, rule.low)));
}

void CompoundPriorities::add_defined(Index connector, std::vector<RuleNode>& out) const {
  for (const DefinedInteraction& d : layout_.defined[connector])
    out.push_back({connector, d.ports});
}

void CompoundPriorities::high_side(const PriorityRule& rule, std::vector<RuleNode>& out) const {
  out.clear();
  if (rule.high_connector == kNone) {
    for (Index k : system_.compounds[rule.compound].connectors) {
      if (layout_.top_level[k] && k != rule.low_connector) add_defined(k, out);
    }
  } else if (rule.high == 0) {
    add_defined(rule.high_connector, out);
  } else {
    out.push_back({rule.high_connector, rule.high});
  }
}

void CompoundPriorities::low_side(const PriorityRule& rule, std::vector<RuleNode>& out) const {
  out.clear();
  if (rule.low_connector != kNone) {
    out.push_back({rule.low_connector, rule.low});
    return;
  }
  for (Index k : system_.compounds[rule.compound].connectors) {
    if (layout_.top_level[k] && k != rule.high_connector) add_defined(k, out);
  }
}

bool CompoundPriorities::find_cycle(const std::vector<PriorityRule>& rules,
                                    const std::vector<RuleNode>& path, int depth,
                                    std::vector<RuleNode>& cycle) {
  // Depth-first over the static rule chains from a low side (E/Interaction.cpp of the reference
  // engine): a high side included in an interaction already on the path closes a cycle.
  if (depth > 64) return false;
  const RuleNode x = path.back();
  std::vector<RuleNode> highs;
  for (std::size_t r = 0; r < rules.size(); ++r) {
    if (!active_rules_[r] || !applies_low(rules[r], x)) continue;
    const RuleNode own_low{rules[r].low_connector, rules[r].low};
    high_side(rules[r], highs);
    for (const RuleNode& d : highs) {
      std::vector<RuleNode> next = path;
      if (rules[r].low_connector != kNone && x != own_low) next.push_back(own_low);
      next.push_back(d);
      for (std::size_t i = 0; i + 1 < next.size(); ++i) {
        if (next[i].first == d.first && subset(d.second, next[i].second)) {
          cycle.assign(next.begin() + static_cast<std::ptrdiff_t>(i), next.end());
          if (d != next[i]) cycle.push_back(next[i]);
          return true;
        }
      }
      if (find_cycle(rules, next, depth + 1, cycle)) return true;
    }
  }
  return false;
}

bool CompoundPriorities::check_cycles() {
  if (layout_.ruled_compounds.empty()) return true;
  acyclic_rule_sets_.resize(layout_.rules.size());
  for (const Index compound : layout_.ruled_compounds) {
    const std::vector<PriorityRule>& rules = layout_.rules[compound];
    std::vector<bool>& active = active_rules_;
    active.assign(rules.size(), false);
    for (std::size_t r = 0; r < rules.size(); ++r) active[r] = rule_guard(rules[r]);
    // The search depends only on which rules are active: a set found acyclic stays so.
    if (acyclic_rule_sets_[compound].count(active)) continue;
    std::vector<RuleNode> cycle, lows;
    for (std::size_t r = 0; r < rules.size(); ++r) {
      if (!active[r]) continue;
      low_side(rules[r], lows);
      for (const RuleNode& low : lows) {
        if (!find_cycle(rules, {low}, 0, cycle)) continue;
        std::string text;
        for (std::size_t i = 0; i < cycle.size(); ++i) {
          text += (i ? " < " : "") + interaction_name(system_, cycle[i].first, cycle[i].second);
        }
        error_ = {3, "cycle in priorities! (" + text + ")", {}};
        return false;
      }
    }
    acyclic_rule_sets_[compound].insert(active);
  }
  return true;
}

void CompoundPriorities::restrict_by(Constraint& c, const Constraint& dominator) const {
  // A dominated value may only run where its dominator cannot (TimingConstraint::applyPriority
  // of the reference engine): after the dominator's window if that meets the waiting window,
  // else before it. Invariants and pending resumes bound the waiting window too: a dominator
  // that time cannot reach before they force a step must not block the dominated value (else
  // writers_buffer's W1 write, dominated by W2's next period beyond W1's invariant, time-locks).
  const Interval window = wait(c, state_.now).intersect(time_bound_);
  const Interval meet = dominator.interval.intersect(window);
  Interval allowed;
  if (!meet.empty()) {
    if (meet.right == kPlusInfinity) {
      c.interval = Interval::none();
      return;
    }
    allowed = {meet.right, kPlusInfinity, !meet.right_open, false};
  } else if (dominator.interval.left != kMinusInfinity && state_.now < dominator.interval.left) {
    allowed = {kMinusInfinity, dominator.interval.left, false, !dominator.interval.left_open};
  } else {
    if (dominator.interval.right == kPlusInfinity) {
      c.interval = Interval::none();
      return;
    }
    allowed = {dominator.interval.right, kPlusInfinity, !dominator.interval.right_open, false};
  }
  c.interval = c.interval.intersect(allowed);
}

bool CompoundPriorities::dominated_locally(const InteractionValue& low,
                                           const InteractionValue& high) const {
  // low <= high: port set inclusion, and for each sub-connector port of low, its
  // sub-interaction included in high's.
  if (!subset(low.ports, high.ports)) return false;
  for (std::size_t i = 0, j = 0; i < 64 && (low.ports >> i) != 0; ++i) {
    if (!(low.ports & (PortSet{1} << i))) continue;
    const PortValue& lv = low.choice[j++];
    const PortSet below = high.ports & ((PortSet{1} << i) - 1);
    const PortValue& hv = high.choice[static_cast<std::size_t>(std::popcount(below))];
    if (lv.from_atom != hv.from_atom) return false;
    if (!lv.from_atom && lv.sub != hv.sub && !dominated_locally(values_[lv.sub], values_[hv.sub])) {
      return false;
    }
  }
  return true;
}

void CompoundPriorities::apply(InteractionValue& value, Index k) {
  // Maximal progress: every enabled value of the same connector strictly above this one.
  if (maximal_progress_) {
    for (Index w : connector_values_[k]) {
      const InteractionValue& other = values_[w];
      if (&other == &value) continue;
      if (dominated_locally(value, other) && !dominated_locally(other, value)) {
        restrict_by(value.after, other.raw);
        cache_.note_time_dependent(k);
      }
    }
  }
  const std::vector<PriorityRule>& rules = layout_.rules[system_.connectors[k].parent];
  if (rules.empty()) return;
  // Rule closure: the dominators of every high side reached from this value through active
  // rules, whether or not the interactions in between are enabled.
  visited_rule_nodes_.clear();
  dominate(value, rules, {k, value.ports}, 0);
}

void CompoundPriorities::dominate(InteractionValue& value, const std::vector<PriorityRule>& rules,
                                  const RuleNode& low, std::size_t depth) {
  // Visited nodes: a sorted vector, which keeps its capacity from value to value.
  const auto at = std::lower_bound(visited_rule_nodes_.begin(), visited_rule_nodes_.end(), low);
  if (at != visited_rule_nodes_.end() && *at == low) return;
  visited_rule_nodes_.insert(at, low);
  if (depth == high_sides_.size()) high_sides_.emplace_back();
  std::vector<RuleNode>& highs = high_sides_[depth];  // a deque: deeper calls leave it in place
  // Only the rules whose low side may name the node's connector: a chain of n rules costs n
  // visits per value, not n^2.
  for (Index r : layout_.rules_by_low[low.first]) {
    const PriorityRule& rule = rules[r];
    if (!applies_low(rule, low) || !rule_guard(rule)) continue;
    high_side(rule, highs);
    for (const RuleNode& high : highs) {
      connectors_.compute_connector(high.first);
      for (Index w : connector_values_[high.first]) {
        const InteractionValue& other = values_[w];
        if (other.ports == high.second || (maximal_progress_ && subset(high.second, other.ports))) {
          restrict_by(value.after, other.raw);
        }
      }
      dominate(value, rules, high, depth + 1);
    }
  }
}

void CompoundPriorities::recompute(Index k) {
  cache_.clear_time_dependent(k);
  const IndexList& values = connector_values_[k];
  // Read through one pointer (values_ is the owner's, so each access would load it again);
  // only until apply, which may compute a connector and so grow values_.
  InteractionValue* const all = values_.data();
  for (Index v : values) all[v].after = all[v].raw;
  // A lone value without priority rules has nothing above it: it stays as it is.
  const bool alone = values.size() == 1 && !cache_.ruled(k);
  bool urgent = false;
  for (Index v : values) {
    if (!alone) apply(values_[v], k);
    const InteractionValue& value = values_[v];
    urgent = urgent || (value.raw.urgency != Urgency::Lazy && !value.after.interval.empty());
  }
  cache_.set_urgent(k, urgent);
  // A stale connector's binders are all stale already (ConnectorCache::begin).
  if (!cache_.stale(k)) cache_.priorities_changed(k);
}

}  // namespace smcbip::engines
