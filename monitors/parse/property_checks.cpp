// The model-free checks of a parsed property file (see property_checks.h).
#include "monitors/parse/property_checks.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>

namespace smcbip::monitors::detail {

namespace {

bool before(const bipc::Location& a, const bipc::Location& b) {
  return std::tie(a.line, a.column) < std::tie(b.line, b.column);
}

/// Nanoseconds per unit; a number without unit counts in milliseconds (the default clock unit).
double nanoseconds(TimeUnit unit) {
  switch (unit) {
    case TimeUnit::Seconds:
      return 1e9;
    case TimeUnit::None:
    case TimeUnit::Milliseconds:
      return 1e6;
    case TimeUnit::Microseconds:
      return 1e3;
    case TimeUnit::Nanoseconds:
      return 1.0;
  }
  return 1e6;
}

/// The most values a parameter may take: a sweep is judged point by point, each with its own
/// runs, so beyond this a sweep cannot finish.
constexpr double kMaxParameterValues = 100000;

/// The most trajectories a simulate query writes: each is a file's worth of lines.
constexpr double kMaxSimulatedRuns = 10000;

/// The most runs an expectation may ask for: far beyond what a machine makes in a day.
constexpr double kMaxRuns = 1e12;

bool is_temporal(const Formula& f) {
  switch (f.kind) {
    case Formula::Kind::Next:
    case Formula::Kind::Finally:
    case Formula::Kind::Globally:
    case Formula::Kind::Until:
    case Formula::Kind::Release:
      return true;
    default:
      break;
  }
  for (const auto& operand : f.operands) {
    if (is_temporal(*operand)) return true;
  }
  return false;
}

class Checker {
 public:
  explicit Checker(bipc::Diagnostics& diagnostics) : diagnostics_(diagnostics) {}

  void run(const PropertyFile& file) {
    for (const Declaration& d : file.declarations) declare(d);
    for (const Query& q : file.queries) query(q);
    // Only in a file otherwise right: a parameter refused already needs no second message.
    if (!diagnostics_.has_errors()) unused_parameters(file);
  }

 private:
  void declare(const Declaration& d) {
    const auto [found, fresh] = declared_.emplace(d.name, d.at);
    if (!fresh) {
      error(d.at, "'" + d.name + "' is declared twice (first at line " +
                      std::to_string(found->second.line) + ")");
    }
    if (d.kind == Declaration::Kind::Constant) return;
    for (const Value& v : d.values) no_unit(v, "a parameter value");
    if (d.range && !(d.values[2].number > 0.0)) {
      error(d.values[2].at, "the step of parameter '" + d.name + "' must be > 0");
    } else if (d.range && d.values[1].number < d.values[0].number) {
      error(d.values[1].at, "parameter '" + d.name + "' stops (" + d.values[1].text +
                                ") before it starts (" + d.values[0].text + ")");
    } else if (d.range) {
      const double count =
          std::floor((d.values[1].number - d.values[0].number) / d.values[2].number) + 1;
      if (!(count <= kMaxParameterValues)) {
        error(d.values[2].at, "parameter '" + d.name + "' would take " + number_text(count) +
                                  " values; a sweep takes at most " +
                                  number_text(kMaxParameterValues) + ": use a larger step");
      }
    } else if (static_cast<double>(d.values.size()) > kMaxParameterValues) {
      error(d.at, "parameter '" + d.name + "' lists more than " + number_text(kMaxParameterValues) +
                      " values");
    }
  }

  static std::string number_text(double x) {
    if (x < 1e15) return std::to_string(static_cast<long long>(x));
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
  }

  // A parameter no query reads sweeps nothing: it is a mistake (a misspelt name, a query
  // forgotten), not a request.
  void unused_parameters(const PropertyFile& file) {
    std::set<std::string> used;
    for (const Query& q : file.queries) used.merge(names_read(q));
    for (const Declaration& d : file.declarations) {
      if (d.kind == Declaration::Kind::Parameter && !used.contains(d.name)) {
        error(d.at, "parameter '" + d.name + "' is not used by any query");
      }
    }
  }

