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

namespace smcbip::tools {
namespace {

constexpr double kWidth = 760, kHeight = 440;
constexpr double kLeft = 76, kRight = 170, kTop = 56, kBottom = 58;
constexpr std::array<const char*, 6> kColours{"#1f77b4", "#d62728", "#2ca02c",
                                              "#9467bd", "#ff7f0e", "#8c564b"};

std::string text(double v, int digits = 6) { return number_text(v, digits); }

/// Axis ticks at a round step (1, 2, 2.5 or 5 times a power of ten), about five of them.
std::vector<double> ticks(double low, double high) {
  const double raw = (high - low) / 5;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * power;
  for (double m : {1.0, 2.0, 2.5, 5.0}) {
    if (m * power >= raw) {
      step = m * power;
      break;
    }
  }
  std::vector<double> at;
  for (double t = std::ceil(low / step - 1e-9) * step; t <= high + step * 1e-9; t += step) {
    at.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  }
  return at;
}

/// Maps a query's values into its panel.
struct Frame {
  double x0, x1, y0, y1;
  double x(double v) const { return kLeft + (v - x0) / (x1 - x0) * (kWidth - kLeft - kRight); }
  double y(double v) const {
    return kHeight - kBottom - (v - y0) / (y1 - y0) * (kHeight - kTop - kBottom);
  }
};

pugi::xml_node element(pugi::xml_node parent, const char* name,
                       std::initializer_list<std::pair<const char*, std::string>> attributes) {
  pugi::xml_node node = parent.append_child(name);
  for (const auto& [key, value] : attributes) node.append_attribute(key) = value.c_str();
  return node;
}

pugi::xml_node label(pugi::xml_node parent, double x, double y, const std::string& words,
                     const char* anchor = "start", const std::string& extra = "") {
  pugi::xml_node t =
      element(parent, "text", {{"x", text(x)}, {"y", text(y)}, {"text-anchor", anchor}});
  if (!extra.empty()) t.append_attribute("transform") = extra.c_str();
  t.text().set(words.c_str());
  return t;
}

void line(pugi::xml_node parent, double x1, double y1, double x2, double y2, const char* stroke,
          const std::string& dash = "") {
  pugi::xml_node l = element(
      parent, "line",
      {{"x1", text(x1)}, {"y1", text(y1)}, {"x2", text(x2)}, {"y2", text(y2)}, {"stroke", stroke}});
  if (!dash.empty()) l.append_attribute("stroke-dasharray") = dash.c_str();
}

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
    const double left = kLeft, right = kWidth - kRight, top = kTop, bottom = kHeight - kBottom;
    for (double t : ticks(f.y0, f.y1)) {
      line(g, left, f.y(t), right, f.y(t), "#e0e0e0");
      label(g, left - 6, f.y(t) + 4, text(t), "end");
    }
    for (double t : ticks(f.x0, f.x1)) {
      line(g, f.x(t), bottom, f.x(t), bottom + 5, "#000");
      label(g, f.x(t), bottom + 19, text(t), "middle");
    }
    line(g, left, top, left, bottom, "#000");
    line(g, left, bottom, right, bottom, "#000");
    label(g, (left + right) / 2, kHeight - 16, axis_, "middle");
    const std::string what =
        q.kind == monitors::Query::Kind::Expectation
            ? std::string(monitors::observation_keyword(q.observe)) + ": " + to_string(*q.observed)
            : "probability";
    label(g, 20, (top + bottom) / 2, what, "middle",
          "rotate(-90 20 " + text((top + bottom) / 2) + ")");
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
  pugi::xml_node svg = doc.append_child("svg");
  const double height = kHeight * static_cast<double>(std::max<std::size_t>(1, panels.size()));
  svg.append_attribute("xmlns") = "http://www.w3.org/2000/svg";
  svg.append_attribute("width") = text(kWidth).c_str();
  svg.append_attribute("height") = text(height).c_str();
  svg.append_attribute("viewBox") = ("0 0 " + text(kWidth) + " " + text(height)).c_str();
  svg.append_attribute("font-family") = "sans-serif";
  svg.append_attribute("font-size") = "12";
  element(svg, "rect", {{"width", "100%"}, {"height", "100%"}, {"fill", "#fff"}});
  for (std::size_t p = 0; p < panels.size(); ++p) {
    pugi::xml_node g = element(
        svg, "g", {{"transform", "translate(0 " + text(kHeight * static_cast<double>(p)) + ")"}});
    panels[p].draw(g);
  }
  std::ostringstream out;
  doc.save(out, "  ");
  return out.str();
}

}  // namespace smcbip::tools
