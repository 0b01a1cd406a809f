// The outputs of simulate queries (see trajectory_plot.h).
#include "smc/tools/trajectory_plot.h"

#include <algorithm>
#include <limits>
#include <sstream>

#include "smc/tools/svg_parts.h"

namespace smcbip::tools {
namespace {

/// CSV text of an expression: in quotes, doubled inside, when it holds a comma or a quote.
std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// The frame of series `s` over every run: time from 0, values with a margin when flat.
Frame frame_of(const smc::Trajectories& t, std::size_t s) {
  Frame f{0, 0, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const auto& run : t.runs) {
    for (const auto& point : run) {
      f.x1 = std::max(f.x1, point[0]);
      f.y0 = std::min(f.y0, point[s + 1]);
      f.y1 = std::max(f.y1, point[s + 1]);
    }
  }
  if (!(f.y0 <= f.y1)) f.y0 = 0, f.y1 = 1;
  if (f.y0 == f.y1) f.y0 -= 1, f.y1 += 1;
  if (f.x1 <= f.x0) f.x1 = f.x0 + 1;
  return f;
}

}  // namespace

std::string trajectories_csv(const smc::Trajectories& t) {
  std::ostringstream out;
  out << "run,time";
  for (const std::string& s : t.series) out << "," << csv_cell(s);
  out << "\n";
  for (std::size_t r = 0; r < t.runs.size(); ++r) {
    for (const auto& point : t.runs[r]) {
      out << r;
      for (double v : point) out << "," << number_text(v, 12);
      out << "\n";
    }
  }
  return out.str();
}

std::string trajectories_svg(const std::string& query, const smc::Trajectories& t) {
  pugi::xml_document doc;
  pugi::xml_node svg = svg_root(doc, t.series.size());
  for (std::size_t s = 0; s < t.series.size(); ++s) {
    pugi::xml_node g = panel_group(svg, s);
    const Frame f = frame_of(t, s);
    label(g, kLeft, 24, query, "start").append_attribute("font-weight") = "bold";
    frame_axes(g, f, "time (ms)", t.series[s]);
    for (std::size_t r = 0; r < t.runs.size(); ++r) {
      std::string points;
      for (const auto& point : t.runs[r]) {
        points += text(f.x(point[0])) + "," + text(f.y(point[s + 1])) + " ";
      }
      element(g, "polyline",
              {{"points", points},
               {"fill", "none"},
               {"stroke", kColours[r % kColours.size()]},
               {"stroke-opacity", "0.6"}});
    }
  }
  return svg_text(doc);
}

}  // namespace smcbip::tools
