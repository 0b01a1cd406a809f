// The plot of when F phi first holds (see first_hit_plot.h).
#include "smc/tools/first_hit_plot.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "smc/stats/sampling_plans.h"
#include "smc/tools/svg_parts.h"

namespace smcbip::tools {
namespace {

constexpr int kBins = 40;

/// The cumulative panel: the empirical distribution as steps, and its band.
void cumulative(pugi::xml_node g, const smc::QueryResult& r, double horizon,
                const std::string& title) {
  const Frame f{0, horizon, 0, 1};
  label(g, kLeft, 24, title, "start").append_attribute("font-weight") = "bold";
  frame_axes(g, f, "time (ms)", "probability of phi by then");
  std::vector<double> hits = r.first_hits;
  std::sort(hits.begin(), hits.end());
  const auto n = static_cast<double>(std::max<std::uint64_t>(1, r.samples));
  const double epsilon = smc::dkw_half_width(r.samples, r.alpha);
  std::string curve = text(f.x(0)) + "," + text(f.y(0)) + " ";
  std::string upper, lower;
  double below = 0;
  const auto step_to = [&](double t, double next) {
    curve += text(f.x(t)) + "," + text(f.y(below / n)) + " " + text(f.x(t)) + "," +
             text(f.y(next / n)) + " ";
    below = next;
  };
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (i + 1 < hits.size() && hits[i + 1] == hits[i]) continue;
    step_to(std::min(hits[i], horizon), static_cast<double>(i + 1));
  }
  curve += text(f.x(horizon)) + "," + text(f.y(below / n));
  // The band around the steps, drawn at each bin's end.
  for (int b = 0; b <= kBins; ++b) {
    const double t = horizon * b / kBins;
    const double at =
        static_cast<double>(std::upper_bound(hits.begin(), hits.end(), t) - hits.begin()) / n;
    upper += text(f.x(t)) + "," + text(f.y(std::min(1.0, at + epsilon))) + " ";
    lower = text(f.x(t)) + "," + text(f.y(std::max(0.0, at - epsilon))) + " " + lower;
  }
  element(g, "polygon",
          {{"points", upper + lower}, {"fill", kColours[0]}, {"fill-opacity", "0.18"}});
  element(g, "polyline",
          {{"points", curve}, {"fill", "none"}, {"stroke", kColours[0]}, {"stroke-width", "1.5"}});
  label(g, kWidth - kRight + 8, kTop + 12,
        "band: " + text(100 * (1 - r.alpha), 4) + "% (DKW, +-" + text(epsilon, 3) + ")");
  label(g, kWidth - kRight + 8, kTop + 28, text(r.samples) + " runs");
}

/// The density panel: the first times' histogram, per ms.
void density(pugi::xml_node g, const smc::QueryResult& r, double horizon) {
  std::vector<double> counts(kBins, 0);
  const double width = horizon / kBins;
  for (double t : r.first_hits) {
    counts[std::min(kBins - 1, static_cast<int>(t / width))] += 1;
  }
  const auto n = static_cast<double>(std::max<std::uint64_t>(1, r.samples));
  double top = 0;
  for (double& c : counts) top = std::max(top, c /= n * width);
  const Frame f{0, horizon, 0, top > 0 ? top * 1.1 : 1};
  label(g, kLeft, 24, "density of the first time phi holds", "start");
  frame_axes(g, f, "time (ms)", "probability per ms");
  for (int b = 0; b < kBins; ++b) {
    if (counts[b] == 0) continue;
    element(g, "rect",
            {{"x", text(f.x(b * width))},
             {"y", text(f.y(counts[b]))},
             {"width", text(f.x((b + 1) * width) - f.x(b * width))},
             {"height", text(f.y(0) - f.y(counts[b]))},
             {"fill", kColours[1]},
             {"fill-opacity", "0.7"}});
  }
}

}  // namespace

bool has_first_hits(const smc::QueryResult& r) {
  return r.first_hit_horizon > 0 && r.error.empty();
}

std::string first_hit_svg(const Report& report) {
  std::vector<const smc::QueryResult*> plotted;
  for (const smc::QueryResult& r : report.results) {
    if (has_first_hits(r)) plotted.push_back(&r);
  }
  pugi::xml_document doc;
  pugi::xml_node svg = svg_root(doc, 2 * plotted.size());
  for (std::size_t i = 0; i < plotted.size(); ++i) {
    const smc::QueryResult& r = *plotted[i];
    cumulative(panel_group(svg, 2 * i), r, r.first_hit_horizon,
               query_text(report, r) + parameters_text(r));
    density(panel_group(svg, 2 * i + 1), r, r.first_hit_horizon);
  }
  return svg_text(doc);
}

}  // namespace smcbip::tools
