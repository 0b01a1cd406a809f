// Instance-level checks of a flattened system: what a connector instance reaches through
// exports and hierarchical connectors.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "bipc/lower/detail/lowering.h"

namespace smcbip::bipc::lower {

namespace {

/// Walks each connector once (memoised), bottom-up through the connectors it binds, so the
/// whole pass is linear in the size of the bound port lists.
class InstanceChecker {
 public:
  InstanceChecker(const ir::System& system, const std::vector<Location>& locs, Diagnostics& diags)
      : system_(system),
        locs_(locs),
        diags_(diags),
        state_(system.connectors.size(), State::Unvisited),
        summaries_(system.connectors.size()),
        owner_connector_(system.atoms.size(), ir::kNone),
        owner_param_(system.atoms.size(), 0) {}

  void run() {
    for (ir::Index k = 0; k < system_.connectors.size(); ++k) summarise(k);
  }

 private:
  enum class State : std::uint8_t { Unvisited, Active, Done };

  /// The atoms a connector's interactions may involve, and whether one has a stochastic port.
  struct Summary {
    std::vector<ir::Index> atoms;
    bool stochastic = false;
  };

  const Summary& summarise(ir::Index k) {
    if (state_[k] == State::Done) return summaries_[k];
    if (state_[k] == State::Active) {
      error(k, "hierarchical connectors form a cycle through '" + system_.connectors[k].path + "'");
      return summaries_[k];  // empty: the cycle is reported once, where it closes
    }
    state_[k] = State::Active;
    // Sub-connectors first, so that the ownership marks below are not disturbed by recursion.
    for (const auto& refs : system_.connectors[k].bound) {
      for (const ir::PortRef& ref : refs) {
        if (ref.kind == ir::PortRef::Kind::Connector && ref.instance < state_.size()) {
          summarise(ref.instance);
        }
      }
    }
    summaries_[k] = combine(k);
    state_[k] = State::Done;
    return summaries_[k];
  }

  Summary combine(ir::Index k) {
    const ir::ConnectorInstance& connector = system_.connectors[k];
    Summary summary;
    std::size_t stochastic_params = 0;
    bool reported_twice = false;
    for (std::size_t param = 0; param < connector.bound.size(); ++param) {
      bool stochastic = false;
      for (ir::Index atom : param_atoms(connector.bound[param], stochastic)) {
        if (owner_connector_[atom] != k) {
          owner_connector_[atom] = k;
          owner_param_[atom] = param;
          summary.atoms.push_back(atom);
        } else if (owner_param_[atom] != param && !reported_twice) {
          error(k, "connector '" + connector.path + "' binds atom '" + system_.atoms[atom].path +
                       "' twice");
          reported_twice = true;
        }
      }
      if (stochastic) ++stochastic_params;
    }
    if (stochastic_params > 1) {
      error(k, "connector '" + connector.path +
                   "': at most one stochastic port per interaction, but " +
                   std::to_string(stochastic_params) + " of its ports may bring one");
    }
    summary.stochastic = stochastic_params > 0;
    return summary;
  }

  /// The distinct atoms one port parameter may reach, through any of its alternatives.
  std::vector<ir::Index> param_atoms(const std::vector<ir::PortRef>& refs, bool& stochastic) const {
    std::vector<ir::Index> atoms;
    for (const ir::PortRef& ref : refs) {
      if (ref.kind == ir::PortRef::Kind::Connector) {
        if (ref.instance >= summaries_.size()) continue;
        const Summary& sub = summaries_[ref.instance];
        atoms.insert(atoms.end(), sub.atoms.begin(), sub.atoms.end());
        stochastic = stochastic || sub.stochastic;
      } else if (ref.instance < system_.atoms.size()) {
        atoms.push_back(ref.instance);
        stochastic = stochastic || is_stochastic(ref);
      }
    }
    std::sort(atoms.begin(), atoms.end());
    atoms.erase(std::unique(atoms.begin(), atoms.end()), atoms.end());
    return atoms;
  }

  bool is_stochastic(const ir::PortRef& ref) const {
    const ir::Index type = system_.atoms[ref.instance].type;
    if (type >= system_.atom_types.size()) return false;
    const auto& ports = system_.atom_types[type].ports;
    return ref.port < ports.size() && ports[ref.port].stochastic.has_value();
  }

  void error(ir::Index k, std::string message) {
    diags_.error(k < locs_.size() ? locs_[k] : Location{}, std::move(message));
  }

  const ir::System& system_;
  const std::vector<Location>& locs_;
  Diagnostics& diags_;
  std::vector<State> state_;
  std::vector<Summary> summaries_;
  // Which connector last claimed an atom, and through which port parameter: reset-free marks.
  std::vector<ir::Index> owner_connector_;
  std::vector<std::size_t> owner_param_;
};

}  // namespace

void check_instances(const ir::System& system, const std::vector<Location>& connector_locs,
                     Diagnostics& diags) {
  InstanceChecker(system, connector_locs, diags).run();
}

}  // namespace smcbip::bipc::lower
