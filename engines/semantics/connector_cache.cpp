// Stale-connector bookkeeping of the optimised scheduler.
#include "engines/semantics/connector_cache.h"

#include <algorithm>

namespace smcbip::engines {

using bipc::ir::Index;

namespace {

/// Whether evaluating the code twice on the same connector data and port data gives the same
/// result with no other effect. Calls may draw random numbers or print; loads and stores
/// outside the connector's own data and its ports' parameters, or stores into those parameters,
/// read or write state the cache does not track.
bool cacheable(const bipc::ir::Code& code) {
  using bipc::ir::Op;
  using bipc::ir::Scope;
  for (const bipc::ir::Instr& in : code.instrs) {
    switch (in.op) {
      case Op::Call:
      case Op::StoreRate:
        return false;
      case Op::Load:
        if (in.scope != Scope::ConnectorData && in.scope != Scope::PortParam) return false;
        break;
      case Op::Store:
        if (in.scope != Scope::ConnectorData) return false;
        break;
      default:
        break;
    }
  }
  return true;
}

}  // namespace

ConnectorCache::ConnectorCache(const bipc::ir::System& system, const Layout& layout)
    : system_(system),
      atom_connectors_(system.atoms.size()),
      parents_(system.connectors.size()),
      ruled_(system.connectors.size(), 0),
      rank_(system.connectors.size(), 0),
      stale_(system.connectors.size(), 0),
      computed_(system.connectors.size(), 0),
      direct_(system.connectors.size(), 0),
      work_(system.compounds.size()),
      in_work_(system.connectors.size(), 0),
      queued_(system.compounds.size(), 0),
      checked_(system.connectors.size(), 0),
      touched_(system.atoms.size(), 0),
      ruled_compounds_(layout.ruled_compounds) {
  time_dependent_.reset(system.connectors.size());
  urgent_.reset(system.connectors.size());
  for (Index c = 0; c < system.compounds.size(); ++c) {
    const std::vector<Index>& connectors = system.compounds[c].connectors;
    for (Index r = 0; r < connectors.size(); ++r) rank_[connectors[r]] = r;
  }
  for (Index k = 0; k < system.connectors.size(); ++k) {
    const bipc::ir::ConnectorInstance& connector = system.connectors[k];
    for (const std::vector<bipc::ir::PortRef>& refs : connector.bound) {
      for (const bipc::ir::PortRef& ref : refs) {
        auto& users = ref.kind == bipc::ir::PortRef::Kind::Atom ? atom_connectors_[ref.instance]
                                                                : parents_[ref.instance];
        if (users.empty() || users.back() != k) users.push_back(k);
      }
    }
    bool fixed = true;
    for (const bipc::ir::InteractionCode& code :
         system.connector_types[connector.type].interactions) {
      fixed = fixed && cacheable(code.guard) && cacheable(code.up);
    }
    if (!fixed) volatile_.push_back(k);
    ruled_[k] = layout.rules[connector.parent].empty() ? 0 : 1;
  }
}

void ConnectorCache::mark_stale_with_binders(Index k) {
  stale_[k] = 1;
  stale_list_.push_back(k);
  add_work(k);
  for (Index parent : parents_[k]) mark_stale(parent);
}

void ConnectorCache::add_work(Index k) {
  if (in_work_[k]) return;
  in_work_[k] = 1;
  const Index compound = system_.connectors[k].parent;
  work_[compound].push_back(k);
  queue_compound(compound);
}

void ConnectorCache::queue_compound(Index compound) {
  if (queued_[compound]) return;
  queued_[compound] = 1;
  queue_.push(compound);
}

void ConnectorCache::clear_work() {
  if (queue_.empty() && worked_.empty()) return;
  for (; !queue_.empty(); queue_.pop()) worked_.push_back(queue_.top());
  for (Index compound : worked_) {
    for (Index k : work_[compound]) in_work_[k] = 0;
    work_[compound].clear();
    queued_[compound] = 0;
  }
  worked_.clear();
}

bool ConnectorCache::start(TimeValue now, bool full) {
  time_passed_ = full || now != last_now_;
  last_now_ = now;
  clear_work();  // a failed computation may have left some behind
  direct_work_.clear();
  if (!full) return false;
  // A failed computation may have left flags behind.
  stale_.assign(stale_.size(), 1);
  computed_.assign(computed_.size(), 0);
  stale_list_.resize(stale_.size());
  for (Index k = 0; k < stale_list_.size(); ++k) stale_list_[k] = k;
  return true;
}

void ConnectorCache::queue_unchanged_work() {
  for (Index k : volatile_) mark_stale(k);
  if (time_passed_) {
    for (Index k : time_dependent_) add_work(k);
  }
  for (Index compound : ruled_compounds_) queue_compound(compound);
}

bool ConnectorCache::next_compound(Index& compound) {
  if (queue_.empty()) return false;
  compound = queue_.top();
  queue_.pop();
  worked_.push_back(compound);
  return true;
}

const std::vector<Index>& ConnectorCache::work(Index compound) {
  if (!system_.compounds[compound].priorities.empty())
    return system_.compounds[compound].connectors;
  std::vector<Index>& connectors = work_[compound];
  auto by_rank = [&](Index a, Index b) { return rank_[a] < rank_[b]; };
  if (connectors.size() > 16) {
    std::sort(connectors.begin(), connectors.end(), by_rank);
    return connectors;
  }
  // A step's few connectors: insertion sort is cheaper than std::sort's set-up.
  for (std::size_t i = 1; i < connectors.size(); ++i) {
    const Index k = connectors[i];
    std::size_t j = i;
    for (; j > 0 && by_rank(k, connectors[j - 1]); --j) connectors[j] = connectors[j - 1];
    connectors[j] = k;
  }
  return connectors;
}

void ConnectorCache::priorities_changed(Index k) {
  // Connectors of the same compound bind this one's raw constraints, which did not change.
  for (Index parent : parents_[k]) {
    if (system_.connectors[parent].parent != system_.connectors[k].parent) mark_stale(parent);
  }
}

void ConnectorCache::end() {
  for (Index k : stale_list_) stale_[k] = computed_[k] = 0;
  stale_list_.clear();
  direct_work_.clear();
  clear_work();
  all_stale_ = false;
}

}  // namespace smcbip::engines
