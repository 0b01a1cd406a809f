#include "monitors/trace/trace_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <unordered_map>
#include <utility>

#include "monitors/online/critical_bound.h"
#include "monitors/online/extremum.h"
#include "monitors/trace/detail/trace_reader.h"

namespace smcbip::monitors {
namespace {

using Json = nlohmann::json;

/// The path without its first component (the root's name, which trace paths may drop).
std::string without_root(const std::string& path) {
  const std::size_t dot = path.find('.');
  return dot == std::string::npos ? std::string() : path.substr(dot + 1);
}

/// Whether a path of the trace and a path of a property name the same thing.
bool same_path(const std::string& in_trace, const std::string& in_property) {
  return in_trace == in_property || without_root(in_trace) == in_property ||
         in_trace == without_root(in_property);
}

/// What a name of a predicate reads in each step.
struct TraceName {
  enum class Kind : std::uint8_t { Data, Place } kind = Kind::Data;
  std::string key;    // Data: the data key; Place: the atom's key in "places"
  std::string place;  // Place
};

using detail::TraceClocks;

/// One step of a trace as a state: its data, marked places and fired interaction; the data its
/// header declares clocks grow at their rates after the step.
class StepState final : public StateView {
 public:
  StepState(const std::unordered_map<const Expr*, TraceName>& names, const TraceClocks& clocks,
            double ticks_per_ms)
      : names_(names), clocks_(clocks), ticks_per_ms_(ticks_per_ms) {}

  double slope(const Expr& name) const override {
    const TraceName& n = names_.at(&name);
    if (n.kind != TraceName::Kind::Data) return 0;
    const auto clock = clocks_.find(n.key);
    if (clock == clocks_.end()) return 0;
    const Json* rate = member(member(&line_, "rates"), n.key);
    const double r = rate != nullptr && rate->is_number() ? rate->get<double>() : 1.0;
    // Units per millisecond, then per tick.
    return r * 1e6 / clock->second / ticks_per_ms_;
  }

  void read(Json line) { line_ = std::move(line); }

  double value(const Expr& name) const override {
    const TraceName& n = names_.at(&name);
    if (n.kind == TraceName::Kind::Data) {
      const Json* v = member(member(&line_, "data"), n.key);
      if (v != nullptr && v->is_boolean()) return v->get<bool>() ? 1 : 0;
      return v != nullptr && v->is_number() ? v->get<double>()
                                            : std::numeric_limits<double>::quiet_NaN();
    }
    const Json* marked = member(member(&line_, "places"), n.key);
    if (marked == nullptr || !marked->is_array()) return 0;
    for (const Json& place : *marked) {
      if (place.is_string() && place.get_ref<const std::string&>() == n.place) return 1;
    }
    return 0;
  }

  bool fired(const Expr& fired) const override {
    const Json* f = member(&line_, "fired");
    return f != nullptr && f->is_string() &&
           same_path(f->get_ref<const std::string&>(), fired.path);
  }

 private:
  /// The member `key` of an object, or null.
  static const Json* member(const Json* object, const std::string& key) {
    if (object == nullptr || !object->is_object()) return nullptr;
    const auto it = object->find(key);
    return it == object->end() ? nullptr : &*it;
  }

  const std::unordered_map<const Expr*, TraceName>& names_;
  const TraceClocks& clocks_;
  double ticks_per_ms_;
  Json line_;
};

/// Binds the names of the file's predicates to the keys of the first step.
class NameBinder {
 public:
  NameBinder(const Json& first, const Bindings& constants, bipc::Diagnostics& diagnostics)
      : constants_(constants), diagnostics_(diagnostics) {
    if (first.contains("data")) {
      for (const auto& [key, value] : first["data"].items()) data_.push_back(key);
    }
    if (first.contains("places")) {
      for (const auto& [key, value] : first["places"].items()) atoms_.push_back(key);
    }
  }

