#include "smc/tools/report.h"

#include <iomanip>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "bipc/json_dump.h"
#include "smc/stats/sampling_plans.h"

namespace smcbip::tools {
namespace {

bool has_interval(const smc::QueryResult& r) {
  return r.method != smc::Method::Sprt && r.method != smc::Method::Ssp &&
         r.method != smc::Method::Paired;
}

std::string verdict_text(const smc::QueryResult& r) {
  if (!r.verdict) return "";
  return *r.verdict ? "holds" : "does not hold";
}

/// Why the results of one query hold together: one band, or α split over its points.
std::string guarantee(const smc::QueryResult& first, std::size_t points) {
  std::ostringstream out;
  if (first.method == smc::Method::Band) {
    out << "one set of " << first.samples << " runs judges all " << points
        << " values; each estimate is within +-"
        << number_text(smc::dkw_half_width(first.samples, first.alpha), 3)
        << " of its probability, all at once, with confidence " << number_text(1 - first.alpha)
        << " (DKW band)";
  } else if (first.split > 1) {
    out << "the " << points << " points share their runs; alpha "
        << number_text(first.alpha * static_cast<double>(first.split)) << " is split over them ("
        << number_text(first.alpha, 4) << " each), so every answer holds at once with confidence "
        << number_text(1 - first.alpha * static_cast<double>(first.split));
  } else {
    out << "one point";
  }
  return out.str();
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

std::string parameters_text(const smc::QueryResult& r) {
  std::string text;
  for (const auto& [name, value] : r.parameters) text += " " + name + "=" + number_text(value);
  return text;
}

std::string number_text(double v, int digits) {
  std::ostringstream out;
  out << std::setprecision(digits) << v;
  return out.str();
}

std::string query_text(const Report& report, const smc::QueryResult& r) {
  return to_string(report.file.queries[r.query]);
}

void print_results(std::ostream& out, const Report& report) {
  for (const smc::QueryResult& r : report.results) {
    out << query_text(report, r) << parameters_text(r) << "\n  "
        << (r.trajectories ? "simulate" : smc::method_name(r.method)) << ": ";
    if (!r.error.empty()) {
      out << "no answer: " << r.error << "\n";
      continue;
    }
    if (r.trajectories) {
      std::size_t points = 0;
      for (const auto& run : r.trajectories->runs) points += run.size();
      out << r.samples << " runs, " << points << " points, " << number_text(r.seconds)
          << " s (--trajectories DIR writes them as CSV and SVG)\n";
      continue;
    }
    if (r.verdict) out << verdict_text(r) << ", ";
    out << "estimate " << number_text(r.estimate);
    if (has_interval(r))
      out << " in [" << number_text(r.ci.low) << ", " << number_text(r.ci.high) << "]";
    out << ", " << r.samples << " runs";
    if (r.undecided > 0) out << " (" << r.undecided << " undecided)";
    out << ", " << number_text(r.seconds) << " s\n";
  }
}

void print_sweeps(std::ostream& out, const Report& report) {
  const auto& rs = report.results;
  for (std::size_t i = 0; i < rs.size();) {
    std::size_t end = i;
    while (end < rs.size() && rs[end].query == rs[i].query) ++end;
    out << query_text(report, rs[i]) << "\n  " << smc::method_name(rs[i].method) << ": "
        << guarantee(rs[i], end - i) << "\n";
    for (; i < end; ++i) {
      const smc::QueryResult& r = rs[i];
      out << "  ";
      for (const auto& [name, value] : r.parameters) {
        out << name << "=" << std::left << std::setw(8) << number_text(value) << " ";
      }
      out << std::right;
      if (!r.error.empty()) {
        out << "no answer: " << r.error << "\n";
        continue;
      }
      out << std::setw(10) << number_text(r.estimate);
      if (has_interval(r)) {
        out << "  [" << number_text(r.ci.low, 4) << ", " << number_text(r.ci.high, 4) << "]";
      }
      if (r.verdict) out << "  " << verdict_text(r);
      out << "  " << r.samples << " runs";
      if (r.undecided > 0) out << " (" << r.undecided << " undecided)";
      out << "\n";
    }
    out << "  " << number_text(rs[end - 1].seconds, 3) << " s\n";
  }
}

std::string json_text(const Report& report) {
  using Json = nlohmann::ordered_json;
  Json results = Json::array();
  for (const smc::QueryResult& r : report.results) {
    Json line;
    line["query"] = query_text(report, r);
    line["method"] = smc::method_name(r.method);
    line["param"] = Json::object();
    for (const auto& [name, value] : r.parameters) line["param"][name] = value;
    line["estimate"] = r.error.empty() ? Json(r.estimate) : Json(nullptr);
    line["ci"] = r.error.empty() ? Json::array({r.ci.low, r.ci.high}) : Json(nullptr);
    line["verdict"] = r.verdict ? Json(*r.verdict) : Json(nullptr);
    line["samples"] = r.samples;
    line["undecided"] = r.undecided;
    line["seconds"] = r.seconds;
    line["alpha"] = r.alpha;
    const smc::UndecidedRuns& why = r.why_undecided;
    line["undecided_runs"] = {{"limit", why.limit},
                              {"timelock", why.timelock},
                              {"error", why.error},
                              {"ended", why.ended}};
    if (!why.first_error.empty()) {
      line["first_model_error"] = {{"run", why.first_error_run}, {"message", why.first_error}};
    }
    if (!r.error.empty()) line["error"] = r.error;
    if (r.trajectories) {
      line["series"] = r.trajectories->series;
      line["runs"] = r.trajectories->runs;
    }
    results.push_back(std::move(line));
  }
  Json out;
  out["model"] = {{"file", report.model}, {"root", report.root}, {"hash", report.hash}};
  if (const smc::CheckOptions* o = report.settings.options) {
    out["settings"] = {{"method", report.settings.method},
                       {"seed", o->seed},
                       {"alpha", o->alpha},
                       {"beta", o->beta},
                       {"delta", o->delta},
                       {"confidence", o->confidence},
                       {"max_steps", o->max_steps},
                       {"undecided", report.settings.undecided},
                       {"param", report.settings.parameters}};
  }
  out["results"] = std::move(results);
  return bipc::dump_json(out, 2) + "\n";
}

std::string csv_text(const Report& report) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const smc::QueryResult& r : report.results) {
    for (const auto& [name, value] : r.parameters) {
      if (seen.insert(name).second) names.push_back(name);
    }
  }
  std::ostringstream out;
  out << "query";
  for (const std::string& name : names) out << "," << csv_field(name);
  out << ",method,estimate,ci_low,ci_high,verdict,samples,undecided,alpha,seconds\n";
  for (const smc::QueryResult& r : report.results) {
    out << csv_field(query_text(report, r));
    for (const std::string& name : names) {
      out << ",";
      if (const auto found = r.parameters.find(name); found != r.parameters.end()) {
        out << number_text(found->second, 17);
      }
    }
    out << "," << smc::method_name(r.method) << ",";
    if (r.error.empty()) {
      out << number_text(r.estimate, 17) << "," << number_text(r.ci.low, 17) << ","
          << number_text(r.ci.high, 17);
    } else {
      out << ",,";
    }
    out << "," << (r.verdict ? (*r.verdict ? "true" : "false") : "") << "," << r.samples << ","
        << r.undecided << "," << number_text(r.alpha, 17) << "," << number_text(r.seconds) << "\n";
  }
  return out.str();
}

}  // namespace smcbip::tools
