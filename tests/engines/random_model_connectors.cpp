// Random architecture: components, connectors over their ports, and priority rules.
#include <algorithm>
#include <cstddef>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "random_model_generator.h"

namespace smcbip::tests::random_model_detail {

void Generator::add_atom(Scope& scope, const std::string& name) {
  const AtomType& type = one_of(atom_types_);
  scope.body << "    component " << type.name << " " << name << "("
             << (options_.data ? number(0, 4) : "") << ")\n";
  for (const AtomPort& port : type.ports) {
    if (!port.exported) continue;
    scope.offers.push_back(
        Offer{name + "." + port.name, port.type, {name}, false, false, port.stochastic});
  }
  for (const std::string& x : type.exported_ints) scope.guard_ints.push_back(name + "." + x);
  for (const std::string& b : type.exported_bools) scope.guard_bools.push_back(name + "." + b);
}

std::vector<std::vector<int>> Generator::interactions(Define define, int ports) {
  std::vector<std::vector<int>> all;
  for (int mask = 1; mask < (1 << ports); ++mask) {
    if (define == Define::kRendezvous && mask != (1 << ports) - 1) continue;
    if (define == Define::kBroadcast && (mask & 1) == 0) continue;
    std::vector<int> members;
    for (int i = 0; i < ports; ++i) {
      if (mask & (1 << i)) members.push_back(i);
    }
    all.push_back(members);
  }
  return all;
}

bool Generator::add_connector(Scope& scope, bool allow_export) {
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < scope.offers.size(); ++i) {
    if (!scope.offers[i].used) candidates.push_back(i);
  }
  if (candidates.empty()) return false;
  std::shuffle(candidates.begin(), candidates.end(), rng_);
  std::stable_partition(candidates.begin(), candidates.end(),
                        [&](std::size_t i) { return scope.offers[i].must_bind; });
  const int arity = one_of(std::vector<int>{1, 2, 2, 2, 3, 3, 4});
  std::vector<std::size_t> chosen;
  std::set<std::string> components;
  bool stochastic = false;
  for (std::size_t i : candidates) {
    if (static_cast<int>(chosen.size()) == arity) break;
    const Offer& offer = scope.offers[i];
    if (std::any_of(offer.components.begin(), offer.components.end(),
                    [&](const std::string& a) { return components.count(a) > 0; }) ||
        (stochastic && offer.stochastic)) {
      continue;
    }
    chosen.push_back(i);
    components.insert(offer.components.begin(), offer.components.end());
    stochastic = stochastic || offer.stochastic;
  }
  const int ports = static_cast<int>(chosen.size());

  Define define = Define::kRendezvous;
  if (ports >= 2) {
    const int shape = uniform(0, 99);
    if (shape >= 45) define = Define::kBroadcast;
    if (shape >= 85 && ports <= 3) define = Define::kAllTriggers;
    if (options_.rendezvous_only) define = Define::kRendezvous;
  }
  const bool exports = allow_export && options_.hierarchy && chance(30) &&
                       (define == Define::kRendezvous || ports <= 3);
  const bool export_data = exports && options_.data && chance(60);

  const std::string id = std::to_string(connector_count_++);
  const std::string type_name = "K" + id, name = "c" + id;
  std::ostringstream text;
  std::vector<std::string> params, int_refs_all, bool_refs_all;
  for (int i = 0; i < ports; ++i) {
    const Offer& offer = scope.offers[chosen[static_cast<std::size_t>(i)]];
    params.push_back(std::string(kPortTypeNames[offer.type]) + " p" + std::to_string(i));
  }
  text << "  connector type " << type_name << "(" << join(params, ", ") << ")\n";
  const bool uses_tmp = options_.data && chance(30);
  if (uses_tmp) text << "    data int tmp\n";
  if (export_data) text << "    data int d\n";
  if (exports) {
    text << "    export port " << (export_data ? "IntPort top(d)" : "Sig top()") << "\n";
  }
  text << "    define";
  for (int i = 0; i < ports; ++i) {
    const bool trigger = (define == Define::kBroadcast && i == 0) || define == Define::kAllTriggers;
    text << " p" << i << (trigger ? "'" : "");
  }
  text << "\n";

