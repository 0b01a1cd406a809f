// Precomputed facts about a system that every step needs: where each atom's and connector's
// slots live in a run state, the connectors that interact at the top, and listing orders.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bipc/ir/data_guard.h"
#include "bipc/ir/ir.h"
#include "engines/api/time_value.h"
#include "engines/api/value.h"

namespace smcbip::engines {

using bipc::ir::Index;

/// A set of port parameters of one connector with at most 64 ports (wider connectors, which
/// only maximal_only connectors may be, leave their sets empty and list their ports in order).
using PortSet = std::uint64_t;
inline constexpr std::size_t kPortSetBits = 64;

/// One interaction a connector's define expression allows, as a set of its port parameters.
struct DefinedInteraction {
  PortSet ports = 0;
  int code = -1;  // index into ConnectorType::interactions (guard, up, down), or -1
};

/// A compound priority rule with its sides as port sets of their connectors.
struct PriorityRule {
  Index compound = 0;
  Index rule = 0;                         // index into CompoundInstance::priorities
  Index low_connector = bipc::ir::kNone;  // kNone: `*`
  PortSet low = 0;
  Index high_connector = bipc::ir::kNone;  // kNone: `*`
  PortSet high = 0;                        // 0 with a connector: `D:*` (every interaction of D)
};

/// The leading comparisons of a guard (bipc::ir::LeadingComparison) as the engines test them:
/// each operand read from one of three bases, the atom's data, its parameters or the literals
/// kept here, and each comparison by the orders of its operands it holds in. A test costs a few
/// loads and no branch on its shape.
struct LeadingTests {
  enum Base : std::uint8_t { kData, kParams, kLiterals };
  struct Test {
    Base left_base = kLiterals, right_base = kLiterals;
    /// Bit 0: holds when left < right, bit 1: when equal, bit 2: when greater.
    std::uint8_t holds_when = 0;
    Index left = 0, right = 0;  // slots, or indices into `literals`
  };
  std::array<Test, bipc::ir::LeadingComparison::kMax> tests{};
  std::array<Val, 2 * bipc::ir::LeadingComparison::kMax> literals{};
  std::uint8_t count = 0;
};

/// The tests of `leading`, in its order.
LeadingTests compile_leading(const bipc::ir::LeadingComparison& leading);

/// A transition of an atom type as its atoms look for enabled ones.
struct TransitionEntry {
  Index transition = 0;
  Index first_place = bipc::ir::kNone;  // its first `from` place (kNone: it has none)
  bool more_places = false;             // whether it has other `from` places
  /// The comparisons of integer slots leading its guard (data_guard.h), as an index into
  /// Layout::leading_tests (kNone: none): tested before the guard is interpreted, and instead of
  /// it when they are the whole guard.
  Index leading = bipc::ir::kNone;
  bool leading_whole = false;  // they are the whole guard
  /// The first of them to test: 1 where a ValueDispatch chose the entry by its first, which
  /// then holds.
  std::uint8_t first_test = 0;
};

/// Transitions (positions in a list of entries) by the literal their guard compares one datum
/// with: the positions of keys[k] are order[first[k]] .. order[first[k + 1] - 1], in list order.
struct ValueDispatch {
  Index slot = 0;                  // the datum (atom data slot)
  std::vector<std::int64_t> keys;  // sorted, distinct
  std::vector<std::uint32_t> first, order;
  /// The positions of the entries whose literal is `value` (none when no entry has it).
  std::span<const std::uint32_t> entries_for(std::int64_t value) const {
    const auto it = std::lower_bound(keys.begin(), keys.end(), value);
    if (it == keys.end() || *it != value) return {};
    const auto k = static_cast<std::size_t>(it - keys.begin());
    return {order.data() + first[k], order.data() + first[k + 1]};
  }
};

struct Layout {
  std::vector<std::size_t> atom_data, atom_places, atom_clocks, atom_params;  // offsets
  std::vector<std::size_t> connector_data;                                    // offsets
  std::size_t data_size = 0, place_count = 0, clock_count = 0;
  std::vector<Val> params;             // atom parameters, flattened
  std::vector<TimeValue> clock_units;  // per flattened clock
  // Per atom type, in declaration order: transitions labelled by a port, internal ones.
  std::vector<std::vector<TransitionEntry>> labelled_transitions, internal_transitions;
  /// Per atom type whose net is a state machine (one initial place, every transition from one
  /// place to one place: exactly one place is marked at any time), per place: the labelled
  /// transitions from it, in declaration order. Empty for other types.
  std::vector<std::vector<std::vector<TransitionEntry>>> labelled_from_place;
  /// Per atom type and place as labelled_from_place: when every transition from the place is
  /// led by `d == literal` on one datum d (a state variable: `s == 3`), the transitions by
  /// literal, so that an atom looks only at those its value of d can enable.
  std::vector<std::vector<std::optional<ValueDispatch>>> dispatch_from_place;
  /// The leading comparisons of guards (TransitionEntry::leading), and as they are tested.
  std::vector<bipc::ir::LeadingComparison> leading_comparisons;
  std::vector<LeadingTests> leading_tests;
  std::vector<std::vector<DefinedInteraction>> defined;  // per connector, in define order
  /// Per connector: whether `defined` lists every interaction (not when there are too many or
  /// the connector is too wide; it is then maximal_only).
  std::vector<std::uint8_t> enumerated;
  /// Per connector: computes_maximal_only (maximal_interaction.h).
  std::vector<std::uint8_t> maximal_only;
  /// Per connector: the ports every defined interaction contains (none when not enumerated).
  std::vector<PortSet> required_ports;
  std::vector<bool> top_level;           // per connector: not bound by a connector of its compound
  std::vector<Index> listed_connectors;  // connectors without export, in listing order
  std::vector<std::pair<Index, Index>> internal_ports;  // (atom, port) in listing order
  std::vector<std::pair<Index, Index>> extern_ports;    // (atom, port) in listing order
  std::vector<std::vector<PriorityRule>> rules;         // per compound, in declaration order
  /// Per connector: the rules of its compound whose low side names it or is `*`, in order.
  std::vector<std::vector<Index>> rules_by_low;
  std::vector<Index> ruled_compounds;  // the compounds with priority rules, increasing
  std::vector<std::string> atom_names, connector_names;  // full names "ROOT.x"
  /// Atoms in the order they initialise: by name, level by level, as the reference engine's
  /// maps order them.
  std::vector<Index> initial_order;
  /// No atom has a clock and no port is extern: every guard, invariant and resume condition
  /// then holds at all dates or at none, so every enabled item's window is the waiting window.
  bool untimed = false;
};

/// Builds the layout; an error message names what the engines cannot run (e.g. a connector
/// with more than 64 ports and a guard).
std::string build_layout(const bipc::ir::System& system, Layout& layout);

/// The index of the `on` clause (InteractionCode) of exactly the port parameters `ports`
/// (increasing), or -1 when the type has none for them.
int interaction_code(const bipc::ir::ConnectorType& type, std::span<const Index> ports);

/// The interactions a define expression allows, in the reference engine's order: the tree's
/// presence variables are enumerated depth first, 1 before 0.
/// At most this many per connector (a broadcast over 20 ports defines 2^19 of them).
inline constexpr std::size_t kMaxDefinedInteractions = std::size_t{1} << 20;

/// nullopt when there are more than `limit`.
std::optional<std::vector<PortSet>> defined_interactions(
    const std::vector<bipc::ir::DefineNode>& define, std::size_t limit = kMaxDefinedInteractions);

}  // namespace smcbip::engines