  void expression(const Expr& e) {
    for (const auto& operand : e.operands) expression(*operand);
    if (e.kind != Expr::Kind::Name || is_builtin(e.reference) || constants_.contains(e.path)) {
      return;
    }
    std::vector<TraceName> found;
    for (const std::string& key : data_) {
      if (same_path(key, e.path)) found.push_back({TraceName::Kind::Data, key, ""});
    }
    // Only marked places appear in a trace: a member that is no data is taken for a place.
    const std::size_t dot = e.path.rfind('.');
    if (found.empty() && dot != std::string::npos) {
      for (const std::string& atom : atoms_) {
        if (same_path(atom, e.path.substr(0, dot))) {
          found.push_back({TraceName::Kind::Place, atom, e.path.substr(dot + 1)});
        }
      }
    }
    if (found.size() == 1) {
      names_.emplace(&e, found.front());
    } else {
      diagnostics_.error(e.at, "'" + e.path + "' names " +
                                   (found.empty() ? "no data or place of the trace"
                                                  : "several data or places of the trace"));
    }
  }

  void formula(const Formula& f) {
    if (f.atom) expression(*f.atom);
    for (const auto& operand : f.operands) formula(*operand);
  }

  std::unordered_map<const Expr*, TraceName> take() { return std::move(names_); }

