#include "engine/geom/polygon.h"

namespace p3d::geom {

Polygon clip_polygon(const Polygon& poly, Vec2 origin, Vec2 dir, double keep_sign) {
  Polygon out;
  out.reserve(poly.size() + 1);
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 p = poly[i], q = poly[(i + 1) % n];
    const double sp = cross(dir, p - origin) * keep_sign;
    const double sq = cross(dir, q - origin) * keep_sign;
    if (sp >= 0) out.push_back(p);
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  return out.size() >= 3 ? out : Polygon{};
}

double polygon_area(const Polygon& poly) {
  double a = 0;
  for (size_t i = 0; i < poly.size(); ++i) a += cross(poly[i], poly[(i + 1) % poly.size()]);
  return a / 2;
}

Vec2 polygon_centroid(const Polygon& poly) {
  const double area = polygon_area(poly);
  Vec2 c{0, 0};
  if (std::fabs(area) < 1e-12) {  // degenerate: the vertex average is inside the hull
    for (Vec2 p : poly) c += p;
    return poly.empty() ? c : c / double(poly.size());
  }
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2 p = poly[i], q = poly[(i + 1) % poly.size()];
    c += (p + q) * cross(p, q);
  }
  return c / (6 * area);
}

}  // namespace p3d::geom
