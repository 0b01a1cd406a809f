// Checks of compound priorities: the interactions they name, their guards, and the cycles they
// form with each other and with maximal progress (after the Verimag compiler's priority graph).
#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

#include "bipc/check/detail/check_compound.h"

namespace smcbip::bipc::detail {

namespace {

/// One side of a rule after resolution.
struct Side {
  bool wildcard = false;   // `*:*`
  int connector = -1;      // otherwise the connector's index
  bool all_ports = false;  // `c:*`
  std::vector<int> ports;  // otherwise the connector's port parameters, sorted
  bool valid = false;
};

struct Rule {
  Side low, high;
  bool guarded = false;
  bool in_graph = false;  // takes part in the cycle analysis
};

std::string written(const ast::InteractionPattern& pattern) {
  if (!pattern.connector) return "*:*";
  std::string text = pattern.connector->text + ":";
  if (pattern.all_ports || pattern.ports.empty()) return text + "*";
  for (std::size_t i = 0; i < pattern.ports.size(); ++i) {
    text += (i == 0 ? "" : ",") + pattern.ports[i].text();
  }
  return text;
}

bool is_top_level(const CompoundScope& scope, int connector) {
  return scope.bound_by[connector].empty();
}

/// The connector's port parameters named by `c:a.p,b.q`, or nullopt after an error.
std::optional<std::vector<int>> resolve_ports(const ast::InteractionPattern& pattern, int index,
                                              CompoundScope& scope) {
  const ast::ConnectorDecl& connector = scope.type.connectors[index];
  std::vector<int> ports;
  bool ok = true;
  for (const ast::QualifiedName& name : pattern.ports) {
    const std::string text = name.text();
    auto found =
        std::find_if(connector.ports.begin(), connector.ports.end(),
                     [&](const ast::QualifiedName& bound) { return bound.text() == text; });
    if (found == connector.ports.end()) {
      scope.diags.error(name.loc(),
                        "'" + text + "' is not a port of connector '" + connector.name.text + "'");
      ok = false;
      continue;
    }
    const int port = static_cast<int>(found - connector.ports.begin());
    if (std::find(ports.begin(), ports.end(), port) != ports.end()) {
      scope.diags.error(name.loc(), "'" + text + "' appears twice in the interaction of '" +
                                        connector.name.text + "'");
      ok = false;
    }
    ports.push_back(port);
  }
  if (!ok) return std::nullopt;
  std::sort(ports.begin(), ports.end());
  return ports;
}

bool define_is_resolved(const std::vector<ast::PortExpr>& define) {
  return std::all_of(define.begin(), define.end(), [](const ast::PortExpr& node) {
    return node.port ? node.port_index >= 0 : define_is_resolved(node.children);
  });
}

void check_allowed(const ast::InteractionPattern& pattern, int index, const std::vector<int>& ports,
                   CompoundScope& scope) {
  const ast::ConnectorTypeDecl* type = scope.type.connectors[index].connector_type;
  if (type == nullptr || !define_is_resolved(type->define)) return;
  if (define_allows(type->define, ports)) return;
  scope.diags.error(pattern.loc, "'" + written(pattern) + "' is not an interaction of connector '" +
                                     pattern.connector->text + "': the define of '" +
                                     type->name.text + "' does not allow it");
}

Side resolve_side(ast::InteractionPattern& pattern, CompoundScope& scope) {
  Side side;
  if (!pattern.connector) {
    pattern.connector_index = -1;
    side.wildcard = side.valid = true;
    return side;
  }
  auto it = scope.connector_index.find(pattern.connector->text);
  if (it == scope.connector_index.end()) {
    scope.diags.error(pattern.connector->loc,
                      "unknown connector '" + pattern.connector->text + "' in priority");
    return side;
  }
  pattern.connector_index = side.connector = it->second;
  side.valid = true;
  if (!is_top_level(scope, side.connector)) {
    scope.diags.error(pattern.connector->loc,
                      "priority must name a top-level connector: '" + pattern.connector->text +
                          "' is bound by '" +
                          scope.type.connectors[scope.bound_by[side.connector].front()].name.text +
                          "'");
    side.valid = false;
  }
  if (pattern.all_ports || pattern.ports.empty()) {
    side.all_ports = true;
    return side;
  }
  std::optional<std::vector<int>> ports = resolve_ports(pattern, side.connector, scope);
  if (!ports) return Side{};
  check_allowed(pattern, side.connector, *ports, scope);
  side.ports = std::move(*ports);
  return side;
}

bool subset(const std::vector<int>& a, const std::vector<int>& b) {
  return std::includes(b.begin(), b.end(), a.begin(), a.end());
}

/// Whether every interaction `inner` denotes lies within `outer` (Verimag's isIncludedIn:
/// the same connector, and `c:*` on either side or the port sets included).
bool included_in(const Side& inner, const Side& outer) {
  if (inner.connector != outer.connector) return false;
  return inner.all_ports || outer.all_ports || subset(inner.ports, outer.ports);
}

/// A rule `I < J` on a single connector compared with maximal progress, which already puts
/// every interaction below the larger ones containing it. Returns false when the rule cannot
/// take part in the cycle analysis (it is a cycle on its own).
bool check_against_maximal_progress(const Rule& rule, const ast::CompoundPriorityDecl& decl,
                                    Diagnostics& diags) {
  if (rule.low.wildcard || rule.high.wildcard || rule.low.connector != rule.high.connector) {
    return true;
  }
  const std::string low = written(decl.low), high = written(decl.high);
  const bool explicit_sides = !rule.low.all_ports && !rule.high.all_ports;
  if (explicit_sides && rule.low.ports != rule.high.ports) {
    if (subset(rule.high.ports, rule.low.ports)) {
      diags.error(decl.name.loc, "priority contradicts maximal progress: '" + high +
                                     "' is contained in '" + low +
                                     "', so the rule and maximal progress form a cycle");
      return false;
    }
    if (subset(rule.low.ports, rule.high.ports)) {
      diags.warning(decl.name.loc, "priority duplicates maximal progress: '" + low +
                                       "' is contained in '" + high + "'");
    }
    return true;
  }
  if (included_in(rule.high, rule.low)) {
    const std::string rule_text = "'" + low + "' < '" + high + "'";
    diags.error(decl.name.loc, "priority '" + decl.name.text +
                                   "' makes an interaction lower than itself: " + rule_text);
    return false;
  }
  return true;
}

/// Whether some top-level connector is neither `a` nor `b` (what two `*:*` sides range over),
/// given how many top-level connectors there are.
bool other_top_level_exists(const CompoundScope& scope, int top_level_count, int a, int b) {
  int excluded = a >= 0 && is_top_level(scope, a) ? 1 : 0;
  if (b >= 0 && b != a && is_top_level(scope, b)) ++excluded;
  return top_level_count > excluded;
}

/// Whether `from`'s high side meets `to`'s low side, so that the two rules chain
/// (Verimag's areConnected): `*:*` stands for every top-level connector but the other side's.
bool chains(const CompoundScope& scope, int top_level_count, const Rule& from, const Rule& to) {
  if (from.high.wildcard) {
    if (to.low.wildcard) {
      return other_top_level_exists(scope, top_level_count, from.low.connector, to.high.connector);
    }
    return from.low.connector != to.low.connector;
  }
  if (to.low.wildcard) return to.high.connector != from.high.connector;
  return included_in(from.high, to.low);
}

/// The rules a rule may chain to: those whose low side is on the connector of its high side,
/// and those whose low side is `*:*`; every rule when its own high side is `*:*`. Indexing keeps
/// the graph near linear for the usual explicit rules instead of testing every pair.
class ChainCandidates {
 public:
  explicit ChainCandidates(const std::vector<std::size_t>& usable, const std::vector<Rule>& rules)
      : usable_(usable) {
    for (std::size_t r : usable) {
      if (rules[r].low.wildcard) {
        wildcard_low_.push_back(r);
      } else {
        by_low_connector_[rules[r].low.connector].push_back(r);
      }
    }
  }

