// Layout of run states and static tables of a system.
#include "engines/semantics/layout.h"

#include <algorithm>
#include <bit>
#include <functional>

#include "engines/semantics/maximal_interaction.h"

namespace smcbip::engines {

namespace {

using bipc::ir::DefineNode;
using bipc::ir::last_component;
using bipc::ir::System;

Val to_val(const bipc::ir::Value& v, StringPool* strings) {
  switch (v.kind) {
    case bipc::ir::ValueKind::Bool:
      return make_bool(v.b);
    case bipc::ir::ValueKind::Float:
      return make_float(v.f);
    case bipc::ir::ValueKind::String: {
      Val x;
      x.s = strings ? strings->intern(v.s) : 0;
      return x;
    }
    default:
      return make_int(v.i);
  }
}

bool has_trigger(const DefineNode& node) {
  for (const DefineNode& child : node.children) {
    if (child.trigger) return true;
  }
  return false;
}

/// Depth-first enumeration of presence variables; `work` holds what is still to expand, front
/// last (a stack), each a node with its presence or a child whose presence is to be chosen.
struct Enumerator {
  struct Item {
    const DefineNode* node;
    bool present;
    bool choose;  // presence to be iterated over `domain`
    bool domain_one, domain_zero;
  };
  std::vector<PortSet>& out;
  std::size_t limit;
  bool exceeded = false;

  void run(std::vector<Item> work, PortSet ports) {
    if (exceeded) return;
    if (work.empty()) {
      if (ports == 0) return;
      if (out.size() == limit) {
        exceeded = true;
        return;
      }
      out.push_back(ports);
      return;
    }
    Item item = work.back();
    work.pop_back();
    if (item.choose) {
      if (item.domain_one) {
        auto next = work;
        next.push_back({item.node, true, false, false, false});
        run(std::move(next), ports);
      }
      if (item.domain_zero) {
        work.push_back({item.node, false, false, false, false});
        run(std::move(work), ports);
      }
      return;
    }
    const DefineNode& node = *item.node;
    if (node.children.empty()) {
      if (item.present && node.port < 64) ports |= PortSet{1} << node.port;
      run(std::move(work), ports);
      return;
    }
    if (!has_trigger(node)) {
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
        work.push_back({&*it, item.present, false, false, false});
      }
      run(std::move(work), ports);
      return;
    }
    std::size_t triggers = 0;
    for (const DefineNode& child : node.children) triggers += child.trigger ? 1 : 0;
    const std::size_t rounds = item.present ? triggers : 1;
    for (std::size_t t = 0; t < rounds; ++t) {
      auto next = work;
      std::vector<Item> children;
      std::size_t trigger_index = 0;
      for (const DefineNode& child : node.children) {
        Item c{&child, false, true, false, true};
        if (item.present) {
          if (child.trigger) {
            c.domain_one = trigger_index >= t;
            c.domain_zero = trigger_index != t;
            ++trigger_index;
          } else {
            c.domain_one = true;
          }
        }
        children.push_back(c);
      }
      for (auto it = children.rbegin(); it != children.rend(); ++it) next.push_back(*it);
      run(std::move(next), ports);
    }
  }
};

void add_listing(const System& system, Index compound, Layout& layout) {
  const bipc::ir::CompoundInstance& c = system.compounds[compound];
  std::vector<Index> subs = c.compounds;
  std::sort(subs.begin(), subs.end(), [&](Index a, Index b) {
    return last_component(system.compounds[a].path) < last_component(system.compounds[b].path);
  });
  for (Index sub : subs) add_listing(system, sub, layout);
  std::vector<Index> connectors;
  for (Index k : c.connectors) {
    if (!system.connector_types[system.connectors[k].type].export_name) connectors.push_back(k);
  }
  std::sort(connectors.begin(), connectors.end(), [&](Index a, Index b) {
    return last_component(system.connectors[a].path) < last_component(system.connectors[b].path);
  });
  layout.listed_connectors.insert(layout.listed_connectors.end(), connectors.begin(),
                                  connectors.end());
}

/// Atom ports of one kind, recursively in component-name order (atoms and compounds together).
void add_atom_ports(const System& system, Index compound, bool external,
                    std::vector<std::pair<Index, Index>>& out) {
  const bipc::ir::CompoundInstance& c = system.compounds[compound];
  std::vector<std::pair<std::string, std::pair<bool, Index>>> children;
  for (Index a : c.atoms) children.push_back({last_component(system.atoms[a].path), {true, a}});
  for (Index s : c.compounds)
    children.push_back({last_component(system.compounds[s].path), {false, s}});
  std::sort(children.begin(), children.end());
  for (const auto& [name, child] : children) {
    if (!child.first) {
      add_atom_ports(system, child.second, external, out);
      continue;
    }
    const bipc::ir::AtomType& type = system.atom_types[system.atoms[child.second].type];
    std::vector<Index> ports;
    for (Index p = 0; p < type.ports.size(); ++p) {
      const bipc::ir::Port& port = type.ports[p];
      if (external ? port.is_extern : (!port.exported && !port.is_extern)) ports.push_back(p);
    }
    std::sort(ports.begin(), ports.end(),
              [&](Index x, Index y) { return type.ports[x].name < type.ports[y].name; });
    for (Index p : ports) out.push_back({child.second, p});
  }
}

/// The port set a priority side names, or an error.
bool side_ports(const System& system, const bipc::ir::PatternSide& side, PortSet& out) {
  out = 0;
  if (side.connector == bipc::ir::kNone || side.all_ports) return true;
  const bipc::ir::ConnectorInstance& k = system.connectors[side.connector];
  for (const bipc::ir::PortRef& ref : side.ports) {
    bool found = false;
    for (std::size_t i = 0; i < k.bound.size() && !found; ++i) {
      if (std::find(k.bound[i].begin(), k.bound[i].end(), ref) != k.bound[i].end()) {
        out |= PortSet{1} << i;
        found = true;
      }
    }
    if (!found) return false;
  }
  return true;
}

/// The defined interactions with the `on` clause (guard, up, down) of each, if any.
std::vector<DefinedInteraction> with_code(const bipc::ir::ConnectorType& type,
                                          const std::vector<PortSet>& sets) {
  std::vector<DefinedInteraction> defined;
  std::vector<Index> members;
  for (PortSet ports : sets) {
    members.clear();
    for (PortSet left = ports; left != 0; left &= left - 1) {
      members.push_back(static_cast<Index>(std::countr_zero(left)));
    }
    defined.push_back({ports, interaction_code(type, members)});
  }
  return defined;
}

/// The ports every one of `defined` contains; none when there is none defined.
PortSet required_ports(const std::vector<DefinedInteraction>& defined) {
  if (defined.empty()) return 0;
  PortSet required = ~PortSet{0};
  for (const DefinedInteraction& d : defined) required &= d.ports;
  return required;
}

}  // namespace

