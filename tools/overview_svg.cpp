#include "tools/overview_svg.h"

#include <cmath>
#include <cstdio>

#include "engine/render/renderer.h"
#include "engine/render/view.h"
#include "engine/util/rng.h"

namespace p3d::tools {

namespace {

std::string hsl(double hue, double sat, double light) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "hsl(%.0f,%.0f%%,%.0f%%)", std::fmod(hue, 360.0), sat, light);
  return buf;
}

class Svg {
 public:
  Svg(const geom::BBox& box, double width_px) : box_(box) {
    const double w = box.max.x - box.min.x, h = box.max.y - box.min.y;
    scale_ = width_px / std::max(w, 1.0);
    width_ = w * scale_ + 2 * kPad;
    height_ = h * scale_ + 2 * kPad;
  }
  double x(double wx) const { return (wx - box_.min.x) * scale_ + kPad; }
  double y(double wy) const { return (box_.max.y - wy) * scale_ + kPad; }
  double px(double units) const { return units * scale_; }

  void line(geom::Vec2 a, geom::Vec2 b, const std::string& style) {
    printf_("<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" %s/>\n", x(a.x), y(a.y), x(b.x), y(b.y), style.c_str());
  }
  void polygon(const std::vector<geom::Vec2>& pts, const std::string& style) {
    out_ += "<polygon points=\"";
    for (const geom::Vec2& p : pts) printf_("%.2f,%.2f ", x(p.x), y(p.y));
    out_ += "\" " + style + "/>\n";
  }
  void circle(geom::Vec2 c, double r_px, const std::string& style) {
    printf_("<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" %s/>\n", x(c.x), y(c.y), r_px, style.c_str());
  }
  void text(geom::Vec2 at, const std::string& s, const std::string& style) {
    printf_("<text x=\"%.2f\" y=\"%.2f\" %s>%s</text>\n", x(at.x), y(at.y), style.c_str(), s.c_str());
  }
  void raw(const std::string& s) { out_ += s; }

  std::string finish() const {
    char head[256];
    std::snprintf(head, sizeof head,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n",
                  width_, height_, width_, height_);
    return head + std::string("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n") + out_ + "</svg>\n";
  }

 private:
  template <typename... Args>
  void printf_(const char* format, Args... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, format, args...);
    out_ += buf;
  }
  static constexpr double kPad = 16;
  geom::BBox box_;
  double scale_ = 1, width_ = 0, height_ = 0;
  std::string out_;
};

std::string sector_colour(int sector) {
  if (sector < 0) return "#e4e4e4";
  return hsl(double(Rng::mix(uint64_t(sector)) % 360), 45, 84);
}

// First drawn = red, last = violet.
std::string order_colour(size_t k, size_t n) { return hsl(280.0 * double(k) / double(std::max<size_t>(n, 2) - 1), 85, 45); }

}  // namespace

ViewTrace trace_view(const level::Level& level, const render::Camera& camera, int columns, int rows) {
  ViewTrace t{camera, columns, rows, {}};
  t.probe.want_columns = t.probe.want_order = true;
  render::Frame frame(columns, rows);
  render::make_renderer("bsp")->render(level, camera, frame, &t.probe);
  return t;
}