  template <typename Visit>
  void for_each(const Rule& from, Visit visit) const {
    if (from.high.wildcard) {
      for (std::size_t r : usable_) visit(r);
      return;
    }
    if (auto found = by_low_connector_.find(from.high.connector);
        found != by_low_connector_.end()) {
      for (std::size_t r : found->second) visit(r);
    }
    for (std::size_t r : wildcard_low_) visit(r);
  }

 private:
  const std::vector<std::size_t>& usable_;
  std::vector<std::size_t> wildcard_low_;
  std::unordered_map<int, std::vector<std::size_t>> by_low_connector_;
};

Digraph rule_graph(const CompoundScope& scope, const std::vector<Rule>& rules, bool guarded_too) {
  Digraph graph(rules.size());
  int top_level_count = 0;
  for (std::size_t k = 0; k < scope.type.connectors.size(); ++k) {
    if (is_top_level(scope, static_cast<int>(k))) ++top_level_count;
  }
  std::vector<std::size_t> usable;
  for (std::size_t r = 0; r < rules.size(); ++r) {
    if (rules[r].in_graph && (guarded_too || !rules[r].guarded)) usable.push_back(r);
  }
  const ChainCandidates candidates(usable, rules);
  for (std::size_t a : usable) {
    candidates.for_each(rules[a], [&](std::size_t b) {
      if (a != b && chains(scope, top_level_count, rules[a], rules[b])) {
        boost::add_edge(a, b, graph);
      }
    });
  }
  return graph;
}

std::string describe_cycle(const CompoundScope& scope, const std::vector<int>& cycle) {
  std::string text;
  for (int r : cycle) {
    const ast::CompoundPriorityDecl& decl = scope.type.priorities[r];
    text += decl.name.text + " (" + written(decl.low) + " < " + written(decl.high) + ") -> ";
  }
  return text + scope.type.priorities[cycle.front()].name.text;
}

/// Reports one cycle per strongly connected component, at its first rule; returns the rules
/// of the components reported.
std::set<int> report_cycles(CompoundScope& scope, const Digraph& graph,
                            const std::set<int>& already, bool as_error) {
  const std::vector<bool> cyclic = on_long_cycle(graph);
  const std::vector<int> component = strong_component_of(graph);
  std::map<int, std::vector<int>> members;  // cyclic component -> its rules
  for (std::size_t r = 0; r < cyclic.size(); ++r) {
    if (cyclic[r]) members[component[r]].push_back(static_cast<int>(r));
  }
  std::set<int> rules_reported;
  for (const auto& [unused, rules] : members) {
    bool overlaps = false;
    for (int s : rules) {
      rules_reported.insert(s);
      overlaps = overlaps || already.count(s) > 0;
    }
    if (overlaps) continue;
    const int r = rules.front();
    const std::string cycle = describe_cycle(scope, shortest_cycle_through(graph, r));
    const Location at = scope.type.priorities[r].name.loc;
    if (as_error) {
      scope.diags.error(at, "priorities form a cycle: " + cycle);
    } else {
      scope.diags.warning(at, "priorities form a cycle when their guards hold: " + cycle);
    }
  }
  return rules_reported;
}

void check_guard(ast::CompoundPriorityDecl& decl, CompoundScope& scope) {
  if (!decl.guard) return;
  ExprContext ctx;
  ctx.where = ExprContext::Where::CompoundPriorityGuard;
  ctx.package = &scope.package;
  ctx.compound = &scope.type;
  check_condition(*decl.guard, ctx, scope.symbols, scope.diags, "priority guard");
}

Rule check_rule(ast::CompoundPriorityDecl& decl, CompoundScope& scope) {
  Rule rule;
  rule.guarded = decl.guard != nullptr;
  rule.low = resolve_side(decl.low, scope);
  rule.high = resolve_side(decl.high, scope);
  check_guard(decl, scope);
  if (rule.low.wildcard && rule.high.wildcard) {
    scope.diags.error(decl.name.loc,
                      "'*:* < *:*' is not allowed: at most one side of a priority "
                      "may be '*:*'");
    return rule;
  }
  if (!rule.low.valid || !rule.high.valid) return rule;
  rule.in_graph = check_against_maximal_progress(rule, decl, scope.diags);
  return rule;
}

}  // namespace

void check_compound_priorities(CompoundScope& scope) {
  std::set<std::string> names;
  std::vector<Rule> rules;
  for (ast::CompoundPriorityDecl& decl : scope.type.priorities) {
    if (!decl.name.text.empty() && !names.insert(decl.name.text).second) {
      scope.diags.error(decl.name.loc, "duplicate priority '" + decl.name.text + "'");
    }
    rules.push_back(check_rule(decl, scope));
  }
  // Only cycles of unguarded rules are certain; a guarded cycle is a run-time error when all
  // its guards hold (the reference engine exits with code 3), so it is only a warning here.
  const std::set<int> errors = report_cycles(scope, rule_graph(scope, rules, false), {}, true);
  report_cycles(scope, rule_graph(scope, rules, true), errors, false);
}

}  // namespace smcbip::bipc::detail
