// Assumptions the user states in SMT-LIB2 files, parsed by Z3 over the names of a global state,
// and used by the prover only once they are shown inductive relative to its invariants.
#pragma once

#include <z3++.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fdir/smt/code_encoding.h"
#include "fdir/smt/state_encoding.h"

namespace smcbip::fdir {

/// An assumption file as read: its name (for messages) and its text.
struct AssumptionSource {
  std::string file;
  std::string text;
};

/// A mistake in an assumption file, or an assumption refused: `file:line:column: error: what`
/// (line 0: the file as a whole).
class AssumptionError : public std::runtime_error {
 public:
  AssumptionError(std::string file, unsigned line, unsigned column, const std::string& message)
      : std::runtime_error(message), file(std::move(file)), line(line), column(column) {}
  std::string file;
  unsigned line = 0, column = 0;
};

/// Where an assumption was stated: its file, the position of its `(assert`, and its formula
/// as Z3 prints it with the file's names.
struct AssumptionSite {
  std::string file;
  unsigned line = 0, column = 0;
  std::string text;
};

/// One `(assert ...)` of a file, over the state's variables.
struct Assumption {
  AssumptionSite site;
  z3::expr formula;
};

/// The names an assumption may use: `ROOT.atom.place` (Bool) per place, `ROOT.atom.datum` per
/// int (Int) or bool (Bool) datum, as the state encoding names them; a place whose name a
/// datum also has is written `@ROOT.atom.place` (also accepted for every place).
/// Parses the assertions of `source` with Z3's SMT-LIB2 parser. Only `assert`, `define-fun`,
/// `define-sort`, `set-info` and `check-sat` may appear: a declaration would bring names the
/// model does not have. Throws AssumptionError at the position Z3 or the scan gives.
std::vector<Assumption> parse_assumptions(const AssumptionSource& source,
                                          const StateEncoding& state);

/// Checks that the conjunction A of `assumptions` holds in the initial state and is inductive
/// relative to `invariant` (CI, bounds and the traps known): for every net transition t,
/// invariant && A && t enabled && s' the state after t implies A in s'. A connector's `down`
/// havocs the data it writes through a port; unknown values (floats, calls) may be any.
/// Traps that exclude a pre-state are added to `invariant` (counted in `traps`) as the prover
/// does. Throws AssumptionError at the first assertion broken, naming the transition.
void check_inductive(const std::vector<Assumption>& assumptions, const StateEncoding& state,
                     CodeEncoder& encoder, z3::expr_vector& invariant, std::size_t& traps);

}  // namespace smcbip::fdir
