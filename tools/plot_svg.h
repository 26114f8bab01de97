// Charts as SVG for bench --plots: line charts (linear or logarithmic axes) and grouped
// bar charts. Plain text, fixed formatting: the same numbers give the same bytes.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace p3d::tools {

struct LineSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in order; y <= 0 is skipped on a log axis
  bool dashed = false;
  int color = -1;  // an index into the palette; -1: the series' own index
};

struct LineChart {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  std::vector<LineSeries> series;
};

struct BarSeries {
  std::string name;
  std::vector<double> values;  // one per group; NaN or <= 0 leaves the bar out
};

struct BarChart {
  std::string title, y_label;
  std::vector<std::string> groups;  // along the x axis
  std::vector<BarSeries> series;    // side by side within each group
  double reference = 0;             // > 0: a horizontal rule at this value (say, a goal)
  std::string reference_label;
};

std::string line_chart_svg(const LineChart& chart);
std::string bar_chart_svg(const BarChart& chart);

}  // namespace p3d::tools
