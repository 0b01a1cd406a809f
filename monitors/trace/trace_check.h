// The queries of a property file judged on recorded runs (the JSON-lines exchange format of
// DESIGN.md): each step is read once and given to every query's monitor, so a trace of any
// length is checked in the memory its formulas need.
#pragma once

#include <cstddef>
#include <istream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "bipc/errors.h"
#include "monitors/online/online_monitor.h"
#include "monitors/property/ast.h"

namespace smcbip::monitors {

/// One fault of a trace: where (line and byte column, from 1) and what.
struct TraceFault {
  std::size_t line = 0;
  std::size_t column = 0;
  std::string message;
};

/// The most faults a TraceError lists; it counts the others.
inline constexpr std::size_t kMaxTraceFaults = 20;

/// A trace that is not in the exchange format: its first faults in file order (at most
/// kMaxTraceFaults) and how many more it has. An input error at the first fault; report() is
/// one `path:line:column: error: message` line per fault, then `path: error: N more errors not
/// shown` when there are more.
class TraceError : public InputError {
 public:
  TraceError(std::string path, std::vector<TraceFault> faults, std::size_t more);
  std::string report() const;
  std::string path;
  std::vector<TraceFault> faults;  // never empty
  std::size_t more = 0;
};

/// The verdict of one query for one value of its parameters.
struct TraceResult {
  std::size_t query = 0;  // index in PropertyFile::queries
  Bindings parameters;    // the parameters the query names, with their values
  Verdict verdict = Verdict::Undecided;
  std::optional<double> value;  // expectations: the maximum or minimum over the run
};

struct TraceReport {
  std::size_t steps = 0;
  std::string end;  // as the trace says: "deadlock", "timelock", "limit", ... or "" (none)
  std::vector<TraceResult> results;
};

/// Checks every query of `file` on the trace read from `in` (`path` names it in errors).
/// Names of predicates are bound to the trace's data and places (paths may drop the root's
/// name); what does not bind is reported in `diagnostics` (then the report is empty). A run
/// that ends in a deadlock keeps its last state; one that ends otherwise, or without an end
/// line, is cut short. The whole trace is read for faults: lines that are not JSON objects,
/// steps without a number "time" or whose time goes back, data the queries read that are not
/// numbers or booleans (or missing), places of their atoms that are not lists of names, end
/// lines of an unknown reason, lines after the end line. Throws TraceError when it finds any,
/// and MonitorError for bounds the scale cannot hold.
TraceReport check_trace(const PropertyFile& file, std::istream& in, const std::string& path,
                        const TimeScale& scale, bipc::Diagnostics& diagnostics,
                        Reading reading = Reading::Continuous);

/// The values of a file's constants, and each parameter's list of values.
Bindings constant_values(const PropertyFile& file);
std::map<std::string, std::vector<double>> parameter_values(const PropertyFile& file);
/// The bindings a query is judged under: the constants, with every combination of the values
/// of the parameters it names.
std::vector<Bindings> query_bindings(const PropertyFile& file, const Query& query);

}  // namespace smcbip::monitors
