// Replaying a recorded trace (the JSON-lines exchange format of DESIGN.md): a run that fires,
// step by step, the interaction the trace names, which must be enabled when its turn comes,
// and reaches the states the trace records.
#pragma once

#include <cstddef>
#include <istream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace smcbip::engines {

/// One state of a trace to follow, and how it was reached.
struct ReplayStep {
  std::size_t line = 0;  // in the trace file
  /// The connector (`ROOT.c`) or port (`ROOT.a.p`) fired to reach the state; empty for the
  /// initial state.
  std::string fired;
  /// The interaction as the text trace lists it (`ROOT.c: a.p(v=1;) b.q()`), when the trace
  /// gives it (`"interaction"`): it tells apart the interactions of one connector.
  std::string interaction;
  /// The recorded date (`time`, in milliseconds), when the trace gives it.
  std::optional<double> time;
  /// The recorded state, when the trace gives it: marked places per atom, and data values as
  /// JSON text by `atom.datum` (clocks are not compared).
  std::optional<std::map<std::string, std::vector<std::string>>> places;
  std::map<std::string, std::string> data;
};

/// A trace to follow: its states, the initial one first, and how it ended.
struct ReplayScript {
  std::string file;
  std::vector<ReplayStep> steps;
  std::string end;  // `deadlock`, `timelock`, `limit`, `stopped`, `error`, or empty
  std::size_t end_line = 0;
};

/// A line of a trace file that cannot be read: `where` is `file:line`.
class ReplayError : public std::runtime_error {
 public:
  ReplayError(std::string where, const std::string& message)
      : std::runtime_error(message), where(std::move(where)) {}
  std::string where;
};

/// Reads a JSON-lines trace (a header line, one line per state with `step`, `fired`, `places`,
/// `data`, optionally `interaction`, and an `end` line). Throws ReplayError.
ReplayScript read_replay_script(std::istream& in, const std::string& file);

}  // namespace smcbip::engines
