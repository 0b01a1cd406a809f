// Connectors whose interactions are found from the define tree instead of by enumeration: a
// broadcast over n ports defines 2^(n-1) interactions, but under maximal progress only the
// largest enabled one can execute, and it is unique and found in one pass over the tree.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::engines {

using bipc::ir::Index;

/// Whether a connector's executable interactions under maximal progress are exactly the
/// combinations of offers of its largest enabled port set whenever its enabled ports all offer
/// the same constraint, open to the right (Runtime::compute_connector checks that part): no
/// export (nothing above sees its dominated interactions), only atom ports bound, guards empty
/// and `up`s calling nothing (so skipping the dominated interactions skips nothing observable),
/// and no priority rule of its compound naming it or `*`.
bool computes_maximal_only(const bipc::ir::System& system, Index connector);

/// The largest port set the define expression allows among the ports with `enabled[i]` set,
/// in increasing port order, into `out`; false (and `out` empty) when no interaction is enabled.
/// A leaf is its port; a node without triggers needs all its children; a node with triggers
/// takes every enabled child provided one of them is a trigger. Each child's largest set
/// contains all its others, so the union is the one largest set.
bool largest_enabled_interaction(const std::vector<bipc::ir::DefineNode>& define,
                                 std::span<const std::uint8_t> enabled, std::vector<Index>& out);

}  // namespace smcbip::engines
