#include "engine/image/draw2d.h"

#include <algorithm>
#include <cmath>

namespace p3d::image {

namespace {

void plot(Image& img, int x, int y, uint32_t color, uint32_t alpha) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
  uint32_t& p = img.at(x, y);
  p = alpha >= 256 ? color : blend(p, color, alpha);
}

// Liang-Barsky: clips the segment to the image (widened by a pixel); false if nothing is left.
bool clip(glm::dvec2& a, glm::dvec2& b, double w, double h) {
  double t0 = 0, t1 = 1;
  const glm::dvec2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y}, q[4] = {a.x + 1, w - a.x, a.y + 1, h - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  if (t0 > t1) return false;
  b = a + d * t1;
  a = a + d * t0;
  return true;
}

}  // namespace

void draw_line(Image& img, glm::dvec2 a, glm::dvec2 b, uint32_t color, uint32_t alpha) {
  if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) return;
  if (!clip(a, b, img.width, img.height)) return;
  int x0 = int(std::floor(a.x)), y0 = int(std::floor(a.y));
  const int x1 = int(std::floor(b.x)), y1 = int(std::floor(b.y));
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0), sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  for (int err = dx + dy;;) {  // Bresenham
    plot(img, x0, y0, color, alpha);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) err += dy, x0 += sx;
    if (e2 <= dx) err += dx, y0 += sy;
  }
}

void fill_rect(Image& img, int x, int y, int w, int h, uint32_t color, uint32_t alpha) {
  for (int py = std::max(0, y); py < std::min(img.height, y + h); ++py)
    for (int px = std::max(0, x); px < std::min(img.width, x + w); ++px) plot(img, px, py, color, alpha);
}

void fill_convex(Image& img, std::span<const glm::dvec2> points, uint32_t color, uint32_t alpha) {
  if (points.size() < 3) return;
  double top = INFINITY, bottom = -INFINITY;
  for (const glm::dvec2& p : points) top = std::min(top, p.y), bottom = std::max(bottom, p.y);
  const int y0 = std::max(0, int(std::ceil(top - 0.5))), y1 = std::min(img.height - 1, int(std::floor(bottom - 0.5)));
  for (int y = y0; y <= y1; ++y) {  // each row meets a convex polygon in one span
    const double cy = y + 0.5;
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < points.size(); ++i) {
      const glm::dvec2 p = points[i], q = points[(i + 1) % points.size()];
      if ((p.y > cy) == (q.y > cy)) continue;
      const double x = p.x + (cy - p.y) * (q.x - p.x) / (q.y - p.y);
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
    for (int x = std::max(0, int(std::ceil(lo - 0.5))); x <= std::min(img.width - 1, int(std::floor(hi - 0.5))); ++x)
      plot(img, x, y, color, alpha);
  }
}

}  // namespace p3d::image
