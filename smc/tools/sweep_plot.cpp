#include "smc/tools/sweep_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "smc/tools/svg_parts.h"

namespace smcbip::tools {
namespace {

struct Series {
  std::string name;
  std::vector<const smc::QueryResult*> points;  // by increasing x
};

class Panel {
 public:
  Panel(const Report& report, std::vector<const smc::QueryResult*> results)
      : report_(report), results_(std::move(results)) {
    choose_axis();
    group();
  }

  void draw(pugi::xml_node g) const {
    const monitors::Query& q = report_.file.queries[results_.front()->query];
    const Frame f = frame(q);
    label(g, kLeft, 24, query_text(report_, *results_.front()), "start")
        .append_attribute("font-weight") = "bold";
    axes(g, f, q);
    for (std::size_t s = 0; s < series_.size(); ++s)
      curve(g, f, series_[s], kColours[s % kColours.size()]);
    threshold(g, f, q);
    legend(g, q);
  }

 private:
  void choose_axis() {
    std::map<std::string, std::set<double>> values;
    for (const smc::QueryResult* r : results_) {
      for (const auto& [name, value] : r->parameters) values[name].insert(value);
    }
    for (const auto& [name, seen] : values) {
      if (axis_.empty() || seen.size() > values.at(axis_).size()) axis_ = name;
    }
  }

  void group() {
    std::map<std::string, Series> by_rest;
    for (const smc::QueryResult* r : results_) {
      std::string rest;
      for (const auto& [name, value] : r->parameters) {
        if (name != axis_) rest += (rest.empty() ? "" : ", ") + name + "=" + text(value);
      }
      Series& s = by_rest[rest];
      s.name = rest;
      s.points.push_back(r);
    }
    for (auto& [rest, s] : by_rest) {
      std::sort(s.points.begin(), s.points.end(), [&](auto* a, auto* b) {
        return a->parameters.at(axis_) < b->parameters.at(axis_);
      });
      series_.push_back(std::move(s));
    }
  }

  Frame frame(const monitors::Query& q) const {
    Frame f{0, 1, 0, 1};
    bool first = true;
    for (const smc::QueryResult* r : results_) {
      const double x = r->parameters.at(axis_);
      f.x0 = first ? x : std::min(f.x0, x);
      f.x1 = first ? x : std::max(f.x1, x);
      if (q.kind == monitors::Query::Kind::Expectation && r->error.empty()) {
        f.y0 = first ? r->ci.low : std::min(f.y0, r->ci.low);
        f.y1 = first ? r->ci.high : std::max(f.y1, r->ci.high);
      }
      first = false;
    }
    if (f.x1 == f.x0) f = {f.x0 - 1, f.x1 + 1, f.y0, f.y1};
    if (!(f.y1 > f.y0)) f = {f.x0, f.x1, f.y0 - 1, f.y0 + 1};
    return f;
  }

  void axes(pugi::xml_node g, const Frame& f, const monitors::Query& q) const {
    const std::string what =
        q.kind == monitors::Query::Kind::Expectation
            ? std::string(monitors::observation_keyword(q.observe)) + ": " + to_string(*q.observed)
            : "probability";
    frame_axes(g, f, axis_, what);
  }

  void curve(pugi::xml_node g, const Frame& f, const Series& s, const char* colour) const {
    std::vector<const smc::QueryResult*> answered;
    for (const smc::QueryResult* r : s.points) {
      if (r->error.empty()) answered.push_back(r);
    }
    if (answered.empty()) return;
    const auto at = [&](const smc::QueryResult* r, double y) {
      return text(f.x(r->parameters.at(axis_))) + "," + text(f.y(y)) + " ";
    };
    std::string band, estimate;
    for (const smc::QueryResult* r : answered) band += at(r, r->ci.high);
    for (auto r = answered.rbegin(); r != answered.rend(); ++r) band += at(*r, (*r)->ci.low);
    for (const smc::QueryResult* r : answered) estimate += at(r, r->estimate);
    // Tests (SPRT, SSP) decide without an interval.
    const smc::Method m = answered.front()->method;
    if (m != smc::Method::Sprt && m != smc::Method::Ssp) {
      element(g, "polygon",
              {{"points", band}, {"fill", colour}, {"fill-opacity", "0.18"}, {"stroke", "none"}});
    }
    element(g, "polyline",
            {{"points", estimate}, {"fill", "none"}, {"stroke", colour}, {"stroke-width", "2"}});
    for (const smc::QueryResult* r : answered) {
      const bool fails = r->verdict && !*r->verdict;
      pugi::xml_node dot = element(g, "circle",
                                   {{"cx", text(f.x(r->parameters.at(axis_)))},
                                    {"cy", text(f.y(r->estimate))},
                                    {"r", "3.5"},
                                    {"fill", fails ? "#fff" : colour},
                                    {"stroke", colour},
                                    {"stroke-width", "1.5"}});
      const std::string tip = axis_ + "=" + text(r->parameters.at(axis_)) + ": " +
                              text(r->estimate) + " in [" + text(r->ci.low) + ", " +
                              text(r->ci.high) + "]";
      dot.append_child("title").text().set(tip.c_str());
    }
  }

