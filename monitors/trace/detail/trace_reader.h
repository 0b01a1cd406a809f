// Reading the JSON lines of a recorded run (the exchange format of DESIGN.md) step by step,
// with every fault located at its line and column and the reading going on past it.
#pragma once

#include <cstddef>
#include <istream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "monitors/online/signal.h"
#include "monitors/trace/trace_check.h"

namespace smcbip::monitors::detail {

/// The clocks a trace's header declares: nanoseconds per unit of each.
using TraceClocks = std::unordered_map<std::string, double>;

/// The reasons an end line may give, as `smcbip simulate --trace jsonl` writes them.
inline constexpr std::string_view kEndReasons[] = {"deadlock", "timelock", "limit",
                                                   "stopped",  "error",    "absorbing"};

/// The column (from 1) at which the value of the member `keys[0]` of the JSON object `text`,
/// then of its member `keys[1]`, and so on, begins; 0 when there is none. `text` must be valid
/// JSON; of repeated keys the last counts, as for the parsed value.
std::size_t value_column(std::string_view text, const std::vector<std::string>& keys);

/// A trace's header line (first, optional), its steps, then perhaps its end line. A faulty line is
/// recorded (the first fault of each line) and skipped, so that one reading finds the faults of the
/// whole trace.
class TraceReader {
 public:
  TraceReader(std::istream& in, std::string path, double ticks_per_unit)
      : in_(in), path_(std::move(path)), ticks_per_unit_(ticks_per_unit) {}

  /// The next well-formed step, or nullopt when the trace is over.
  std::optional<nlohmann::json> next();

  /// The time of the step next() returned last, in ticks.
  online::Tick ticks() const { return ticks_; }

  /// From now on (the step returned last included), every step must hold each of `data` as a
  /// number or boolean, and a list of place names for each of `atoms` in "places".
  void require(std::vector<std::string> data, std::vector<std::string> atoms);

  /// The clocks the header declares.
  const TraceClocks& clocks() const { return clocks_; }

  /// The end line's reason, or "" when there is none.
  const std::string& end() const { return end_; }

  bool faulty() const { return !faults_.empty(); }

  /// Records a fault of the whole trace (at the line last read, column 1).
  void fault(const std::string& message) { fault_at(1, message); }

  /// Throws TraceError when a fault was found.
  void finish() const;

 private:
  /// Checks the line read last; false (after recording why) when it is not a good step.
  bool check_step(const nlohmann::json& line);
  bool check_end(const nlohmann::json& line);
  /// `"header": {"clocks": {"ROOT.a.x": {"unit_ns": 1000000}, ...}}`, on the first line.
  bool check_header(const nlohmann::json& line, bool first);
  bool check_required(const nlohmann::json& line);
  /// Records a fault at `column` of the line last read.
  bool fault_at(std::size_t column, const std::string& message);
  /// The column of a member's value in the line last read (that of its first byte if none).
  std::size_t column(const std::vector<std::string>& keys) const;

  std::istream& in_;
  std::string path_;
  double ticks_per_unit_;
  std::string text_;  // the line last read
  std::size_t line_ = 0;
  bool any_line_ = false;  // that is not blank
  std::size_t end_line_ = 0;
  TraceClocks clocks_;
  std::string end_;
  bool any_step_ = false;
  online::Tick ticks_ = 0, last_ = 0;
  std::vector<std::string> data_, atoms_;
  std::vector<TraceFault> faults_;
  std::size_t more_ = 0;
};

}  // namespace smcbip::monitors::detail
