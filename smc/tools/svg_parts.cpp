// The parts the tools' SVG plots share (see svg_parts.h).
#include "smc/tools/svg_parts.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace smcbip::tools {

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

pugi::xml_node element(pugi::xml_node parent, const char* name,
                       std::initializer_list<std::pair<const char*, std::string>> attributes) {
  pugi::xml_node node = parent.append_child(name);
  for (const auto& [key, value] : attributes) node.append_attribute(key) = value.c_str();
  return node;
}

pugi::xml_node label(pugi::xml_node parent, double x, double y, const std::string& words,
                     const char* anchor, const std::string& extra) {
  pugi::xml_node t =
      element(parent, "text", {{"x", text(x)}, {"y", text(y)}, {"text-anchor", anchor}});
  if (!extra.empty()) t.append_attribute("transform") = extra.c_str();
  t.text().set(words.c_str());
  return t;
}

void line(pugi::xml_node parent, double x1, double y1, double x2, double y2, const char* stroke,
          const std::string& dash) {
  pugi::xml_node l = element(
      parent, "line",
      {{"x1", text(x1)}, {"y1", text(y1)}, {"x2", text(x2)}, {"y2", text(y2)}, {"stroke", stroke}});
  if (!dash.empty()) l.append_attribute("stroke-dasharray") = dash.c_str();
}

void frame_axes(pugi::xml_node g, const Frame& f, const std::string& x_name,
                const std::string& y_name) {
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
  label(g, (left + right) / 2, kHeight - 16, x_name, "middle");
  label(g, 20, (top + bottom) / 2, y_name, "middle",
        "rotate(-90 20 " + text((top + bottom) / 2) + ")");
}

pugi::xml_node svg_root(pugi::xml_document& doc, std::size_t panels) {
  pugi::xml_node svg = doc.append_child("svg");
  const double height = kHeight * static_cast<double>(std::max<std::size_t>(1, panels));
  svg.append_attribute("xmlns") = "http://www.w3.org/2000/svg";
  svg.append_attribute("width") = text(kWidth).c_str();
  svg.append_attribute("height") = text(height).c_str();
  svg.append_attribute("viewBox") = ("0 0 " + text(kWidth) + " " + text(height)).c_str();
  svg.append_attribute("font-family") = "sans-serif";
  svg.append_attribute("font-size") = "12";
  element(svg, "rect", {{"width", "100%"}, {"height", "100%"}, {"fill", "#fff"}});
  return svg;
}

pugi::xml_node panel_group(pugi::xml_node svg, std::size_t index) {
  return element(
      svg, "g", {{"transform", "translate(0 " + text(kHeight * static_cast<double>(index)) + ")"}});
}

std::string svg_text(const pugi::xml_document& doc) {
  std::ostringstream out;
  doc.save(out, "  ");
  return out.str();
}

}  // namespace smcbip::tools
