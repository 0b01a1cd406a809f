// The parts the tools' SVG plots share: the panel's size and margins, colours, round axis
// ticks, the mapping of values into a panel, and the elements written through pugixml.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <pugixml.hpp>
#include <string>
#include <utility>
#include <vector>

#include "smc/tools/report.h"

namespace smcbip::tools {

inline constexpr double kWidth = 760, kHeight = 440;
inline constexpr double kLeft = 76, kRight = 170, kTop = 56, kBottom = 58;
inline constexpr std::array<const char*, 6> kColours{"#1f77b4", "#d62728", "#2ca02c",
                                                     "#9467bd", "#ff7f0e", "#8c564b"};

inline std::string text(double v, int digits = 6) { return number_text(v, digits); }

/// Axis ticks at a round step (1, 2, 2.5 or 5 times a power of ten), about five of them.
std::vector<double> ticks(double low, double high);

/// Maps a panel's values into its drawing area.
struct Frame {
  double x0, x1, y0, y1;
  double x(double v) const { return kLeft + (v - x0) / (x1 - x0) * (kWidth - kLeft - kRight); }
  double y(double v) const {
    return kHeight - kBottom - (v - y0) / (y1 - y0) * (kHeight - kTop - kBottom);
  }
};

pugi::xml_node element(pugi::xml_node parent, const char* name,
                       std::initializer_list<std::pair<const char*, std::string>> attributes);
pugi::xml_node label(pugi::xml_node parent, double x, double y, const std::string& words,
                     const char* anchor = "start", const std::string& extra = "");
void line(pugi::xml_node parent, double x1, double y1, double x2, double y2, const char* stroke,
          const std::string& dash = "");

/// The frame's axes with their ticks and names.
void frame_axes(pugi::xml_node g, const Frame& f, const std::string& x_name,
                const std::string& y_name);

/// A document of `panels` panels stacked, on a white ground; its root.
pugi::xml_node svg_root(pugi::xml_document& doc, std::size_t panels);
/// The group of panel `index`, translated to its place.
pugi::xml_node panel_group(pugi::xml_node svg, std::size_t index);
/// The document as text.
std::string svg_text(const pugi::xml_document& doc);

}  // namespace smcbip::tools