  void threshold(pugi::xml_node g, const Frame& f, const monitors::Query& q) const {
    if (q.kind != monitors::Query::Kind::Hypothesis) return;
    const monitors::Bindings constants = monitors::constant_values(report_.file);
    std::set<double> thetas;
    for (const smc::QueryResult* r : results_) {
      const monitors::Value& v = q.threshold;
      if (!v.is_name()) {
        thetas.insert(v.number);
      } else if (const auto p = r->parameters.find(v.name); p != r->parameters.end()) {
        thetas.insert(p->second);
      } else {
        thetas.insert(constants.at(v.name));
      }
    }
    if (thetas.size() != 1) return;  // a threshold that varies has no one line
    const double theta = *thetas.begin();
    line(g, kLeft, f.y(theta), kWidth - kRight, f.y(theta), "#555", "6 4");
    label(g, kWidth - kRight + 6, f.y(theta) + 4, "threshold " + text(theta));
  }

  void legend(pugi::xml_node g, const monitors::Query& q) const {
    double y = kTop + 4;
    const smc::QueryResult& first = *results_.front();
    const double joint = first.alpha * static_cast<double>(first.split);
    const bool tests = first.method == smc::Method::Sprt || first.method == smc::Method::Ssp;
    const std::string how =
        first.method == smc::Method::Band ? "DKW band, " + text(100 * (1 - first.alpha), 4) + "%"
        : tests
            ? std::string(smc::method_name(first.method)) + ", alpha " + text(joint, 3) + " in all"
            : "intervals, " + text(100 * (1 - joint), 4) + "% for all";
    label(g, kWidth - kRight + 6, y, how);
    y += 18;
    if (q.kind == monitors::Query::Kind::Hypothesis) {
      label(g, kWidth - kRight + 6, y, "open: does not hold");
      y += 18;
    }
    for (std::size_t s = 0; s < series_.size() && !series_[s].name.empty(); ++s) {
      const char* colour = kColours[s % kColours.size()];
      element(g, "rect",
              {{"x", text(kWidth - kRight + 6)},
               {"y", text(y - 9)},
               {"width", "10"},
               {"height", "10"},
               {"fill", colour}});
      label(g, kWidth - kRight + 20, y, series_[s].name);
      y += 18;
    }
  }

  const Report& report_;
  std::vector<const smc::QueryResult*> results_;
  std::string axis_;
  std::vector<Series> series_;
};

}  // namespace

bool sweeps_parameter(const monitors::PropertyFile& file, const monitors::Query& q) {
  const auto parameters = monitors::parameter_values(file);
  const std::vector<monitors::Bindings> points = monitors::query_bindings(file, q);
  return std::any_of(parameters.begin(), parameters.end(),
                     [&](const auto& p) { return points.front().contains(p.first); });
}

std::string sweep_svg(const Report& report) {
  std::vector<Panel> panels;
  for (std::size_t i = 0; i < report.results.size();) {
    std::vector<const smc::QueryResult*> query;
    const std::size_t q = report.results[i].query;
    for (; i < report.results.size() && report.results[i].query == q; ++i) {
      if (!report.results[i].parameters.empty()) query.push_back(&report.results[i]);
    }
    if (!query.empty()) panels.emplace_back(report, std::move(query));
  }
  pugi::xml_document doc;
  pugi::xml_node svg = svg_root(doc, panels.size());
  for (std::size_t p = 0; p < panels.size(); ++p) panels[p].draw(panel_group(svg, p));
  return svg_text(doc);
}

}  // namespace smcbip::tools
