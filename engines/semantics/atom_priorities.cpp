// The priority rules of an atom type, after the reference engine: a port is disabled when a
// chain of active rules from it ends at an enabled port; active rules that chain into a cycle
// are an error.
#include "engines/semantics/atom_priorities.h"

namespace smcbip::engines {

using bipc::ir::kNone;

namespace {

bool in_low(const bipc::ir::AtomPriority& rule, std::size_t p) {
  return rule.low == kNone ? rule.high != p : rule.low == p;
}

bool in_high(const bipc::ir::AtomPriority& rule, std::size_t p) {
  return rule.high == kNone ? rule.low != p : rule.high == p;
}

/// Whether a port is in the high side of `x` and the low side of `y`.
bool chained(const bipc::ir::AtomPriority& x, const bipc::ir::AtomPriority& y, std::size_t ports) {
  for (std::size_t q = 0; q < ports; ++q) {
    if (in_high(x, q) && in_low(y, q)) return true;
  }
  return false;
}

}  // namespace

void AtomPriorities::evaluate_guards(const bipc::ir::AtomType& type, ModelCode& eval,
                                     const Frame& f) {
  const std::size_t rules = type.priorities.size();
  active_.assign(rules, 0);
  for (std::size_t r = 0; r < rules; ++r) active_[r] = eval.holds(type.priorities[r].guard, f);
}

bool AtomPriorities::acyclic(const bipc::ir::AtomType& type) {
  const std::size_t rules = type.priorities.size();
  const std::size_t n = type.ports.size();
  // Depth-first search for a cycle among active rules (colours: 0 new, 1 on path, 2 done), on
  // an explicit path of (rule, next rule to try).
  colour_.assign(rules, 0);
  for (std::size_t root = 0; root < rules; ++root) {
    if (!active_[root] || colour_[root] != 0) continue;
    colour_[root] = 1;
    path_.assign(1, {root, 0});
    while (!path_.empty()) {
      const std::size_t r = path_.back().first;
      std::size_t& next = path_.back().second;
      while (next < rules &&
             (!active_[next] || !chained(type.priorities[r], type.priorities[next], n))) {
        ++next;
      }
      if (next == rules) {
        colour_[r] = 2;
        path_.pop_back();
        continue;
      }
      const std::size_t r2 = next++;
      if (colour_[r2] == 1) return false;
      if (colour_[r2] == 0) {
        colour_[r2] = 1;
        path_.emplace_back(r2, 0);
      }
    }
  }
  return true;
}

bool AtomPriorities::high_enabled(const bipc::ir::AtomType& type, std::size_t r,
                                  const std::optional<AtomPortValue>* offers) const {
  for (std::size_t q = 0; q < type.ports.size(); ++q) {
    if (in_high(type.priorities[r], q) && offers[q] && !type.ports[q].is_extern) return true;
  }
  return false;
}

bool AtomPriorities::dominated(const bipc::ir::AtomType& type, std::size_t p,
                               const std::optional<AtomPortValue>* offers) {
  const std::size_t rules = type.priorities.size();
  const std::size_t n = type.ports.size();
  seen_.assign(rules, 0);
  chain_ends_.clear();
  for (std::size_t r = 0; r < rules; ++r) {
    if (active_[r] && in_low(type.priorities[r], p)) {
      seen_[r] = 1;
      chain_ends_.push_back(r);
    }
  }
  while (!chain_ends_.empty()) {
    const std::size_t r = chain_ends_.back();
    chain_ends_.pop_back();
    if (high_enabled(type, r, offers)) return true;
    for (std::size_t r2 = 0; r2 < rules; ++r2) {
      if (seen_[r2] || !active_[r2]) continue;
      if (chained(type.priorities[r], type.priorities[r2], n)) {
        seen_[r2] = 1;
        chain_ends_.push_back(r2);
      }
    }
  }
  return false;
}

bool AtomPriorities::apply(const bipc::ir::AtomType& type, ModelCode& eval, const Frame& f,
                           std::optional<AtomPortValue>* offers) {
  // The guards are evaluated for the cycle check and again for the chains: a guard that calls
  // an impure extern makes two calls per update of the atom, in every engine alike.
  evaluate_guards(type, eval, f);
  if (!acyclic(type)) return false;
  evaluate_guards(type, eval, f);
  const std::size_t n = type.ports.size();
  disabled_.assign(n, 0);
  for (std::size_t p = 0; p < n; ++p) {
    if (offers[p] && !type.ports[p].is_extern) disabled_[p] = dominated(type, p, offers) ? 1 : 0;
  }
  for (std::size_t p = 0; p < n; ++p) {
    if (disabled_[p]) offers[p].reset();
  }
  return true;
}

}  // namespace smcbip::engines