  // `on` clauses: guards over port data, up (when data are exported) and down transfers.
  std::vector<std::vector<int>> allowed = interactions(define, ports);
  std::shuffle(allowed.begin(), allowed.end(), rng_);
  const std::size_t described =
      export_data ? allowed.size()
                  : std::min<std::size_t>(allowed.size(), options_.data ? uniform(0, 2) : 0);
  for (std::size_t k = 0; k < described; ++k) {
    std::vector<std::string> names, ints, bools;
    for (int i : allowed[k]) {
      const std::string port = "p" + std::to_string(i);
      const int type = scope.offers[chosen[static_cast<std::size_t>(i)]].type;
      names.push_back(port);
      if (has_int(type)) ints.push_back(port + ".v");
      if (has_bool(type)) bools.push_back(port + ".b");
    }
    text << "    on " << join(names, " ");
    if (!ints.empty() && chance(50)) text << " provided (" << data_guard(ints, bools) << ")";
    if (export_data) {
      text << " up { d = " << (ints.empty() ? number(0, 4) : "(" + join(ints, " + ") + ") % 7")
           << "; }";
    }
    std::vector<std::string> down;
    if (!ints.empty() && chance(60)) {
      const std::string& target = one_of(ints);
      if (uses_tmp && ints.size() >= 2 && target != ints[0]) {
        down.push_back("tmp = " + ints[0] + "; " + ints[0] + " = " + target + "; " + target +
                       " = tmp;");
      } else {
        down.push_back(target + " = (" + one_of(ints) + " + 1) % 5;");
      }
    }
    if (export_data && !ints.empty() && chance(50)) down.push_back(one_of(ints) + " = d % 5;");
    if (!bools.empty() && chance(30)) down.push_back(one_of(bools) + " = !" + one_of(bools) + ";");
    if (!down.empty()) text << " down { " << join(down, " ") << " }";
    text << "\n";
  }
  text << "  end\n\n";
  connector_types_ << text.str();

  MadeConnector made{name, {}, define};
  for (std::size_t i : chosen) {
    scope.offers[i].used = true;
    made.refs.push_back(scope.offers[i].ref);
  }
  scope.body << "    connector " << type_name << " " << name << "(" << join(made.refs, ", ")
             << ")\n";
  if (exports) {
    scope.offers.push_back(Offer{name + ".top", export_data ? kInt : kSig,
                                 std::vector<std::string>(components.begin(), components.end()),
                                 true, false, stochastic});
  } else {
    scope.top_level.push_back(std::move(made));
  }
  return true;
}

void Generator::bind_pending(Scope& scope) {
  while (std::any_of(scope.offers.begin(), scope.offers.end(),
                     [](const Offer& o) { return o.must_bind && !o.used; })) {
    add_connector(scope, false);
  }
}

std::string Generator::pattern(const MadeConnector& connector) {
  if (chance(60)) return connector.name + ":*";
  std::vector<std::string> refs;
  switch (connector.define) {
    case Define::kRendezvous:
      refs = connector.refs;
      break;
    case Define::kBroadcast:
      refs.push_back(connector.refs[0]);
      for (std::size_t i = 1; i < connector.refs.size(); ++i) {
        if (chance(50)) refs.push_back(connector.refs[i]);
      }
      break;
    case Define::kAllTriggers:
      for (const std::string& ref : connector.refs) {
        if (chance(50)) refs.push_back(ref);
      }
      if (refs.empty()) refs.push_back(one_of(connector.refs));
      break;
  }
  return connector.name + ":" + join(refs, ",");
}

void Generator::add_priorities(Scope& scope) {
  const int top = static_cast<int>(scope.top_level.size());
  if (!options_.priorities || top < 2) return;
  const int rules = uniform(0, std::min(3, top - 1));
  std::set<std::pair<int, int>> made;
  int rule_count = 0;
  for (int r = 0; r < rules; ++r) {
    const int low = uniform(0, top - 2), high = uniform(low + 1, top - 1);
    if (!made.insert({low, high}).second) continue;
    scope.body << "    priority r" << rule_count++ << " "
               << pattern(scope.top_level[static_cast<std::size_t>(low)]) << " < "
               << pattern(scope.top_level[static_cast<std::size_t>(high)]);
    if (!scope.guard_ints.empty() && chance(40)) {
      scope.body << " provided (" << data_guard(scope.guard_ints, scope.guard_bools) << ")";
    }
    scope.body << "\n";
  }
  if (chance(20)) {
    scope.body << "    priority r" << rule_count << " *:* < " << scope.top_level.back().name
               << ":*\n";
  }
}

}  // namespace smcbip::tests::random_model_detail
