// The priority rules of an atom type (`priority name low < high provided guard`): which offers
// of an atom they withdraw, and their cycle check.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/model.h"
#include "engines/interpreter/code_eval.h"

namespace smcbip::engines {

/// Applies an atom type's priority rules to the offers of one of its atoms, with buffers reused
/// from atom to atom: one per thread that fires atoms.
class AtomPriorities {
 public:
  /// Withdraws the offers (`offers`: per port of the type) of ports that a chain of active rules
  /// leads from to an enabled port; `f`: the atom's frame. False when the active rules form a
  /// cycle (the reference engine's error 4), which leaves the offers as they were.
  bool apply(const bipc::ir::AtomType& type, ModelCode& eval, const Frame& f,
             std::optional<AtomPortValue>* offers);

 private:
  void evaluate_guards(const bipc::ir::AtomType& type, ModelCode& eval, const Frame& f);
  bool acyclic(const bipc::ir::AtomType& type);
  /// Whether the rule's high side names an enabled port (extern ports do not dominate).
  bool high_enabled(const bipc::ir::AtomType& type, std::size_t rule,
                    const std::optional<AtomPortValue>* offers) const;
  /// Whether a chain of active rules from port `p` ends at an enabled port.
  bool dominated(const bipc::ir::AtomType& type, std::size_t p,
                 const std::optional<AtomPortValue>* offers);

  std::vector<std::uint8_t> active_;    // per rule: its guard holds
  std::vector<std::uint8_t> colour_;    // per rule, in the cycle search
  std::vector<std::uint8_t> disabled_;  // per port
  std::vector<std::uint8_t> seen_;      // per rule, in the chains from one port
  std::vector<std::size_t> chain_ends_;
  std::vector<std::pair<std::size_t, std::size_t>> path_;  // cycle search: (rule, next rule)
};

}  // namespace smcbip::engines