  void query(const Query& q) {
    if ((q.kind == Query::Kind::Invariant || q.kind == Query::Kind::Reachable) &&
        is_temporal(*q.formula)) {
      error(q.formula->at, std::string(q.kind == Query::Kind::Invariant ? "A[]" : "E<>") +
                               " takes a state predicate, without temporal operators");
    }
    run_bound(q.run);
    if (q.kind == Query::Kind::Hypothesis) threshold(q.threshold);
    if (q.kind == Query::Kind::Compare) run_bound(q.other_run);
    if (q.kind == Query::Kind::Simulate) {
      whole(q.runs, "the number of runs", 1.0);
      if (!q.runs.is_name() && q.runs.number > kMaxSimulatedRuns) {
        error(q.runs.at, "simulate writes at most " + number_text(kMaxSimulatedRuns) +
                             " trajectories, got " + q.runs.text);
      }
      for (const auto& e : q.series) expression(*e);
      return;
    }
    if (q.kind == Query::Kind::Expectation) {
      if (q.pr_form) {
        whole(q.runs, "the number of runs", 1.0);
        if (!q.runs.is_name() && q.runs.number > kMaxRuns) {
          error(q.runs.at, "the number of runs must be at most " + number_text(kMaxRuns) +
                               ", got " + q.runs.text);
        }
      }
      expression(*q.observed);
    } else {
      formula(*q.formula);
      if (q.other) formula(*q.other);
    }
  }

  void run_bound(const Bound& b) {
    if (b.kind == Bound::Kind::Steps) whole(b.high, "a step bound", 0.0);
    if (b.kind == Bound::Kind::Time) time(b.high);
  }

  void formula(const Formula& f) {
    switch (f.bound.kind) {
      case Bound::Kind::None:
        break;
      case Bound::Kind::Steps:
        whole(f.bound.high, "a step bound", 0.0);
        break;
      case Bound::Kind::Time:
        interval(f.bound);
        break;
    }
    if (f.atom) expression(*f.atom);
    for (const auto& operand : f.operands) formula(*operand);
  }

  void expression(const Expr& e) {
    for (const auto& operand : e.operands) expression(*operand);
  }

  void interval(const Bound& b) {
    time(b.low);
    time(b.high);
    if (b.low.is_name() || b.high.is_name()) return;
    if (b.low.number * nanoseconds(b.low.unit) > b.high.number * nanoseconds(b.high.unit)) {
      error(b.low.at, "the interval [" + to_string(b.low) + "," + to_string(b.high) +
                          "] is empty: its lower bound is above its upper bound");
    }
  }

  void time(const Value& v) {
    if (used(v) && !v.is_name() && v.number < 0.0) {
      error(v.at, "a time bound must be >= 0, got " + to_string(v));
    }
  }

  void whole(const Value& v, const std::string& what, double least) {
    if (!used(v) || v.is_name()) return;
    no_unit(v, what);
    if (!v.integral || v.number < least) {
      error(v.at, what + " must be a whole number >= " + std::to_string(static_cast<int>(least)) +
                      ", got " + v.text);
    }
  }

  void threshold(const Value& v) {
    if (!used(v) || v.is_name()) return;
    no_unit(v, "a probability threshold");
    if (v.number < 0.0 || v.number > 1.0) {
      error(v.at, "a probability threshold must lie in [0, 1], got " + v.text);
    }
  }

  void no_unit(const Value& v, const std::string& what) {
    if (!v.is_name() && v.unit != TimeUnit::None) {
      error(v.at, what + " takes no time unit, got " + to_string(v));
    }
  }

  /// Whether a name is declared before `v` (reported otherwise); true for numbers.
  bool used(const Value& v) {
    if (!v.is_name()) return true;
    const auto found = declared_.find(v.name);
    if (found == declared_.end()) {
      error(v.at, "unknown constant or parameter '" + v.name + "'");
      return false;
    }
    if (before(v.at, found->second)) {
      error(v.at, "'" + v.name + "' is used before its declaration at line " +
                      std::to_string(found->second.line));
      return false;
    }
    return true;
  }

  void error(bipc::Location at, const std::string& message) { diagnostics_.error(at, message); }

  bipc::Diagnostics& diagnostics_;
  std::map<std::string, bipc::Location> declared_;
};

}  // namespace

void check_properties(const PropertyFile& file, bipc::Diagnostics& diagnostics) {
  Checker(diagnostics).run(file);
}

}  // namespace smcbip::monitors::detail