std::string overview_svg(const level::Level& level, const std::optional<ViewTrace>& view) {
  geom::BBox box = level.bounds;
  const double margin = 0.04 * std::max(box.max.x - box.min.x, box.max.y - box.min.y) + 16;
  box.min -= geom::Vec2(margin);
  box.max += geom::Vec2(margin);
  Svg svg(box, 1400);

  svg.raw("<g id=\"leaves\">\n");
  const auto cells = level::leaf_cells(level, box);
  for (size_t i = 0; i < cells.size(); ++i)
    if (cells[i].size() >= 3)
      svg.polygon(cells[i], "fill=\"" + sector_colour(level.leaves[i].sector) + "\" stroke=\"white\" stroke-width=\"0.6\"");
  svg.raw("</g>\n<g id=\"splitters\">\n");
  for (const level::Chord& c : level::node_chords(level, box))
    if (!c.empty) svg.line(c.a, c.b, "stroke=\"#3050b0\" stroke-width=\"0.7\" stroke-dasharray=\"4 3\" opacity=\"0.7\"");
  svg.raw("</g>\n<g id=\"walls\">\n");
  for (const level::Wall& w : level.walls) {
    const char* style = w.segment()      ? "stroke=\"#1060a0\" stroke-width=\"2.2\""
                        : w.two_sided() ? "stroke=\"#c03030\" stroke-width=\"1.4\""
                                        : "stroke=\"#202020\" stroke-width=\"2.4\"";
    svg.line(w.a, w.b, style);
  }
  // Each leaf's fragments, a stroke on their side facing its region, in the leaf's colour.
  svg.raw("</g>\n<g id=\"leaf-fragments\">\n");
  for (const level::Leaf& leaf : level.leaves)
    for (uint32_t i = leaf.first_fragment; i < leaf.first_fragment + leaf.fragment_count; ++i) {
      const level::Fragment& f = level.fragments[i];
      const geom::Vec2 d = f.p1 - f.p0;
      if (glm::length(d) == 0) continue;
      const geom::Vec2 right = geom::Vec2(d.y, -d.x) / glm::length(d);  // the wall's front
      const geom::Vec2 inward = right * ((f.side == 0 ? 2.5 : -2.5) / svg.px(1));
      svg.line(f.p0 + inward, f.p1 + inward,
               "stroke=\"" + (leaf.sector < 0 ? std::string("#909090") : hsl(double(Rng::mix(uint64_t(leaf.sector)) % 360), 60, 45)) +
                   "\" stroke-width=\"1.6\"");
    }
  svg.raw("</g>\n<g id=\"split-points\">\n");
  for (const level::Fragment& f : level.fragments) {
    if (f.cut[0] != level::kNone) svg.circle(f.p0, 2.2, "fill=\"#ff8000\"");
    if (f.cut[1] != level::kNone) svg.circle(f.p1, 2.2, "fill=\"#ff8000\"");
  }
  svg.raw("</g>\n");
  const geom::Vec2 start = level.player_start;
  const double pa = level.player_angle * M_PI / 180;
  svg.line(start, start + geom::Vec2(std::cos(pa), std::sin(pa)) * (margin * 0.6), "stroke=\"#008000\" stroke-width=\"2\"");
  svg.circle(start, 4, "fill=\"#008000\"");

  if (view) {
    const render::View v(view->camera, view->columns, view->rows);
    const auto& order = view->probe.order;
    std::vector<size_t> rank(level.fragments.size(), SIZE_MAX);
    for (size_t k = 0; k < order.size(); ++k) rank[order[k]] = k;
    svg.raw("<g id=\"columns\" stroke-width=\"0.8\" opacity=\"0.55\">\n");
    for (int x = 0; x < view->columns; ++x) {
      const render::ColumnHit& h = view->probe.columns[x];
      if (h.wall < 0) continue;
      const geom::Vec2 hit = v.pos + v.ray(x) * (h.dist / v.d);
      const size_t k = h.fragment >= 0 ? rank[h.fragment] : 0;
      svg.line(v.pos, hit, "stroke=\"" + order_colour(k, order.size()) + "\"");
    }
    svg.raw("</g>\n<g id=\"draw-order\">\n");
    for (size_t k = 0; k < order.size(); ++k) {
      const level::Fragment& f = level.fragments[order[k]];
      svg.line(f.p0, f.p1, "stroke=\"" + order_colour(k, order.size()) + "\" stroke-width=\"4\"");
      svg.text((f.p0 + f.p1) * 0.5, std::to_string(k + 1),
               "font-family=\"monospace\" font-size=\"11\" fill=\"black\" stroke=\"white\" stroke-width=\"0.4\"");
    }
    svg.raw("</g>\n<g id=\"view-cone\">\n");
    const double reach = std::max(box.max.x - box.min.x, box.max.y - box.min.y);
    for (int x : {0, view->columns - 1}) {
      const geom::Vec2 r = v.ray(x);
      svg.line(v.pos, v.pos + r / glm::length(r) * reach, "stroke=\"#000000\" stroke-width=\"1\" stroke-dasharray=\"6 4\"");
    }
    svg.circle(v.pos, 5, "fill=\"black\"");
    svg.raw("</g>\n");
  }
  return svg.finish();
}

}  // namespace p3d::tools
