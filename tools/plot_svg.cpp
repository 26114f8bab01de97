#include "tools/plot_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace p3d::tools {

namespace {

constexpr double kWidth = 760, kHeight = 440;
constexpr double kLeft = 70, kRight = 200, kTop = 40, kBottom = 60;  // margins around the plot area
constexpr double kPlotW = kWidth - kLeft - kRight, kPlotH = kHeight - kTop - kBottom;
const char* const kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};

std::string color(size_t i) { return kColors[i % std::size(kColors)]; }

std::string escape(const std::string& s) {
  std::string out;
  for (const char c : s)
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  return out;
}

std::string format(const char* fmt, double a, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
  return buf;
}

// A tick label: 1k, 10k, 1M for large numbers; as few decimals as the value needs.
std::string tick_label(double v) {
  if (v >= 1e6) return format("%gM", v / 1e6);
  if (v >= 1e3) return format("%gk", v / 1e3);
  return format("%g", v);
}

// One axis: where a value lands along the plot's extent (0..1), and its ticks.
struct Axis {
  bool log = false;
  double lo = 0, hi = 1;
  std::vector<double> ticks;

  double at(double v) const { return log ? (std::log10(v) - lo) / (hi - lo) : (v - lo) / (hi - lo); }
};

// Linear ticks at 1, 2 or 5 times a power of ten, about five of them, from zero
// (times here are never negative) to just above the largest value.
Axis linear_axis(double max) {
  Axis a;
  if (!(max > 0)) max = 1;
  const double raw = max / 5, power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * power) {
      step = m * power;
      break;
    }
  a.hi = std::ceil(max / step) * step;
  for (int i = 0; i * step <= a.hi + step * 1e-9; ++i) a.ticks.push_back(i * step);
  return a;
}

// Logarithmic ticks at every power of ten between the decades around the values.
Axis log_axis(double min, double max) {
  Axis a;
  a.log = true;
  a.lo = std::floor(std::log10(min));
  a.hi = std::max(a.lo + 1, std::ceil(std::log10(max) - 0.01));  // 10016 walls stay in the decade of 10k
  for (double e = a.lo; e <= a.hi; ++e) a.ticks.push_back(std::pow(10.0, e));
  return a;
}

Axis axis_for(const std::vector<double>& values, bool log) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (const double v : values)
    if (v > 0 && std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (hi == 0) lo = hi = 1;
  return log ? log_axis(lo, hi) : linear_axis(hi);
}

class Canvas {
 public:
  explicit Canvas(const std::string& title) {
    out_ = format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" ",
                  kWidth, kHeight, kWidth, kHeight) +
           "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    text(kLeft + kPlotW / 2, 22, title, "middle", "font-size=\"15\" font-weight=\"bold\"");
  }

  void text(double x, double y, const std::string& s, const char* anchor, const std::string& extra = "") {
    out_ += format("<text x=\"%.1f\" y=\"%.1f\" ", x, y) + "text-anchor=\"" + anchor + "\" " + extra + ">" + escape(s) +
            "</text>\n";
  }
  void line(double x1, double y1, double x2, double y2, const std::string& style) {
    out_ += format("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" ", x1, y1, x2, y2) + style + "/>\n";
  }
  void raw(const std::string& s) { out_ += s; }

  // The y axis with its grid lines and label, and the frame around the plot area.
  void y_axis(const Axis& y, const std::string& label) {
    for (const double t : y.ticks) {
      const double py = kTop + kPlotH * (1 - y.at(t));
      line(kLeft, py, kLeft + kPlotW, py, "stroke=\"#ddd\"");
      text(kLeft - 6, py + 4, tick_label(t), "end");
    }
    out_ += format("<text transform=\"translate(18 %.1f) rotate(-90)\" text-anchor=\"middle\">", kTop + kPlotH / 2) +
            escape(label) + "</text>\n";
    out_ += format("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#444\"/>\n", kLeft,
                   kTop, kPlotW, kPlotH);
  }

  void legend(size_t i, const std::string& name, const std::string& swatch_style, bool as_bar) {
    const double x = kLeft + kPlotW + 14, y = kTop + 10 + 20 * double(i);
    if (as_bar) out_ += format("<rect class=\"swatch\" x=\"%.1f\" y=\"%.1f\" width=\"18\" height=\"10\" ", x, y - 8) + swatch_style + "/>\n";
    else line(x, y - 3, x + 18, y - 3, swatch_style);
    text(x + 24, y + 1, name, "start");
  }

  std::string finish() { return out_ + "</svg>\n"; }

 private:
  std::string out_;
};

}  // namespace

