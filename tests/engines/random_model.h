// Random valid BIP2 packages for differential testing of the engines (same seed, same trace).
#pragma once

#include <cstdint>
#include <string>

namespace smcbip::tests {

/// The shape of a random package; `seed` alone fixes the text for given other fields.
struct RandomModelOptions {
  std::uint64_t seed = 0;
  /// Atom instances in the whole system, sub-compounds included.
  int atoms = 4;
  /// Most places of an atom type's main token (an auxiliary token may add two more).
  int max_places = 4;
  /// Most exported ports per atom type (one internal port may come on top).
  int max_ports = 3;
  /// Connectors of the root compound, plus those needed to bind exported connector ports.
  int connectors = 4;
  /// Atom and compound priority rules, some guarded.
  bool priorities = true;
  /// Clocks, clock guards, urgencies and resets: a timed model.
  bool clocks = false;
  /// Int and bool data, port parameters, guards, actions, connector up/down.
  bool data = true;
  /// Sub-compounds, and connectors binding other connectors' exported ports.
  bool hierarchy = true;
  /// Every connector a rendezvous of all its ports.
  bool rendezvous_only = false;
  /// Some exported ports of timed atom types carry a @stochastic annotation (exponential or
  /// normal dates on one of the atom's clocks), at most one per connector.
  bool stochastic = false;
};

/// A package named `package_name` whose root compound type is `Root()`. It passes `bipc check`,
/// and every run of it is free of the reference engine's model errors: each atom is a 1-safe
/// Petri net (one main token, plus an auxiliary one forked and joined by it), at most one
/// transition per port (or per unlabelled internal step) is enabled at once, unlabelled internal
/// transitions never loop, priority rules only point upwards in a fixed order, and int data stay
/// in [0, 7) so no action overflows or divides by zero.
std::string random_bip_package(const RandomModelOptions& options, const std::string& package_name);

}  // namespace smcbip::tests