int interaction_code(const bipc::ir::ConnectorType& type, std::span<const Index> ports) {
  for (std::size_t i = 0; i < type.interactions.size(); ++i) {
    const std::vector<Index>& on = type.interactions[i].ports;  // sorted (lowering)
    if (std::equal(on.begin(), on.end(), ports.begin(), ports.end())) return static_cast<int>(i);
  }
  return -1;
}

std::optional<std::vector<PortSet>> defined_interactions(const std::vector<DefineNode>& define,
                                                         std::size_t limit) {
  std::vector<PortSet> out;
  DefineNode root;
  root.children = define;
  Enumerator enumerator{out, limit};
  enumerator.run({{&root, true, false, false, false}}, 0);
  if (enumerator.exceeded) return std::nullopt;
  return out;
}

LeadingTests compile_leading(const bipc::ir::LeadingComparison& leading) {
  LeadingTests out;
  out.count = leading.count;
  std::uint32_t literals = 0;
  const auto operand = [&](const bipc::ir::IntOperand& o, LeadingTests::Base& base, Index& at) {
    switch (o.kind) {
      case bipc::ir::IntOperand::Kind::AtomData:
        base = LeadingTests::kData;
        at = o.index;
        return;
      case bipc::ir::IntOperand::Kind::AtomParam:
        base = LeadingTests::kParams;
        at = o.index;
        return;
      case bipc::ir::IntOperand::Kind::Literal:
        break;
    }
    base = LeadingTests::kLiterals;
    at = literals;
    out.literals[literals++] = make_int(o.literal);
  };
  constexpr std::uint8_t kLess = 1, kEqual = 2, kGreater = 4;
  for (std::size_t k = 0; k < leading.count; ++k) {
    const bipc::ir::IntComparison& c = leading.tests[k];
    LeadingTests::Test& test = out.tests[k];
    operand(c.left, test.left_base, test.left);
    operand(c.right, test.right_base, test.right);
    switch (c.op) {
      case bipc::ir::Op::Eq:
        test.holds_when = kEqual;
        break;
      case bipc::ir::Op::Ne:
        test.holds_when = kLess | kGreater;
        break;
      case bipc::ir::Op::Lt:
        test.holds_when = kLess;
        break;
      case bipc::ir::Op::Le:
        test.holds_when = kLess | kEqual;
        break;
      case bipc::ir::Op::Gt:
        test.holds_when = kGreater;
        break;
      default:  // Ge: leading_comparison keeps to Eq..Ge
        test.holds_when = kEqual | kGreater;
        break;
    }
  }
  return out;
}