std::string line_chart_svg(const LineChart& chart) {
  std::vector<double> xs, ys;
  for (const LineSeries& s : chart.series)
    for (const auto& [x, y] : s.points) xs.push_back(x), ys.push_back(y);
  Axis x = axis_for(xs, chart.log_x), y = axis_for(ys, chart.log_y);
  if (!chart.log_x && !xs.empty()) {  // x starts where the data starts (a size, a thread count)
    x.lo = *std::min_element(xs.begin(), xs.end());
    x.hi = std::max(x.hi, x.lo + 1e-9);
    std::erase_if(x.ticks, [&](double t) { return t < x.lo; });
  }
  Canvas svg(chart.title);
  svg.y_axis(y, chart.y_label);
  for (const double t : x.ticks) {
    const double px = kLeft + kPlotW * x.at(t);
    svg.line(px, kTop, px, kTop + kPlotH, "stroke=\"#eee\"");
    svg.text(px, kTop + kPlotH + 18, tick_label(t), "middle");
  }
  svg.text(kLeft + kPlotW / 2, kHeight - 16, chart.x_label, "middle");
  for (size_t i = 0; i < chart.series.size(); ++i) {
    const LineSeries& s = chart.series[i];
    const std::string ink = color(s.color >= 0 ? size_t(s.color) : i);
    const std::string style = "stroke=\"" + ink + "\" stroke-width=\"2\" fill=\"none\"" +
                              (s.dashed ? " stroke-dasharray=\"6 4\"" : "");
    std::string points, dots;
    for (const auto& [vx, vy] : s.points) {
      if ((chart.log_x && vx <= 0) || (chart.log_y && vy <= 0) || !std::isfinite(vx) || !std::isfinite(vy)) continue;
      const double px = kLeft + kPlotW * x.at(vx), py = kTop + kPlotH * (1 - y.at(vy));
      points += format("%.1f,%.1f ", px, py);
      dots += format("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" ", px, py) + "fill=\"" + ink + "\"/>\n";
    }
    svg.raw("<polyline points=\"" + points + "\" " + style + "/>\n" + dots);
    svg.legend(i, s.name, style, false);
  }
  return svg.finish();
}

std::string bar_chart_svg(const BarChart& chart) {
  std::vector<double> values{chart.reference};
  for (const BarSeries& s : chart.series) values.insert(values.end(), s.values.begin(), s.values.end());
  const Axis y = axis_for(values, false);
  Canvas svg(chart.title);
  svg.y_axis(y, chart.y_label);
  const double group_w = kPlotW / double(std::max<size_t>(1, chart.groups.size()));
  const double bar_w = group_w * 0.8 / double(std::max<size_t>(1, chart.series.size()));
  for (size_t g = 0; g < chart.groups.size(); ++g) {
    const double gx = kLeft + group_w * double(g);
    svg.text(gx + group_w / 2, kTop + kPlotH + 18, chart.groups[g], "middle");
    for (size_t i = 0; i < chart.series.size(); ++i) {
      const double v = g < chart.series[i].values.size() ? chart.series[i].values[g] : NAN;
      if (!(v > 0)) continue;
      const double h = kPlotH * y.at(v);
      svg.raw(format("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" ", gx + group_w * 0.1 + bar_w * double(i),
                     kTop + kPlotH - h, bar_w, h) +
              "fill=\"" + color(i) + "\"/>\n");
    }
  }
  if (chart.reference > 0) {
    const double py = kTop + kPlotH * (1 - y.at(chart.reference));
    svg.line(kLeft, py, kLeft + kPlotW, py, "stroke=\"#000\" stroke-dasharray=\"4 3\"");
    svg.text(kLeft + kPlotW - 4, py - 4, chart.reference_label, "end");
  }
  for (size_t i = 0; i < chart.series.size(); ++i)
    svg.legend(i, chart.series[i].name, "fill=\"" + color(i) + "\"", true);
  return svg.finish();
}

}  // namespace p3d::tools
