// A small SVG line plot (no plotting library needed in the grading image).
#pragma once

#include <string>
#include <vector>

namespace jelly::grade {

struct Series {
  std::string label;
  std::string color;  ///< CSS colour
  std::vector<double> x, y;
  bool dashed = false;
};

/// An SVG document: axes with ticks, the series as polylines, a legend. Non-finite points are
/// left out.
std::string svg_plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                     const std::vector<Series>& series, int width = 640, int height = 360);

}  // namespace jelly::grade
