// The projection shared by every renderer, so that they agree to the last bit:
// column x is sampled at x + 0.5, its ray is forward*d + right*((x+0.5) - W/2)
// with d = (W/2) / tan(fov/2); row y is sampled at y + 0.5 below the horizon H/2.
#pragma once

#include <algorithm>
#include <cmath>

#include "engine/render/camera.h"

namespace p3d::render {

constexpr double kNearDepth = 1e-3;  // hits closer than this (along forward) are ignored

struct View {
  int width = 0, height = 0;
  Vec2 pos;
  double eye = 0;
  double angle = 0;       // radians
  Vec2 forward, right;    // unit vectors; right is forward turned clockwise
  double d = 1;           // projection distance in pixels
  double half_w = 0, half_h = 0;
  Vec2 ray0;              // ray of column 0; ray(x) = ray0 + right * x

  View(const Camera& camera, int w, int h) : width(w), height(h), pos(camera.pos), eye(camera.z) {
    angle = std::fmod(camera.angle, 360.0) * (M_PI / 180);  // any angle: the sky's texture column stays in range
    forward = {std::cos(angle), std::sin(angle)};
    right = {forward.y, -forward.x};
    half_w = w * 0.5;
    half_h = h * 0.5;
    d = half_w / std::tan(camera.fov * (M_PI / 360));
    ray0 = forward * d + right * (0.5 - half_w);
  }

  Vec2 ray(int x) const { return ray0 + right * double(x); }
  double depth_of(Vec2 p) const { return glm::dot(p - pos, forward); }
  double lateral_of(Vec2 p) const { return glm::dot(p - pos, right); }

  // Screen y (continuous, 0 at the top) of height z seen at depth `depth`.
  double screen_y(double z, double depth) const { return half_h - (z - eye) * d / depth; }

  // First row whose centre is at or below screen y, clamped to [0, height].
  int row_at(double y) const {
    const double r = std::ceil(y - 0.5);
    return r <= 0 ? 0 : r >= height ? height : static_cast<int>(r);
  }
};

// The line through a wall as seen from one view: the hit of column x's ray with
// it costs one division. Every renderer hits walls through this, so they agree.
struct WallProjector {
  double den0 = 0, den_dx = 0;  // cross(ray(x), e) = den0 + den_dx * x
  double s_num = 0;             // cross(a - pos, e)
  double t_num0 = 0, t_dx = 0;  // cross(a - pos, ray(x)) = t_num0 + t_dx * x
  double d = 1;

  WallProjector() = default;
  WallProjector(const View& v, Vec2 a, Vec2 b) : d(v.d) {
    const Vec2 e = b - a, rel = a - v.pos;
    den0 = geom::cross(v.ray0, e);
    den_dx = geom::cross(v.right, e);
    s_num = geom::cross(rel, e);
    t_num0 = geom::cross(rel, v.ray0);
    t_dx = geom::cross(rel, v.right);
  }

  // Depth (along forward) and wall parameter t of column x's hit with the wall's
  // line; false when the ray runs parallel or the hit is behind the near plane.
  bool hit(int x, double& depth, double& t) const {
    const double den = den0 + den_dx * x;
    if (den == 0) return false;
    depth = s_num / den * d;
    if (!(depth > kNearDepth)) return false;
    t = (t_num0 + t_dx * x) / den;
    return true;
  }
};

// A conservative range of screen columns [x0, x1]; empty when x0 > x1.
struct ColumnRange {
  int x0 = 1, x1 = 0;
  bool empty() const { return x0 > x1; }
};

// Columns whose ray may meet the segment p0-p1 (clipped to the near plane), widened by one.
ColumnRange columns_of_segment(const View& v, Vec2 p0, Vec2 p1);
// Columns whose ray may meet the box; the whole screen when the camera is inside it.
ColumnRange columns_of_box(const View& v, const geom::BBox& box);

// The side of wall w facing the camera: 0 front, 1 back, -1 edge-on.
inline int facing_side(const level::Wall& w, Vec2 pos) {
  const double s = geom::cross(w.b - w.a, pos - w.a);
  return s < 0 ? 0 : s > 0 ? 1 : -1;
}

// Whether the camera may see side `side` of wall w: one-sided walls show only their front.
inline bool visible_side(const level::Wall& w, int side) { return side == 0 || w.segment() || w.two_sided(); }

}  // namespace p3d::render
