// The model-free checks of a parsed property file (see property_checks.h).
#include "monitors/parse/property_checks.h"

#include <map>
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

class Checker {
 public:
  explicit Checker(bipc::Diagnostics& diagnostics) : diagnostics_(diagnostics) {}

  void run(const PropertyFile& file) {
    for (const Declaration& d : file.declarations) declare(d);
    for (const Query& q : file.queries) query(q);
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
    }
  }

  void query(const Query& q) {
    run_bound(q.run);
    if (q.kind == Query::Kind::Hypothesis) threshold(q.threshold);
    if (q.kind == Query::Kind::Expectation) {
      if (q.pr_form) whole(q.runs, "the number of runs", 1.0);
      expression(*q.observed);
    } else {
      formula(*q.formula);
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