namespace {

/// The datum and literal of a leading `d == literal` (either way round), if the entry has one.
std::optional<std::pair<Index, std::int64_t>> state_test(const Layout& layout,
                                                         const TransitionEntry& entry) {
  if (entry.leading == bipc::ir::kNone) return std::nullopt;
  const bipc::ir::IntComparison& test = layout.leading_comparisons[entry.leading].tests[0];
  using Kind = bipc::ir::IntOperand::Kind;
  if (test.op != bipc::ir::Op::Eq) return std::nullopt;
  if (test.left.kind == Kind::AtomData && test.right.kind == Kind::Literal) {
    return std::pair{test.left.index, test.right.literal};
  }
  if (test.right.kind == Kind::AtomData && test.left.kind == Kind::Literal) {
    return std::pair{test.right.index, test.left.literal};
  }
  return std::nullopt;
}

/// The entries by literal when every one is led by `d == literal` on the same datum and there
/// are enough of them to pay for a search.
std::optional<ValueDispatch> value_dispatch(const Layout& layout,
                                            const std::vector<TransitionEntry>& entries) {
  constexpr std::size_t kWorthIt = 4;
  if (entries.size() < kWorthIt) return std::nullopt;
  std::vector<std::pair<std::int64_t, std::uint32_t>> by_value;
  ValueDispatch out;
  for (std::uint32_t i = 0; i < entries.size(); ++i) {
    const auto test = state_test(layout, entries[i]);
    if (!test || (i > 0 && test->first != out.slot)) return std::nullopt;
    out.slot = test->first;
    by_value.emplace_back(test->second, i);
  }
  std::stable_sort(by_value.begin(), by_value.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::uint32_t i = 0; i < by_value.size(); ++i) {
    if (out.keys.empty() || out.keys.back() != by_value[i].first) {
      out.keys.push_back(by_value[i].first);
      out.first.push_back(i);
    }
    out.order.push_back(by_value[i].second);
  }
  out.first.push_back(static_cast<std::uint32_t>(by_value.size()));
  return out;
}

/// Per atom type: its transitions' entries (labelled, internal, by `from` place when its net is a
/// state machine) and the leading comparisons of their guards.
void add_transition_tables(const System& system, Layout& layout) {
  for (const bipc::ir::AtomType& type : system.atom_types) {
    auto& labelled = layout.labelled_transitions.emplace_back();
    auto& internal = layout.internal_transitions.emplace_back();
    for (Index t = 0; t < type.transitions.size(); ++t) {
      const bipc::ir::Transition& transition = type.transitions[t];
      TransitionEntry entry{t, bipc::ir::kNone, transition.from.size() > 1};
      if (auto leading = bipc::ir::leading_comparison(transition.guard)) {
        entry.leading = static_cast<Index>(layout.leading_tests.size());
        entry.leading_whole = leading->whole;
        layout.leading_comparisons.push_back(*leading);
        layout.leading_tests.push_back(compile_leading(*leading));
      }
      if (!transition.from.empty()) entry.first_place = transition.from.front();
      (transition.port == bipc::ir::kNone ? internal : labelled).push_back(entry);
    }
    auto& from_place = layout.labelled_from_place.emplace_back();
    auto& dispatch = layout.dispatch_from_place.emplace_back();
    if (!bipc::ir::is_state_machine(type)) continue;
    from_place.resize(type.places.size());
    for (const TransitionEntry& entry : labelled) from_place[entry.first_place].push_back(entry);
    for (std::vector<TransitionEntry>& entries : from_place) {
      dispatch.push_back(value_dispatch(layout, entries));
      // The dispatch finds the entries whose first test holds.
      if (dispatch.back()) {
        for (TransitionEntry& entry : entries) entry.first_test = 1;
      }
    }
  }
}

/// Per atom: its slots in a run state, its parameters and its name; and the initial order.
void add_atoms(const System& system, Layout& layout) {
  for (const bipc::ir::AtomInstance& atom : system.atoms) {
    const bipc::ir::AtomType& type = system.atom_types[atom.type];
    layout.atom_data.push_back(layout.data_size);
    layout.data_size += type.data.size();
    layout.atom_places.push_back(layout.place_count);
    layout.place_count += type.places.size();
    layout.atom_clocks.push_back(layout.clock_count);
    layout.clock_count += type.clocks.size();
    for (const bipc::ir::Clock& clock : type.clocks) {
      layout.clock_units.push_back(nanoseconds_per(clock.unit));
    }
    layout.atom_params.push_back(layout.params.size());
    for (const bipc::ir::Value& v : atom.params) layout.params.push_back(to_val(v, nullptr));
    layout.atom_names.push_back(system.root_name + "." + atom.path);
  }
  layout.initial_order.resize(system.atoms.size());
  for (Index a = 0; a < system.atoms.size(); ++a) layout.initial_order[a] = a;
  std::sort(layout.initial_order.begin(), layout.initial_order.end(),
            [&](Index x, Index y) { return layout.atom_names[x] < layout.atom_names[y]; });
}

/// Connector `k`'s data slots, defined interactions and place in its compound; an error message
/// when the engines cannot run it.
std::string add_connector(const System& system, Index k, Layout& layout) {
  const bipc::ir::ConnectorInstance& connector = system.connectors[k];
  const bipc::ir::ConnectorType& type = system.connector_types[connector.type];
  const bool maximal_only = computes_maximal_only(system, k);
  layout.maximal_only.push_back(maximal_only ? 1 : 0);
  const bool wide = type.ports.size() > kPortSetBits;
  if (wide && !maximal_only) {
    return "connector '" + connector.path + "' has more than " + std::to_string(kPortSetBits) +
           " ports and a guard, an `up` calling a function, an export, a sub-connector or a "
           "priority naming it; the engines support such wide connectors only without these";
  }
  layout.connector_data.push_back(layout.data_size);
  layout.data_size += type.data.size();
  const std::optional<std::vector<PortSet>> sets =
      wide ? std::nullopt : defined_interactions(type.define);
  if (!sets && !maximal_only) {
    return "connector '" + connector.path + "' defines more than " +
           std::to_string(kMaxDefinedInteractions) +
           " interactions and a guard, an `up` calling a function, an export, a sub-connector "
           "or a priority naming it; the engines enumerate the interactions of such connectors "
           "and do not support that many";
  }
  layout.enumerated.push_back(sets ? 1 : 0);
  layout.defined.push_back(sets ? with_code(type, *sets) : std::vector<DefinedInteraction>{});
  layout.required_ports.push_back(required_ports(layout.defined.back()));
  // Top level: not bound by another connector of its own compound.
  bool top = true;
  for (Index by : connector.bound_by_all) {
    if (system.connectors[by].parent == connector.parent) top = false;
  }
  layout.top_level.push_back(top);
  layout.connector_names.push_back(system.root_name + "." + connector.path);
  return {};
}

/// Compound `c`'s priority rules as port sets, and per connector those whose low side may name
/// it; an error message when a rule names a port its connector does not bind.
std::string add_priority_rules(const System& system, Index c, Layout& layout) {
  const auto& priorities = system.compounds[c].priorities;
  for (Index r = 0; r < priorities.size(); ++r) {
    PriorityRule rule;
    rule.compound = c;
    rule.rule = r;
    rule.low_connector = priorities[r].low.connector;
    rule.high_connector = priorities[r].high.connector;
    if (!side_ports(system, priorities[r].low, rule.low) ||
        !side_ports(system, priorities[r].high, rule.high)) {
      return "priority '" + priorities[r].name + "' names a port its connector does not bind";
    }
    if (rule.low_connector != bipc::ir::kNone && priorities[r].low.all_ports) {
      const auto n = system.connectors[rule.low_connector].bound.size();
      rule.low = n >= 64 ? ~PortSet{0} : (PortSet{1} << n) - 1;
    }
    layout.rules[c].push_back(rule);
  }
  if (!layout.rules[c].empty()) layout.ruled_compounds.push_back(c);
  // Rules whose low side may name each connector: its own, and `*` ones of its compound.
  for (Index r = 0; r < layout.rules[c].size(); ++r) {
    const Index low = layout.rules[c][r].low_connector;
    if (low != bipc::ir::kNone) {
      layout.rules_by_low[low].push_back(r);
      continue;
    }
    for (Index k : system.compounds[c].connectors) layout.rules_by_low[k].push_back(r);
  }
  return {};
}

}  // namespace

std::string build_layout(const System& system, Layout& layout) {
  layout = Layout{};
  add_transition_tables(system, layout);
  add_atoms(system, layout);
  for (Index k = 0; k < system.connectors.size(); ++k) {
    if (std::string error = add_connector(system, k, layout); !error.empty()) return error;
  }
  add_listing(system, 0, layout);
  add_atom_ports(system, 0, false, layout.internal_ports);
  add_atom_ports(system, 0, true, layout.extern_ports);
  layout.untimed = layout.clock_count == 0 && layout.extern_ports.empty();
  layout.rules.resize(system.compounds.size());
  layout.rules_by_low.resize(system.connectors.size());
  for (Index c = 0; c < system.compounds.size(); ++c) {
    if (std::string error = add_priority_rules(system, c, layout); !error.empty()) return error;
  }
  return {};
}

}  // namespace smcbip::engines
