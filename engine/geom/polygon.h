// Convex polygons clipped by lines: BSP cells for the compiler, the automap and
// the SVG pictures; bounding boxes clipped to the near plane for culling.
#pragma once

#include <vector>

#include "engine/geom/geom.h"

namespace p3d::geom {

using Polygon = std::vector<Vec2>;

// Keeps the part of a convex polygon with cross(dir, p - origin) * keep_sign >= 0.
Polygon clip_polygon(const Polygon& poly, Vec2 origin, Vec2 dir, double keep_sign);

inline Polygon box_polygon(const BBox& b) {
  return {{b.min.x, b.min.y}, {b.max.x, b.min.y}, {b.max.x, b.max.y}, {b.min.x, b.max.y}};
}

double polygon_area(const Polygon& poly);  // signed, counter-clockwise positive
Vec2 polygon_centroid(const Polygon& poly);

}  // namespace p3d::geom