 private:
  const Bindings& constants_;
  bipc::Diagnostics& diagnostics_;
  std::vector<std::string> data_, atoms_;
  std::unordered_map<const Expr*, TraceName> names_;
};

/// Every combination of the values of the parameters `used` names, added to `base`.
std::vector<Bindings> combinations(const std::map<std::string, std::vector<double>>& parameters,
                                   const std::set<std::string>& used, const Bindings& base) {
  std::vector<Bindings> all{base};
  for (const auto& [name, values] : parameters) {
    if (!used.contains(name)) continue;
    std::vector<Bindings> more;
    for (const Bindings& b : all) {
      for (double v : values) {
        more.push_back(b);
        more.back()[name] = v;
      }
    }
    all = std::move(more);
  }
  return all;
}

/// What judges one query for one value of its parameters.
struct Judge {
  TraceResult result;
  std::unique_ptr<OnlineMonitor> monitor;  // path formulas
  std::unique_ptr<Extremum> extremum;      // expectations
  CriticalBound* sweep = nullptr;          // F[0,t] / G[0,t] over a parameter: all values
  double value = 0;                        // of the parameter, for the sweep
};

/// The one parameter a query names, when its formula sweeps it by a critical bound.
std::optional<std::string> swept_parameter(
    const Query& q, const std::map<std::string, std::vector<double>>& parameters) {
  if (!q.formula || q.run.kind != Bound::Kind::None) return std::nullopt;
  std::optional<std::string> swept;
  for (const std::string& name : names_read(q)) {
    if (!parameters.contains(name)) continue;
    if (swept) return std::nullopt;
    swept = name;
  }
  if (swept && !has_critical_bound(*q.formula, *swept)) return std::nullopt;
  return swept;
}

}  // namespace

Bindings constant_values(const PropertyFile& file) {
  Bindings values;
  for (const Declaration& d : file.declarations) {
    if (d.kind != Declaration::Kind::Constant) continue;
    values[d.name] = d.value.is_name() ? values.at(d.value.name) : d.value.number;
  }
  return values;
}

std::map<std::string, std::vector<double>> parameter_values(const PropertyFile& file) {
  std::map<std::string, std::vector<double>> values;
  for (const Declaration& d : file.declarations) {
    if (d.kind != Declaration::Kind::Parameter) continue;
    std::vector<double>& list = values[d.name];
    if (!d.range) {
      for (const Value& v : d.values) list.push_back(v.number);
      continue;
    }
    const double start = d.values[0].number, stop = d.values[1].number, step = d.values[2].number;
    // Counted rather than accumulated, so that the last value is not lost to rounding.
    const auto count = static_cast<std::int64_t>(std::floor((stop - start) / step + 1e-9));
    for (std::int64_t i = 0; i <= count; ++i) list.push_back(start + static_cast<double>(i) * step);
  }
  return values;
}

std::vector<Bindings> query_bindings(const PropertyFile& file, const Query& query) {
  return combinations(parameter_values(file), names_read(query), constant_values(file));
}

TraceReport check_trace(const PropertyFile& file, std::istream& in, const std::string& path,
                        const TimeScale& scale, bipc::Diagnostics& diagnostics, Reading reading) {
  for (const Query& q : file.queries) {
    if (q.kind == Query::Kind::Compare || q.kind == Query::Kind::Simulate) {
      diagnostics.error(q.at,
                        "a comparison of two probabilities or a simulate query needs runs "
                        "of a model: use smcbip check");
    }
    if (q.kind == Query::Kind::Invariant || q.kind == Query::Kind::Reachable) {
      diagnostics.error(q.at, std::string(q.kind == Query::Kind::Invariant ? "A[]" : "E<>") +
                                  " is a question over every reachable state, which one recorded "
                                  "run cannot answer: the invariant prover (smcbip prove) "
                                  "answers it");
    }
  }
  if (diagnostics.has_errors()) return {};
  detail::TraceReader reader(in, path, scale.ticks_per_unit);
  std::optional<Json> line = reader.next();
  if (!line) {
    if (!reader.faulty()) reader.fault("expected at least one step");
    reader.finish();
  }

  const Bindings constants = constant_values(file);
  const auto parameters = parameter_values(file);
  Bindings declared = constants;  // names that are no part of the trace
  for (const auto& [name, values] : parameters) declared[name] = values.front();
  NameBinder binder(*line, declared, diagnostics);
  for (const Query& q : file.queries) {
    if (q.formula) binder.formula(*q.formula);
    if (q.observed) binder.expression(*q.observed);
  }
  if (diagnostics.has_errors()) return {};
  const std::unordered_map<const Expr*, TraceName> names = binder.take();
  std::set<std::string> data, atoms;
  for (const auto& [expr, name] : names) {
    (name.kind == TraceName::Kind::Data ? data : atoms).insert(name.key);
  }
  reader.require({data.begin(), data.end()}, {atoms.begin(), atoms.end()});

  std::vector<Judge> judges;
  std::vector<std::unique_ptr<CriticalBound>> sweeps;
  for (std::size_t i = 0; i < file.queries.size(); ++i) {
    const Query& q = file.queries[i];
    const auto swept =
        reading == Reading::Continuous ? swept_parameter(q, parameters) : std::nullopt;
    if (swept) {
      const std::vector<double>& values = parameters.at(*swept);
      sweeps.push_back(std::make_unique<CriticalBound>(
          *q.formula, *swept, *std::max_element(values.begin(), values.end()), scale, constants));
      for (double value : values) {
        Judge& judge = judges.emplace_back();
        judge.result.query = i;
        judge.result.parameters[*swept] = value;
        judge.sweep = sweeps.back().get();
        judge.value = value;
      }
      continue;
    }
    for (const Bindings& bindings : combinations(parameters, names_read(q), constants)) {
      Judge& judge = judges.emplace_back();
      judge.result.query = i;
      for (const auto& [name, value] : bindings) {
        if (parameters.contains(name)) judge.result.parameters[name] = value;
      }
      if (q.formula) {
        judge.monitor =
            std::make_unique<OnlineMonitor>(*q.formula, scale, bindings, q.run, reading);
      } else {
        judge.extremum = std::make_unique<Extremum>(q, scale, bindings);
      }
    }
  }

  TraceReport report;
  StepState state(names, reader.clocks(), scale.ticks_per_unit);
  online::Tick first = 0;
  for (; line; line = reader.next()) {
    // Past a fault the trace is only read for more of them.
    if (reader.faulty()) continue;
    const online::Tick ticks = reader.ticks();
    if (report.steps == 0) first = ticks;
    state.read(std::move(*line));
    for (auto& sweep : sweeps) sweep->step(state, ticks);
    for (Judge& judge : judges) {
      if (judge.monitor) judge.monitor->step(state, ticks);
      if (judge.extremum) {
        judge.extremum->step(state, ticks - first, static_cast<std::int64_t>(report.steps));
      }
    }
    ++report.steps;
  }
  reader.finish();
  report.end = reader.end();
  const RunEnd end = report.end == "deadlock"    ? RunEnd::Deadlock
                     : report.end == "timelock"  ? RunEnd::Timelock
                     : report.end == "absorbing" ? RunEnd::Absorbing
                                                 : RunEnd::Cut;
  for (auto& sweep : sweeps) sweep->end(end);
  for (Judge& judge : judges) {
    if (judge.monitor) judge.result.verdict = judge.monitor->end(end);
    if (judge.sweep) judge.result.verdict = judge.sweep->verdict(judge.value);
    if (judge.extremum) {
      judge.extremum->end(end);
      judge.result.value = judge.extremum->value();
    }
    report.results.push_back(std::move(judge.result));
  }
  return report;
}

}  // namespace smcbip::monitors
