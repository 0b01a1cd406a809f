// Observable traces of a BIP system's untimed abstraction, projected on named ports and places,
// and their comparison: what the translation of a TASTE design is checked against the original
// translator's BIP of it with.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"

namespace smcbip::taste2bip::test {

/// What is observable, under common labels so that two models' names meet.
struct WatchdogObservation {
  /// Atom ports, "atom.port" (atom path below the root): a step whose interaction (or internal
  /// port) fires one of them shows its label.
  std::map<std::string, std::string> ports;
  /// Places, "atom.place": a step after which the place is marked and was not before shows its
  /// label (an atom entering an SDL state); in an atom with a place `ready` (taste2bip's SDL
  /// atoms, whose state stays marked while a transition runs), also a step that marks `ready`
  /// again.
  std::map<std::string, std::string> places;
  /// Data, "atom.data" or "*.data" (every atom's), reset to zero after every step: for data
  /// that nothing reads but their own update (counters of dropped calls), which would make the
  /// untimed state space infinite. Erasing data that a guard or another update reads changes
  /// the behaviour: only the caller can tell, so it names them.
  std::set<std::string> erased_data;
};

/// How far the traces are explored (stated by each test).
struct TraceBounds {
  std::size_t events = 6;          // k: observable events per trace
  std::size_t silent_steps = 100;  // silent steps in a row explored after a trace's last event
  std::size_t states = 100'000;    // states explored over all traces
};

using Trace = std::vector<std::string>;

/// Shorter traces first, then in lexicographic order of their events.
struct ShorterFirst {
  bool operator()(const Trace& a, const Trace& b) const {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  }
};

/// The observable traces of at most `events` events (prefix-closed: the empty trace is in).
struct TraceSet {
  std::set<Trace, ShorterFirst> traces;
  std::uint64_t states = 0;  // (trace, state) pairs explored
  std::uint64_t errors = 0;  // executions that failed (their successors are missing)
  /// The state or silent-step bound left states unexplored: traces may be missing.
  bool cut = false;
  std::string problem;  // the system could not be explored at all
};

/// The traces of `untimed` (a system already abstracted, see watchdog_untimed.h), found
/// breadth first over (state, trace) with silent steps closed: from each trace's states, every
/// enabled item of every state reachable by silent steps is executed once; an observable step
/// extends the trace by its labels (observed ports sorted, then places entered sorted). A step
/// showing several labels adds them one after the other. Untimed means all dates are 0.
TraceSet projected_traces(const bipc::ir::System& untimed, const engines::Externs& externs,
                          const WatchdogObservation& observation, const TraceBounds& bounds);

/// The first trace (shortest, then lexicographic) that one set has and the other has not.
struct TraceDifference {
  std::optional<Trace> only_left, only_right;
  bool equal() const { return !only_left && !only_right; }
};
TraceDifference compare_traces(const TraceSet& left, const TraceSet& right);

/// `a, b, c` (and `<empty>` for the empty trace).
std::string trace_text(const Trace& trace);

/// A readable report of a difference: which trace the left (`left_name`) has and the right
/// has not, with the right's traces that share its longest prefix; and the converse.
std::string difference_report(const TraceSet& left, const TraceSet& right,
                              const TraceDifference& difference, const std::string& left_name,
                              const std::string& right_name);

}  // namespace smcbip::taste2bip::test
