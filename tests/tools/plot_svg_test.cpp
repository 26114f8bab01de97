// bench's SVG charts: where points and bars land, logarithmic axes, escaping, and
// byte-identical output for the same numbers.
#include "tools/plot_svg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

namespace p3d::tools {
namespace {

struct Dot {
  double x, y;
};

std::vector<Dot> dots(const std::string& svg) {
  std::vector<Dot> out;
  const std::regex circle("<circle cx=\"([0-9.]+)\" cy=\"([0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2])});
  return out;
}

struct Bar {
  double x, y, height;
};

std::vector<Bar> bars(const std::string& svg) {  // data bars only, not the legend's swatches
  std::vector<Bar> out;
  const std::regex rect("<rect x=\"([0-9.]+)\" y=\"([0-9.]+)\" width=\"[0-9.]+\" height=\"([0-9.]+)\" fill=\"#");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), rect); it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3])});
  return out;
}

TEST(PlotSvg, LogAxesSpanWholeDecadesAndSkipWhatTheyCannotShow) {
  LineChart chart{"t", "walls", "ms", true, true, {}};
  chart.series.push_back({"flat", {{1e3, 0.5}, {1e4, 0.5}, {1e6, 0.5}}});
  chart.series.push_back({"linear", {{1e3, 0.5}, {1e6, 500}, {1e5, 0}, {1e5, NAN}}});
  const std::string svg = line_chart_svg(chart);
  const std::vector<Dot> d = dots(svg);
  ASSERT_EQ(d.size(), 5u) << "zero and NaN cannot sit on a log axis";
  EXPECT_DOUBLE_EQ(d[0].y, d[1].y);
  EXPECT_DOUBLE_EQ(d[0].y, d[2].y) << "a flat series is a horizontal line";
  EXPECT_NEAR(d[1].x - d[0].x, (d[2].x - d[0].x) / 3, 0.11) << "one decade of three";
  EXPECT_LT(d[4].y, d[3].y) << "larger values higher up";
  for (const char* tick : {">1k<", ">10k<", ">100k<", ">1M<", ">0.1<"})
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
  EXPECT_EQ(svg.find(">10M<"), std::string::npos) << "no empty decade past the data";
}

TEST(PlotSvg, LinearAxisStartsAtZeroAndBarsScaleWithTheirValues) {
  BarChart chart{"t", "ms", {"E1M1", "MAP01"}, {{"peer", {1.0, 2.0}}, {"ours", {0.5, NAN}}}, 1.5, "goal"};
  const std::string svg = bar_chart_svg(chart);
  const std::vector<Bar> b = bars(svg);
  ASSERT_EQ(b.size(), 3u) << "a NaN value draws no bar";
  EXPECT_NEAR(b[1].height / b[0].height, 0.5, 1e-3);
  EXPECT_NEAR(b[2].height / b[0].height, 2.0, 1e-3);
  EXPECT_NEAR(b[0].y + b[0].height, b[2].y + b[2].height, 0.11) << "every bar stands on the zero line";
  EXPECT_LT(b[0].x, b[1].x);
  EXPECT_LT(b[1].x, b[2].x) << "groups left to right, series side by side";
  EXPECT_NE(svg.find(">goal<"), std::string::npos);
}

TEST(PlotSvg, NamesAreEscapedAndTheSameNumbersGiveTheSameBytes) {
  LineChart chart{"a < b & c", "x", "y", false, false, {{"\"quoted\"", {{1, 2}, {2, 3}}}}};
  const std::string svg = line_chart_svg(chart);
  EXPECT_NE(svg.find("a &lt; b &amp; c"), std::string::npos) << svg;
  EXPECT_NE(svg.find("&quot;quoted&quot;"), std::string::npos) << svg;
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_EQ(svg, line_chart_svg(chart));
}

}  // namespace
}  // namespace p3d::tools
