// Stale-connector bookkeeping of the optimised scheduler.
#include "engines/semantics/connector_cache.h"

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
      time_dependent_(system.connectors.size(), 0),
      urgent_(system.connectors.size(), 0),
      stale_(system.connectors.size(), 0),
      computed_(system.connectors.size(), 0),
      checked_(system.connectors.size(), 0),
      touched_(system.atoms.size(), 0) {
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
  for (Index parent : parents_[k]) mark_stale(parent);
}

bool ConnectorCache::start(TimeValue now, bool full) {
  time_passed_ = full || now != last_now_;
  last_now_ = now;
  if (!full) return false;
  // A failed computation may have left flags behind.
  stale_.assign(stale_.size(), 1);
  computed_.assign(computed_.size(), 0);
  stale_list_.resize(stale_.size());
  for (Index k = 0; k < stale_list_.size(); ++k) stale_list_[k] = k;
  return true;
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
  all_stale_ = false;
}

}  // namespace smcbip::engines
